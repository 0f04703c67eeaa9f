// The curvature-aligned anisotropic metric of Zhuang et al. 2014, and SeamCut's dimensionless variant.
#pragma once

#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace kerf
{

/// How the curvature difference that stretches the metric is measured.
enum class AnisotropyMeasure
{
  /// Zhuang et al. 2014 as used by ROI Scissor (Eq. 5): |k1| - |k2|, in 1 / length, so gamma
  /// carries a length and depends on the model's scale.
  CurvatureDifference,
  /// SeamCut (section 2.2): s = (|k1| - |k2|) / (|k1| + |k2|), in [0, 1] and scale-free. Its
  /// denominator gets `umbilicRegularization` times the root mean square curvature of the
  /// surface, so that flat and umbilic regions, where both curvatures are rounding noise, stay
  /// isotropic instead of getting a random direction.
  Normalized
};

struct AnisotropicMetricOptions
{
  /// Strength of the anisotropy: 0 gives the Euclidean metric.
  double gamma = 0.0;
  AnisotropyMeasure measure = AnisotropyMeasure::Normalized;
  /// See AnisotropyMeasure::Normalized (relative to the root mean square of k1^2 + k2^2).
  double umbilicRegularization = 0.05;
};

/// lambda1 of Zhuang et al. 2014 (ROI Scissor, Eq. 5): 1 + gamma * difference, with the
/// difference measured as `measure` says for principal curvatures whose magnitudes are
/// `larger` >= `smaller`; `regularization` is added to the denominator of the normalised measure.
/// Throws kerf::Error if lambda1 would not be positive (gamma < 0 past the curvature).
double anisotropyLambda(double larger, double smaller, const AnisotropicMetricOptions& options, double regularization);

/// A Riemannian metric given by one tensor per vertex, g_i(v) = sqrt(v^T M_i v) (ROI Scissor,
/// section 3.2). M_i = [e1 e2] diag(lambda1, lambda2) [e1 e2]^-1 (Eq. 4) in the tangent plane,
/// with e1 the principal direction of the curvature of larger magnitude and e2 the other one,
/// lambda2 = 1 / lambda1; extended to 3-space with the unit normal as a third eigenvector of
/// eigenvalue 1, so that vectors slightly off the tangent plane (chords) are measured sensibly.
/// Taking e1 by magnitude (Zhuang's k1 is the larger |k|) makes lambda1 >= 1: crossing a ridge or a
/// crease is long and following it is short, on concave creases as on convex ridges.
struct AnisotropicMetric
{
  std::vector<Eigen::Matrix3d> tensors;  ///< M_i, per vertex
  std::vector<Eigen::Matrix3d> inverses; ///< M_i^-1
  std::vector<double> lambda1;           ///< per vertex, >= 1 for gamma >= 0
  std::vector<Vector3> normals;          ///< unit vertex normals (the third eigenvector); empty if isotropic
  bool isotropic = true;                 ///< every M_i is the identity (gamma = 0)

  /// The metric tensor at a surface point: the corners' tensors interpolated linearly.
  Eigen::Matrix3d tensorAt(const TriangleMesh& mesh, int face, const Vector3& barycentric) const;
  /// Length of v under the mean of the tensors of vertices a and b.
  double length(const Vector3& v, int a, int b) const;
};

/// The metric of every vertex from its principal curvatures and directions. Throws kerf::Error
/// for a negative or non-finite gamma, or descriptors of another mesh.
AnisotropicMetric computeAnisotropicMetric(
  const TriangleMesh& mesh, const SurfaceDescriptors& descriptors, const AnisotropicMetricOptions& options);

} // namespace kerf
