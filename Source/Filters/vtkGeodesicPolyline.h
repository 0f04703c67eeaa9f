/**
 * @class vtkGeodesicPolyline
 * @brief Geodesic Polyline: the shortest path on the surface through points in order, or a closed
 * loop through them, as a polyline that crosses the triangles, isotropic or under the
 * curvature-aligned anisotropic metric. (Not vtkGeodesicPath: VTK has that name, the base of
 * vtkDijkstraGraphGeodesicPath, whose paths follow edges.)
 *
 * Input 0: the surface. Input 1 (optional): the points, a vtkPointSet whose points are taken in
 * their order, each moved to the nearest surface point and refused beyond
 * MaximumProjectionDistance. Without input 1 the points are those clicked in the panel
 * (SetDrawnPoint; in ParaView: hold Ctrl and click on the surface) or, when none is clicked, the
 * typed ones (SetPathPoint, at first the input's low-x and high-x sides); they are moved to the
 * nearest surface point whatever their distance.
 *
 * Each leg, from one point to the next, is the streamline of the distance field from its first
 * point traced back from its second (SeamCut, section 2.2, Eq. 2): it crosses triangles and
 * edges anywhere, not only along edges, and ends exactly on both points. The distance is the
 * heat method (Crane et al. 2013) with the ISOTROPIC metric (its factorization is cached on the
 * surface, so a leg costs a few back-substitutions), Short-Term Vector Dijkstra (Campen et al.
 * 2013) with the ANISOTROPIC metric of Zhuang et al. 2014 (SeamCut's normalised variant, Gamma;
 * Gamma = 0 is the Euclidean metric measured by Vector Dijkstra). With ClosedLoop the last point
 * is joined back to the first.
 *
 * Output: the path as one polyline (closed with ClosedLoop: its last cell point repeats its
 * first) with the point arrays ArcLength (from the first point, under the metric), Face (the
 * input cell holding the segment that leaves the point; at an open path's end, the one that
 * reaches it) and PathPoint (the index of the given point there, -1 elsewhere), the cell arrays
 * Length and Closed, and the field data TotalLength and SelfCrossings (pairs of segments that
 * cross; 0 for a simple loop).
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, no points, fewer than 2
 * points (3 for a loop), points of input 1 off the surface, points on another connected
 * component than the first, two consecutive points at the same place, NaN coordinates or
 * parameters.
 */
#ifndef vtkGeodesicPolyline_h
#define vtkGeodesicPolyline_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkGeodesicPolyline : public vtkPolyDataAlgorithm
{
public:
  static vtkGeodesicPolyline* New();
  vtkTypeMacro(vtkGeodesicPolyline, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The points clicked on the surface in the panel, in order; when any is clicked they replace
  /// the typed path points. Default: none.
  void SetNumberOfDrawnPoints(int count);
  int GetNumberOfDrawnPoints() const;
  void SetDrawnPoint(int index, double x, double y, double z);
  ///@}

  ///@{
  /// The typed path points, used when input 1 is not connected and no point is clicked, in order
  /// (each moved to the nearest surface point). Default: none.
  void SetNumberOfPathPoints(int count);
  int GetNumberOfPathPoints() const;
  void SetPathPoint(int index, double x, double y, double z);
  ///@}

  enum Metrics
  {
    ISOTROPIC = 0,
    ANISOTROPIC = 1
  };

  ///@{
  /// ISOTROPIC: surface distance by the heat method; ANISOTROPIC: under the curvature-aligned
  /// metric with Gamma, by Short-Term Vector Dijkstra. Default ISOTROPIC.
  vtkSetClampMacro(Metric, int, ISOTROPIC, ANISOTROPIC);
  vtkGetMacro(Metric, int);
  void SetMetricToIsotropic() { this->SetMetric(ISOTROPIC); }
  void SetMetricToAnisotropic() { this->SetMetric(ANISOTROPIC); }
  ///@}

  ///@{
  /// Strength of the anisotropy (dimensionless, SeamCut's normalised curvature difference) with
  /// the ANISOTROPIC metric: 0 is Euclidean; above 0, paths avoid crossing ridges and creases.
  /// Default 1.
  vtkSetClampMacro(Gamma, double, 0.0, 100.0);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /// Short-Term Vector Dijkstra's depth k (ANISOTROPIC). Default 3.
  vtkSetClampMacro(Depth, int, 1, 10);
  vtkGetMacro(Depth, int);
  ///@}

  ///@{
  /// Join the last point back to the first (needs 3 points). Default off.
  vtkSetMacro(ClosedLoop, bool);
  vtkGetMacro(ClosedLoop, bool);
  vtkBooleanMacro(ClosedLoop, bool);
  ///@}

  ///@{
  /// Points of input 1 farther from the surface than this fraction of the bounding-box diagonal
  /// are refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

protected:
  vtkGeodesicPolyline();
  ~vtkGeodesicPolyline() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Metric = ISOTROPIC;
  double Gamma = 1.0;
  int Depth = 3;
  bool ClosedLoop = false;
  double MaximumProjectionDistance = 0.05;

private:
  vtkGeodesicPolyline(const vtkGeodesicPolyline&) = delete;
  void operator=(const vtkGeodesicPolyline&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
