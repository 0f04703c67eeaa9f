/**
 * @class vtkGeodesicDistance
 * @brief Geodesic Distance: the distance along the surface from source points (and lines), by the
 * heat method or, under an anisotropic metric, by Short-Term Vector Dijkstra.
 *
 * Input 0: the surface. Input 1 (optional): the sources, a vtkPointSet whose points are each
 * moved to the nearest surface point (refused beyond MaximumProjectionDistance); when it is a vtkPolyData with lines,
 * its polylines are sources too (placed on the surface as kerf::placeCurveOnSurface does). Without input 1 the source
 * is SourcePoint, moved to the nearest surface point whatever its distance (ParaView's handle starts at the input's
 * bounds).
 *
 * With Gamma = 0 the distance is isotropic, by the heat method (Crane et al. 2013) on the
 * intrinsic Delaunay triangulation; its factorizations are cached on the surface, so a new source
 * costs two or three back-substitutions. With Gamma > 0 the distance is measured under the
 * curvature-aligned metric of Zhuang et al. 2014 (SeamCut's normalised variant: crossing a ridge
 * or a crease is longer than following it), by Short-Term Vector Dijkstra (Campen et al. 2013).
 *
 * Output: the surface with the point array "GeodesicDistance" (the name is a parameter; its
 * active scalars), +infinity on the connected components no source touches.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, no source, a source of
 * input 1 farther from the surface than MaximumProjectionDistance, NaN parameters.
 */
#ifndef vtkGeodesicDistance_h
#define vtkGeodesicDistance_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkGeodesicDistance : public vtkPolyDataAlgorithm
{
public:
  static vtkGeodesicDistance* New();
  vtkTypeMacro(vtkGeodesicDistance, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The source when input 1 is not connected, moved to the nearest surface point whatever its
  /// distance (in ParaView it starts at the input's bounds: point at the surface and press P).
  /// Default (0, 0, 0).
  vtkSetVector3Macro(SourcePoint, double);
  vtkGetVector3Macro(SourcePoint, double);
  ///@}

  ///@{
  /// Strength of the anisotropy (dimensionless): 0 measures isotropic distance by the heat
  /// method; above 0, lengths across the principal direction of larger curvature are stretched
  /// by up to 1 + Gamma. Default 0.
  vtkSetClampMacro(Gamma, double, 0.0, 100.0);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /// Short-Term Vector Dijkstra's depth k (Gamma > 0). Default 3.
  vtkSetClampMacro(Depth, int, 1, 10);
  vtkGetMacro(Depth, int);
  ///@}

  ///@{
  /// The heat method's time step t = TimeFactor h^2, h the mean edge length. Default 1.
  vtkSetClampMacro(TimeFactor, double, 1e-3, 1e3);
  vtkGetMacro(TimeFactor, double);
  ///@}

  enum BoundaryConditions
  {
    NEUMANN = 0,
    DIRICHLET = 1,
    MEAN = 2
  };

  ///@{
  /// The heat flow's condition on the mesh boundary: Neumann, Dirichlet, or the mean of both
  /// (Crane et al. 2013's recommendation). Default MEAN.
  vtkSetClampMacro(BoundaryCondition, int, NEUMANN, MEAN);
  vtkGetMacro(BoundaryCondition, int);
  ///@}

  ///@{
  /// Sources of input 1 farther from the surface than this fraction of the bounding-box diagonal are
  /// refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// Name of the output point array. Default "GeodesicDistance".
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

protected:
  vtkGeodesicDistance();
  ~vtkGeodesicDistance() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double SourcePoint[3] = { 0.0, 0.0, 0.0 };
  double Gamma = 0.0;
  int Depth = 3;
  double TimeFactor = 1.0;
  int BoundaryCondition = MEAN;
  double MaximumProjectionDistance = 0.05;
  char* ArrayName = nullptr;

private:
  vtkGeodesicDistance(const vtkGeodesicDistance&) = delete;
  void operator=(const vtkGeodesicDistance&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
