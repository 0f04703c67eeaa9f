/**
 * @class vtkROIScissor
 * @brief ROI Scissor: the feature region around a click, bounded where the surface is most
 * concave (ROI Scissor, sections 4.1-4.3).
 *
 * Input 0: the surface. Input 1 (optional): the clicks, each adding a geodesic disc or, with a
 * non-zero value in the point array ClickSubtractArrayName, subtracting it (ROI Scissor, section
 * 5.2), each with the radius Radius or its own; without input 1, ClickPoint. The clicks' parameters and the rules that
 * place them on the surface are vtkDiscClickAlgorithm's.
 *
 * The candidate region is the union of the added clicks' geodesic discs minus the subtracted ones'
 * (of radius Radius unless the clicks give theirs) around the clicks
 * (heat method; each click's distance is kept, so a new radius costs no new distance). Vertices
 * within InnerFraction of the radius of a click get the value 1, the ends of the edges crossing
 * the region's border 0, and the concavity-aware harmonic field (ROI Scissor, section 3.1) is
 * solved on the faces touching the region. Of IsolineCount uniformly sampled isolines the best
 * by the section 4.2 score is split into parts (SegmentFraction of the triangles it crosses);
 * each part's most concave triangle gives a feature point, and the feature points are joined by
 * anisotropic geodesics (Gamma) into the closed boundary (section 4.3). Faces inside the
 * boundary, on the click's side, form the region.
 *
 * Output 0: the surface with the cell array "RoiRegion" (1 inside, 0 outside; the name is a
 * parameter, its active scalars), the point arrays "RoiField" (the harmonic field, NaN outside
 * the faces it was solved on) and "RoiCandidate" (1 inside the discs), and the field data
 * IsoValue and Score of the chosen isoline, SegmentSizes (the faces outside and inside) and ClickDistanceFields (the
 * distance fields this filter has computed for its clicks on this surface, kept ones not counted again). Output 1: the
 * boundary as closed polylines with the cell arrays Length (under the metric), Closed and SelfCrossings.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, a click of input 1 farther
 * from the surface than MaximumProjectionDistance, clicks on several components, discs covering
 * their whole component, holding no vertex or too small to hold their inner vertices, every adding
 * click inside a subtracted disc, a field without a closed isoline, NaN parameters.
 */
#ifndef vtkROIScissor_h
#define vtkROIScissor_h

#include "KerfFiltersModule.h"
#include "vtkDiscClickAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkROIScissor : public vtkDiscClickAlgorithm
{
public:
  static vtkROIScissor* New();
  vtkTypeMacro(vtkROIScissor, vtkDiscClickAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Vertices nearer than this fraction of r to a click get the value 1. Default 0.1.
  vtkSetClampMacro(InnerFraction, double, 1e-3, 0.9);
  vtkGetMacro(InnerFraction, double);
  ///@}

  ///@{
  /// Isolines sampled uniformly to choose the boundary from. Default 50.
  vtkSetClampMacro(IsolineCount, int, 3, 1000);
  vtkGetMacro(IsolineCount, int);
  ///@}

  ///@{
  /// The chosen isoline is split into this fraction of the triangles it crosses (at least 3
  /// parts), one feature point each. Default 0.1.
  vtkSetClampMacro(SegmentFraction, double, 1e-3, 1.0);
  vtkGetMacro(SegmentFraction, double);
  ///@}

  ///@{
  /// Anisotropy of the geodesics joining the feature points (SeamCut's normalised curvature
  /// difference; 0: isotropic). Default 1.
  vtkSetClampMacro(Gamma, double, 0.0, 100.0);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /// Name of the output cell array of the region. Default "RoiRegion".
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  /// The boundary polylines (output 1).
  vtkPolyData* GetBoundary();

protected:
  vtkROIScissor();
  ~vtkROIScissor() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double InnerFraction = 0.1;
  int IsolineCount = 50;
  double SegmentFraction = 0.1;
  double Gamma = 1.0;
  char* RegionArrayName = nullptr;

private:
  vtkROIScissor(const vtkROIScissor&) = delete;
  void operator=(const vtkROIScissor&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
