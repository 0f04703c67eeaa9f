/**
 * @class vtkROIScissor
 * @brief ROI Scissor: the feature region around a click, bounded where the surface is most
 * concave (ROI Scissor, sections 4.1-4.3).
 *
 * Input 0: the surface. Input 1 (optional): clicks, a vtkPointSet whose points each add a
 * geodesic disc, each moved to the nearest surface point and refused beyond
 * MaximumProjectionDistance; without it the click is ClickPoint, moved to the nearest surface
 * point whatever its distance (ParaView's handle starts at the input's bounds). A click's point
 * data may give its own radius (the array ClickRadiusArrayName, default "Radius", a fraction of
 * the diagonal like Radius) and make it subtract its disc instead of adding it (the array
 * ClickSubtractArrayName, default "Subtract": non-zero subtracts; ROI Scissor, section 5.2);
 * without these arrays every click adds a disc of radius Radius.
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
 * IsoValue and Score of the chosen isoline and ClickDistanceFields (the distance fields this
 * filter has computed for its clicks on this surface, kept ones not counted again). Output 1: the boundary as closed polylines with the
 * cell arrays Length (under the metric), Closed and SelfCrossings.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, a click of input 1 farther
 * from the surface than MaximumProjectionDistance, clicks on several components, a disc covering its
 * whole component or too small to hold its inner vertices, a field without a closed isoline,
 * NaN parameters.
 */
#ifndef vtkROIScissor_h
#define vtkROIScissor_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkROIScissor : public vtkPolyDataAlgorithm
{
public:
  static vtkROIScissor* New();
  vtkTypeMacro(vtkROIScissor, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The click when input 1 is not connected, moved to the nearest surface point whatever its
  /// distance (in ParaView it starts at the input's bounds: point at the surface and press P).
  /// Default (0, 0, 0).
  vtkSetVector3Macro(ClickPoint, double);
  vtkGetVector3Macro(ClickPoint, double);
  ///@}

  ///@{
  /// Geodesic radius r of each click's disc, as a fraction of the bounding-box diagonal. Default 0.25.
  vtkSetClampMacro(Radius, double, 1e-6, 10.0);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Geodesic radius of each click's disc in the input's units; when positive it replaces Radius
  /// (clicks' own radii stay fractions of the diagonal). ParaView sets it with the sphere widget
  /// centred on the click. Default 0 (Radius is used).
  vtkSetClampMacro(AbsoluteRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AbsoluteRadius, double);
  ///@}

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
  /// Clicks of input 1 farther from the surface than this fraction of the bounding-box diagonal are
  /// refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// Point arrays of input 1 read when present: each click's radius (fraction of the diagonal;
  /// default name "Radius") and whether it subtracts its disc (non-zero; default name "Subtract").
  vtkSetStringMacro(ClickRadiusArrayName);
  vtkGetStringMacro(ClickRadiusArrayName);
  vtkSetStringMacro(ClickSubtractArrayName);
  vtkGetStringMacro(ClickSubtractArrayName);
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

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double ClickPoint[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.25;
  double AbsoluteRadius = 0.0;
  double InnerFraction = 0.1;
  int IsolineCount = 50;
  double SegmentFraction = 0.1;
  double Gamma = 1.0;
  double MaximumProjectionDistance = 0.05;
  char* RegionArrayName = nullptr;
  char* ClickRadiusArrayName = nullptr;
  char* ClickSubtractArrayName = nullptr;

private:
  vtkROIScissor(const vtkROIScissor&) = delete;
  void operator=(const vtkROIScissor&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
