// Edge weights of the discrete Laplacian: uniform, cotangent, intrinsic Delaunay, and the two concavity-aware schemes.
#pragma once

#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/TriangleMesh.h"

#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace kerf
{

/// How the Laplacian weighs an edge (i, j).
enum class LaplacianWeighting
{
  /// w_ij = 1.
  Uniform,
  /// w_ij = (cot alpha + cot beta) / 2 over the angles opposite the edge.
  Cotangent,
  /// Au et al. 2011 (ROI Scissor, Eq. 2-3): w_ij = |e_ij| / G_ij * beta, G_ij = |K_i| + |K_j|
  /// and beta = 0.01 if i or j is concave, else 1.
  ConcavityAware,
  /// ROI Scissor (section 3.1): as ConcavityAware with the smooth
  /// beta(t) = 1 / (1 + 100 t^2) for t = H_ij / (2 H_max) > 0, else 1.
  SmoothConcavity,
  /// The cotangent weights of the intrinsic Delaunay triangulation (Bobenko and Springborn 2007):
  /// nonnegative without clamping, and linearly precise on planar meshes. Its edges are the
  /// mesh's edges where no flip was needed and new vertex pairs where one was, so
  /// computeLaplacianWeights can give it only for meshes whose intrinsic Delaunay triangulation
  /// keeps their edges; intrinsicDelaunayLaplacian() (Numerics/IntrinsicTriangulation.h) gives
  /// it for any mesh, with the mesh of its edges.
  IntrinsicDelaunay
};

/// Parameters of the weights. The defaults are the papers' values.
struct LaplacianWeightOptions
{
  LaplacianWeighting weighting = LaplacianWeighting::Cotangent;
  /// beta on edges touching a concave vertex (ConcavityAware).
  double concaveBeta = 0.01;
  /// Added to G_ij, relative to the mean total curvature k1^2 + k2^2 over the vertices (at least
  /// 1 / diagonal^2), so that flat and developable regions (G = 0 up to rounding) get large,
  /// finite and uniform weights (ConcavityAware, SmoothConcavity).
  double curvatureRegularization = 0.01;
  /// H_max of SmoothConcavity, as a quantile of the vertices' concave mean curvature: 1 is the
  /// maximum (the paper); a slightly lower quantile ignores a few noisy vertices.
  double concavityQuantile = 1.0;
};

/// Whether the weighting needs the surface descriptors (curvature, concavity).
bool needsDescriptors(LaplacianWeighting weighting);

/// The weighting's name as the command line and the benchmark runner spell it: "uniform",
/// "cotangent", "concavity", "smooth-concavity", "intrinsic-delaunay".
std::string laplacianWeightingName(LaplacianWeighting weighting);
/// The weighting a name spells; throws kerf::Error listing the names for any other text.
LaplacianWeighting parseLaplacianWeighting(const std::string& name);

/// A key naming the weights these options give (Surface::laplacianWeights caches by it).
std::string cacheKey(const LaplacianWeightOptions& options);

/// Largest cotangent magnitude used: angles below about 0.006 degrees count as that angle.
constexpr double CotangentLimit = 1e4;
/// Weight given, relative to the mean positive weight, to the edges of a vertex whose weights
/// are all zero (for example around degenerate triangles), so that no vertex is disconnected.
constexpr double WeightFloor = 1e-6;

/// The cotangent of each triangle corner's angle, corner k of triangle f at 3 f + k: dot / |cross|
/// of the two edge vectors at the corner, clamped to [-CotangentLimit, CotangentLimit], and 0 for
/// every corner of a zero-area triangle (isZeroArea). The cotangent weights below and the charts'
/// conformal maps both use it.
std::vector<double> cornerCotangents(const TriangleMesh& mesh);

/// One weight per mesh edge (indexed like TriangleMesh edges), all >= 0. Cotangent details: each
/// cotangent is computed as dot / |cross| of the two edge vectors at the angle and clamped to
/// [-CotangentLimit, CotangentLimit]; zero-area triangles contribute nothing. Negative weights
/// (an edge whose opposite angles sum to more than pi) are set to 0, so that the Laplacian is an
/// M-matrix and harmonic fields obey the maximum principle; linear functions stay exact on
/// meshes without such edges. A vertex left with no positive weight gets WeightFloor times the
/// mean positive weight on its edges. The concavity-aware
/// schemes need the descriptors (Gaussian and mean curvature, concavity); H_ij of
/// SmoothConcavity is measured positive on concave edges, i.e. minus Kerf's mean curvature.
/// IntrinsicDelaunay throws kerf::Error when the intrinsic Delaunay triangulation joins vertices
/// that no mesh edge joins (solve on intrinsicDelaunayLaplacian(mesh).mesh instead).
std::vector<double> computeLaplacianWeights(
  const TriangleMesh& mesh, const LaplacianWeightOptions& options, const SurfaceDescriptors* descriptors = nullptr);

/// The mean diagonal entry of the Laplacian over the vertices used by triangles (1 if none): the
/// scale soft-constraint weights are given relative to.
double laplacianMeanDiagonal(const TriangleMesh& mesh, const std::vector<double>& edgeWeights);

/// The positive semi-definite Laplacian L = D - W (D the diagonal of row sums of W).
Eigen::SparseMatrix<double> assembleLaplacian(const TriangleMesh& mesh, const std::vector<double>& edgeWeights);

} // namespace kerf
