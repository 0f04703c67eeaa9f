// Isotropic geodesic distance by the heat method (Crane et al. 2013) on the intrinsic Delaunay triangulation.
#pragma once

#include "Geodesic/SurfacePoint.h"
#include "Mesh/TriangleMesh.h"

#include <memory>
#include <string>
#include <vector>

namespace kerf
{

class Surface;

/// The fill-reducing ordering of the sparse Cholesky factorizations.
enum class CholeskyOrdering
{
  /// Geometric from GeometricOrderingRows vertices (a million triangles), AMD below.
  Automatic,
  /// Approximate minimum degree: cheap to compute; the faster set-up on one core below about
  /// 50k vertices (Documentation/filters/Geodesics.md has the figures).
  AMD,
  /// Nested dissection (METIS): the least fill, but the costliest analysis.
  METIS,
  /// Nested dissection by coordinate bisection of the vertices (geometricNestedDissection):
  /// between AMD's and METIS's fill, its analysis about AMD's.
  Geometric
};

/// How the heat flow treats the mesh boundary (Crane et al. 2013, boundary conditions).
enum class HeatBoundaryCondition
{
  Neumann,   ///< zero flux: distance isolines meet the boundary at right angles
  Dirichlet, ///< zero heat: isolines bend to follow the boundary
  Mean       ///< the mean of both heat solutions, which Crane et al. recommend
};

struct HeatGeodesicOptions
{
  /// The time step is t = timeFactor * h^2, h the mean edge length (Crane et al. 2013: m = 1).
  double timeFactor = 1.0;
  HeatBoundaryCondition boundary = HeatBoundaryCondition::Mean;
  CholeskyOrdering ordering = CholeskyOrdering::Automatic;
};

/// A key naming these options (HeatGeodesics::of caches by it).
std::string cacheKey(const HeatGeodesicOptions& options);

/// A distance field on a mesh.
struct GeodesicDistance
{
  /// Per vertex; +infinity on components the source does not touch and on unused vertices.
  std::vector<double> distance;
  /// The gradient of the piecewise-linear distance on each triangle (zero where it is infinite).
  std::vector<Vector3> faceGradients;
};

/// Geodesic distance from any source by the heat method (Crane et al. 2013, Algorithm 1):
/// integrate heat u for one implicit step (M + t L) u = u0, normalise X = -grad u / |grad u|
/// per triangle, solve L phi = -div X, and shift phi to 0 on the source. Every operator lives on
/// the intrinsic Delaunay triangulation (Bobenko and Springborn 2007), where the Laplacian has no
/// negative weights whatever the input's triangles; Sharp, Soliman and Crane 2019 show the gain
/// on poor meshes. The heat and Poisson matrices share one sparsity pattern, so one symbolic
/// analysis (ordering) serves both factorizations; a mesh with boundary adds the Dirichlet heat
/// matrix (same pattern again) for the Mean and Dirichlet conditions. Set-up does all of this
/// once; each source then costs two or three solves and two sweeps over the triangles.
///
/// The Poisson system is singular (constants) per connected component: its right-hand side is
/// made compatible by removing its area-weighted mean, and one vertex per component gets an
/// extra diagonal term, which keeps the pattern and fixes the constant exactly.
///
/// Keeps a reference to the mesh, which must outlive it. The const methods share workspace: one
/// thread at a time.
class HeatGeodesics
{
public:
  /// Throws kerf::Error for an empty mesh, a non-positive or non-finite time factor, or a failed
  /// factorization.
  explicit HeatGeodesics(const TriangleMesh& mesh, const HeatGeodesicOptions& options = HeatGeodesicOptions());
  ~HeatGeodesics();
  HeatGeodesics(HeatGeodesics&&) noexcept;
  HeatGeodesics(const HeatGeodesics&) = delete;
  HeatGeodesics& operator=(const HeatGeodesics&) = delete;

  /// The set-up for a surface, cached on it (Surface::derived) under the options' key.
  static const HeatGeodesics& of(const Surface& surface, const HeatGeodesicOptions& options = HeatGeodesicOptions());

  /// The distance from the source and its gradient per triangle. Throws kerf::Error for a bad
  /// source (checkGeodesicSource).
  GeodesicDistance compute(const GeodesicSource& source) const;

  const TriangleMesh& mesh() const { return this->Mesh; }
  const HeatGeodesicOptions& options() const { return this->Options; }
  double timeStep() const;
  /// Edge flips made to reach the intrinsic Delaunay triangulation.
  int flips() const;

private:
  struct Implementation;
  const TriangleMesh& Mesh;
  HeatGeodesicOptions Options;
  std::unique_ptr<Implementation> Impl;
};

} // namespace kerf
