// A fill-reducing ordering for sparse Cholesky factors of mesh matrices: nested dissection by
// coordinate bisection.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <Eigen/SparseCore>

#include <vector>

namespace kerf
{

/// Fill-reducing ordering of a symmetric matrix whose rows belong to points in space (a mesh's
/// vertices), by nested dissection (George 1973) with coordinate bisection (geometric
/// partitioning, as in Miller, Teng, Thurston and Vavasis 1998, with axis-aligned cuts): the
/// points are split at the median of the coordinate axis (of three) whose split has the smallest
/// one-sided vertex separator, that separator is ordered last, and both halves are ordered the same
/// way until they have at most `leafSize` rows, which keep increasing index order.
///
/// `lowerPattern` holds at least the lower (or the upper) triangle of the matrix's pattern;
/// its values are not read. Returns perm with perm[k] the row eliminated k-th, the form
/// CHOLMOD's given orderings take. Linear memory, O(n log n) time, deterministic (ties in a
/// coordinate are broken by row index). Throws kerf::Error when the sizes disagree.
std::vector<int> geometricNestedDissection(
  const std::vector<Vector3>& points, const Eigen::SparseMatrix<double>& lowerPattern, int leafSize = 64);

/// From this many rows the solvers of mesh matrices (heat method, harmonic fields) order with
/// geometricNestedDissection instead of AMD. On the 1M-triangle cube dumbbell (501k rows) it
/// halves the factorization's flops (15.6 against 30.6 GFlop for the Laplacian); below about
/// 50k rows AMD's cheaper analysis wins (Documentation/filters/Geodesics.md has the figures).
constexpr int GeometricOrderingRows = 200000;

/// The same for the squared Laplacian L_F^T L_F that least-squares harmonic fields factor: its
/// wider stencil (two rings) gives AMD more fill, and the constraint columns of a new stroke reach
/// a smaller part of a nested-dissection factor. On the 100k-triangle cube dumbbell (50k rows) the
/// first cut costs the same with either ordering while a new cut and a refinement are 22-28%
/// faster; on the 22k one (11k rows) the first cut is 8% slower and a refinement 27% faster; on
/// psb-dev's models (about 5k rows) AMD is faster throughout (Documentation/filters/HarmonicCuts.md).
constexpr int GeometricOrderingRowsSquared = 20000;

} // namespace kerf
