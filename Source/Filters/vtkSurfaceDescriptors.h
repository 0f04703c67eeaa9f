/**
 * @class vtkSurfaceDescriptors
 * @brief Per-vertex normals, principal curvatures and directions, mean and Gaussian curvature,
 * concavity flag and normal-cone angle of a triangle surface.
 *
 * The curvature tensor is estimated per triangle from the variation of the vertex normals along
 * its edges and averaged at each vertex with Voronoi corner weights (Rusinkiewicz 2004,
 * "Estimating curvatures and their derivatives on triangle meshes"). This estimator is chosen
 * over Taubin 1995 because it uses only each triangle's own edges, so it stays accurate on
 * irregular tessellations and gives consistent principal directions, and it costs one small
 * least-squares solve per triangle. Vertex normals use Max's 1999 weights, exact on spheres.
 *
 * Point arrays added to the output (names are parameters):
 * - Normals (3 components, also set as the active normals)
 * - MaximumCurvature k1 and MinimumCurvature k2, k1 >= k2, in 1/length; positive where the
 *   surface bends away from its normal (a sphere with outward normals has k = 1/R)
 * - MaximumCurvatureDirection and MinimumCurvatureDirection: unit tangent vectors
 * - MeanCurvature (k1 + k2) / 2 and GaussianCurvature k1 k2
 * - Concave: 1 where (p_hat - p) . n > 0, p_hat the centroid of the one-ring
 *   (Au et al. 2011; ROI Scissor, Eq. 3), else 0 (unsigned char)
 * - NormalConeAngle: the largest angle, in radians, between the normals of two triangles around
 *   the vertex (Dekkers and Kobbelt 2014, Eq. 4)
 *
 * Accepted input: a vtkPolyData surface whose polygons and strips are triangulated on the fly.
 * Points with identical coordinates (OBJ texture seams, STL facets) are welded and share their
 * values; a triangle that welding leaves with a repeated point is refused. Boundaries, several components, zero-area
 * triangles (which contribute nothing) and points used by no triangle (which get zero values) are accepted. Refused
 * with an error: no triangles, NaN or infinite coordinates, triangles repeating a point, duplicate triangles,
 * non-manifold edges or vertices, and inconsistently oriented neighbouring triangles.
 *
 * The output keeps the input's arrays. When the input holds only triangles its cells are shared;
 * otherwise the output is the triangulated surface with the cell data of each source polygon.
 */
#ifndef vtkSurfaceDescriptors_h
#define vtkSurfaceDescriptors_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>
#include <string>

class KERFFILTERS_EXPORT vtkSurfaceDescriptors : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceDescriptors* New();
  vtkTypeMacro(vtkSurfaceDescriptors, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Names of the output point arrays. Defaults: "Normals", "MaximumCurvature",
  /// "MinimumCurvature", "MaximumCurvatureDirection", "MinimumCurvatureDirection",
  /// "MeanCurvature", "GaussianCurvature", "Concave", "NormalConeAngle".
  vtkSetStringMacro(NormalsArrayName);
  vtkGetStringMacro(NormalsArrayName);
  vtkSetStringMacro(MaximumCurvatureArrayName);
  vtkGetStringMacro(MaximumCurvatureArrayName);
  vtkSetStringMacro(MinimumCurvatureArrayName);
  vtkGetStringMacro(MinimumCurvatureArrayName);
  vtkSetStringMacro(MaximumDirectionArrayName);
  vtkGetStringMacro(MaximumDirectionArrayName);
  vtkSetStringMacro(MinimumDirectionArrayName);
  vtkGetStringMacro(MinimumDirectionArrayName);
  vtkSetStringMacro(MeanCurvatureArrayName);
  vtkGetStringMacro(MeanCurvatureArrayName);
  vtkSetStringMacro(GaussianCurvatureArrayName);
  vtkGetStringMacro(GaussianCurvatureArrayName);
  vtkSetStringMacro(ConcaveArrayName);
  vtkGetStringMacro(ConcaveArrayName);
  vtkSetStringMacro(NormalConeAngleArrayName);
  vtkGetStringMacro(NormalConeAngleArrayName);
  ///@}

protected:
  vtkSurfaceDescriptors();
  ~vtkSurfaceDescriptors() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* NormalsArrayName = nullptr;
  char* MaximumCurvatureArrayName = nullptr;
  char* MinimumCurvatureArrayName = nullptr;
  char* MaximumDirectionArrayName = nullptr;
  char* MinimumDirectionArrayName = nullptr;
  char* MeanCurvatureArrayName = nullptr;
  char* GaussianCurvatureArrayName = nullptr;
  char* ConcaveArrayName = nullptr;
  char* NormalConeAngleArrayName = nullptr;

private:
  vtkSurfaceDescriptors(const vtkSurfaceDescriptors&) = delete;
  void operator=(const vtkSurfaceDescriptors&) = delete;

  /// The converted surface, kept between executions (see kerf::SurfaceInput).
  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
