// LinABF (Zayer, Lévy and Seidel 2007): the planar angles of a chart from one sparse linear solve.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// The angles of a chart flattened by LinABF, per triangle corner: corner k of triangle f at
/// index 3 f + k (the corner at vertex triangle(f)[k]).
struct LinearABFAngles
{
  /// beta: the 3D angles, those at an interior vertex scaled so that they sum to 2 pi (ABF's
  /// optimal angles, Sheffer and de Sturler 2001).
  std::vector<double> targets;
  /// alpha = beta + e: each triangle's sum is pi and each interior vertex's 2 pi (to round-off);
  /// the wheel (sine) condition holds to first order in e.
  std::vector<double> angles;
  int interiorVertices = 0;
};

/// Linear Angle Based Flattening's angles (Zayer, Lévy and Seidel 2007): the corrections e that
/// minimise sum e^2 / beta^2 under the triangle sums, the interior vertex sums and the wheel
/// condition linearised around beta (log sin(beta + e) ~ log sin beta + e cot beta), in closed
/// form e = W^-1 C^T (C W^-1 C^T)^-1 r. The per-triangle constraints are eliminated first (as
/// ABF++ does, Sheffer et al. 2005), which leaves a symmetric positive definite system of two
/// unknowns per interior vertex, factored by CHOLMOD (kerf::SparseCholesky). A developable chart
/// gets e = 0. Meant for a disk (chartTopologyProblem); throws kerf::Error for an empty chart, a
/// corner of zero angle (a triangle of zero area) or constraints that are not independent (a
/// closed chart, for one), found when the solution misses the vertex sums.
LinearABFAngles linearAngleBasedAngles(const TriangleMesh& chart);

} // namespace kerf
