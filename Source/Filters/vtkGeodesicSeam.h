/**
 * @class vtkGeodesicSeam
 * @brief Geodesic Seam: SeamCut's seam from a cut line to a point, along the curvature-aligned
 * anisotropic distance from the line (SeamCut, sections 2.2 and 3).
 *
 * Input 0: the surface. Input 1: the cut, as polylines on the surface (for example Stroke
 * Cut's second output); a polyline whose last point repeats its first is closed. All lines
 * must lie on one connected component.
 *
 * The distance from the lines under the anisotropic metric (Zhuang et al. 2014, SeamCut's
 * normalised variant, Gamma) is computed by Short-Term Vector Dijkstra (the heat method when
 * Gamma = 0); the seam is the streamline of its descent direction (SeamCut, Eq. 2) from
 * TargetPoint (the emitter) back to the lines. The field is kept while the surface, the lines
 * and the metric stay the same, so moving TargetPoint (seam regrowth, SeamCut section 3) costs
 * one streamline. With UseAnchor the seam is made to meet the lines at AnchorPoint (moved to the
 * nearest point of the lines): the geodesic under the metric from there to the target.
 *
 * Output 0: the surface with the point array "SeamDistance" (the name is a parameter; +infinity
 * off the lines' component) and the field data "SeamWork" ("field": computed, "regrowth": the
 * kept field reused). Output 1: the seam as one polyline from the lines to the target, with the
 * cell arrays Length (under the metric) and Closed.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, no line, lines farther from
 * the surface than MaximumProjectionDistance, lines on several components, a target
 * on another component, NaN parameters.
 */
#ifndef vtkGeodesicSeam_h
#define vtkGeodesicSeam_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkGeodesicSeam : public vtkPolyDataAlgorithm
{
public:
  static vtkGeodesicSeam* New();
  vtkTypeMacro(vtkGeodesicSeam, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The seam's end away from the lines (the emitter) clicked on the surface in the panel (in
  /// ParaView: hold Ctrl and click): the last clicked point, when any, replaces TargetPoint.
  /// Default: none.
  void SetNumberOfDrawnPoints(int count);
  int GetNumberOfDrawnPoints() const;
  void SetDrawnPoint(int index, double x, double y, double z);
  ///@}

  ///@{
  /// The typed end of the seam away from the lines (the emitter), used when no point is clicked,
  /// moved to the nearest surface point whatever its distance (in ParaView it starts at the
  /// input's bounds). Default (0, 0, 0).
  vtkSetVector3Macro(TargetPoint, double);
  vtkGetVector3Macro(TargetPoint, double);
  ///@}

  ///@{
  /// Make the seam meet the lines at AnchorPoint (seam anchoring). Default off.
  vtkSetMacro(UseAnchor, bool);
  vtkGetMacro(UseAnchor, bool);
  vtkBooleanMacro(UseAnchor, bool);
  ///@}

  ///@{
  /// Where the seam meets the lines with UseAnchor (moved to the nearest point of the lines).
  /// Default (0, 0, 0).
  vtkSetVector3Macro(AnchorPoint, double);
  vtkGetVector3Macro(AnchorPoint, double);
  ///@}

  ///@{
  /// Strength of the anisotropy (dimensionless, SeamCut's normalised curvature difference): 0
  /// gives isotropic seams; above 0, seams avoid crossing ridges and creases. Default 1.
  vtkSetClampMacro(Gamma, double, 0.0, 100.0);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /// Short-Term Vector Dijkstra's depth k. Default 3.
  vtkSetClampMacro(Depth, int, 1, 10);
  vtkGetMacro(Depth, int);
  ///@}

  ///@{
  /// Line coordinates farther from the surface than this fraction of the bounding-box
  /// diagonal are refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// Name of the output point array of the distance from the lines. Default "SeamDistance".
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  /// The seam (output 1).
  vtkPolyData* GetSeam();

protected:
  vtkGeodesicSeam();
  ~vtkGeodesicSeam() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double TargetPoint[3] = { 0.0, 0.0, 0.0 };
  bool UseAnchor = false;
  double AnchorPoint[3] = { 0.0, 0.0, 0.0 };
  double Gamma = 1.0;
  int Depth = 3;
  double MaximumProjectionDistance = 0.05;
  char* ArrayName = nullptr;

private:
  vtkGeodesicSeam(const vtkGeodesicSeam&) = delete;
  void operator=(const vtkGeodesicSeam&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
