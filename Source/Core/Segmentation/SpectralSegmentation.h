// Spectral clustering of faces (Liu and Zhang 2004; Kouhestani 2013, section 3.5) on a coarsened mesh.
#pragma once

#include "Segmentation/FaceGraph.h"

#include <Eigen/Core>

#include <vector>

namespace kerf
{

class Surface;

struct SpectralSegmentationOptions
{
  /// delta of Dist = delta Geod / avg(Geod) + (1 - delta) Ang / avg(Ang). Default 0.03 (the
  /// survey's range is [0.01, 0.05]).
  double geodesicWeight = 0.03;
  /// eta of Ang = eta (1 - cos alpha) on convex edges (concave edges use 1). Default 0.2 (the
  /// survey's range is [0.1, 0.2]).
  double convexAngleWeight = 0.2;
  /// The dense n x n affinity is formed on this many patches, not on the faces: the faces are
  /// first clustered by hierarchicalFaceClustering, the affinity and its eigenvectors computed
  /// on the patch graph, and each face takes its patch's segment. Meshes with fewer faces are
  /// not coarsened. Default 400.
  int patchCount = 400;
};

struct SpectralSegmentationResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int patches = 0;         ///< the size of the affinity matrix
  int kMeansIterations = 0;
};

/// Liu and Zhang 2004: the distance of neighbouring patches is delta times their geodesic step
/// (centroid to the middle of the shared boundary to centroid) over its mean plus (1 - delta)
/// times the length-weighted mean angular distance across their boundary over its mean; all-pairs
/// distances are shortest paths in the patch graph; W = exp(-Dist / (2 sigma^2)) with sigma the
/// mean distance; N = D^-1/2 W D^-1/2; the rows of its k leading eigenvectors, normalised to unit
/// length, are clustered by area-weighted k-means, seeded by the pair with the smallest
/// association Q = V V^T and then each next seed minimising its largest association with those
/// chosen. Faces take their patch's cluster; segments are made connected (finalizeSegments).
/// Each dual-graph component is segmented apart (segmentComponents). Throws kerf::Error for k < 1,
/// k > faces, weights outside [0, 1] or a patch count below 2.
SpectralSegmentationResult segmentSpectrally(const FaceGraph& graph, int k, const SpectralSegmentationOptions& options);

/// segmentSpectrally on a surface, the same labels bit for bit; the patches and their affinity,
/// which do not depend on k, are kept on the surface (Surface::derived), so that a new k costs
/// only the eigenvectors and the k-means (the ensemble choosing its count asks for several).
SpectralSegmentationResult segmentSpectrally(const Surface& surface, int k, const SpectralSegmentationOptions& options);

/// The patches segmentSpectrally forms its affinity on: per face, its cluster of
/// buildFaceClusterHierarchy cut at options.patchCount clusters, or the face itself on a mesh of
/// at most that many faces; numbered from 0.
std::vector<int> spectralPatches(const FaceGraph& graph, const SpectralSegmentationOptions& options);

/// The matrix whose leading eigenvectors segmentSpectrally clusters: N = D^-1/2 W D^-1/2 on the
/// patch graph of `patch` (per face, as spectralPatches gives it), m x m for m patches, with
/// each patch's area in `area`.
Eigen::MatrixXd spectralAffinity(const FaceGraph& graph, const std::vector<int>& patch,
  const SpectralSegmentationOptions& options, std::vector<double>& area);

/// The eigenvectors of the `count` largest eigenvalues of a symmetric matrix, orthonormal columns
/// in ascending order of their eigenvalues (as Eigen's SelfAdjointEigenSolver orders them), and
/// those eigenvalues in `values`. When the Krylov subspace, max(2 count + 1, 20) vectors, is
/// smaller than the matrix: Spectra's implicitly restarted Lanczos (SymEigsSolver, ARPACK's method:
/// Lehoucq, Sorensen and Yang 1998) on products with the matrix, to a relative residual of 1e-12; its result is
/// checked (residual and orthonormality as tridiagonalLeadingEigenvectors checks its own) and
/// tridiagonalLeadingEigenvectors decides if the check fails or Lanczos does not converge, and
/// for larger counts. Deterministic. Throws kerf::Error if the matrix is not square, count is not
/// in [1, n] or the eigenvalues fail.
Eigen::MatrixXd leadingEigenvectors(const Eigen::MatrixXd& symmetric, int count, Eigen::VectorXd& values);

/// The same by Eigen's Householder tridiagonalization and its eigenvalues of the tridiagonal
/// matrix, then inverse iteration on the tridiagonal matrix from a fixed start, each
/// vector orthogonalised against those before it (so an eigenvalue of several vectors gets an
/// orthonormal basis of its space), carried back by the Householder reflections: O(n^2 count)
/// after the O(n^3) reduction, instead of accumulating every eigenvector. Deterministic. Throws
/// kerf::Error if the matrix is not square, count is not in [1, n] or the eigenvalues fail.
Eigen::MatrixXd tridiagonalLeadingEigenvectors(const Eigen::MatrixXd& symmetric, int count, Eigen::VectorXd& values);

} // namespace kerf
