// Spectral face clustering on a patch graph: distances, affinity, leading eigenvectors, k-means in the embedding.
#include "Segmentation/SpectralSegmentation.h"

#include "CacheKey.h"
#include "Error.h"
#include "Mesh/ShortestPaths.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Surface/Surface.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/DenseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <string>

namespace kerf
{

namespace
{
// Area-weighted k-means of the rows of `points`, seeded as Liu and Zhang 2004 do.
std::vector<int> clusterEmbedding(
  const Eigen::MatrixXd& points, const std::vector<double>& weights, int k, int& iterations)
{
  const int m = static_cast<int>(points.rows());
  const Eigen::MatrixXd association = points * points.transpose();
  std::vector<int> seeds;
  Eigen::Index r = 0, s = 0;
  association.minCoeff(&r, &s);
  seeds.push_back(static_cast<int>(r));
  if (k > 1)
  {
    seeds.push_back(static_cast<int>(s == r ? (r + 1) % m : s));
  }
  while (static_cast<int>(seeds.size()) < k)
  {
    int best = -1;
    double bestValue = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m; ++i)
    {
      if (std::find(seeds.begin(), seeds.end(), i) != seeds.end())
      {
        continue;
      }
      double largest = -std::numeric_limits<double>::infinity();
      for (int seed : seeds)
      {
        largest = std::max(largest, association(i, seed));
      }
      if (largest < bestValue)
      {
        bestValue = largest;
        best = i;
      }
    }
    seeds.push_back(best);
  }
  Eigen::MatrixXd centres(k, points.cols());
  for (int c = 0; c < k; ++c)
  {
    centres.row(c) = points.row(seeds[c]);
  }
  std::vector<int> label(m, -1);
  for (iterations = 1; iterations <= 100; ++iterations)
  {
    bool changed = false;
    for (int i = 0; i < m; ++i)
    {
      int best = 0;
      (centres.rowwise() - points.row(i)).rowwise().squaredNorm().minCoeff(&best);
      changed = changed || best != label[i];
      label[i] = best;
    }
    if (!changed)
    {
      break;
    }
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(k, points.cols());
    std::vector<double> mass(k, 0.0);
    for (int i = 0; i < m; ++i)
    {
      sums.row(label[i]) += weights[i] * points.row(i);
      mass[label[i]] += weights[i];
    }
    for (int c = 0; c < k; ++c)
    {
      if (mass[c] > 0.0)
      {
        centres.row(c) = sums.row(c) / mass[c];
      }
    }
  }
  return label;
}

// Patches: Garland et al.'s clusters of `tree` cut at options.patchCount, or the faces themselves on
// meshes of at most that many.
std::vector<int> patchesOf(
  int n, const SpectralSegmentationOptions& options, const std::function<FaceClusterHierarchy()>& tree)
{
  std::vector<int> patch(n);
  if (n > options.patchCount)
  {
    patch = cutHierarchyAtCount(tree(), options.patchCount);
  }
  else
  {
    std::iota(patch.begin(), patch.end(), 0);
  }
  return patch;
}

// What segmentConnected reads that does not depend on k: the patches, their affinity and areas.
struct SpectralPreparation
{
  std::vector<int> patch;
  Eigen::MatrixXd affinity; ///< empty with a single patch
  std::vector<double> area;
  int patches = 0;
};

SpectralPreparation prepare(
  const FaceGraph& graph, const std::vector<int>& patch, const SpectralSegmentationOptions& options)
{
  SpectralPreparation prepared;
  prepared.patch = patch;
  prepared.patches = *std::max_element(patch.begin(), patch.end()) + 1;
  if (prepared.patches > 1)
  {
    prepared.affinity = spectralAffinity(graph, patch, options, prepared.area);
  }
  return prepared;
}

SpectralSegmentationResult segmentConnected(const FaceGraph& graph, const SpectralPreparation& prepared, int k)
{
  const int n = graph.faceCount();
  SpectralSegmentationResult result;
  const std::vector<int>& patch = prepared.patch;
  const std::vector<double>& area = prepared.area;
  const Eigen::MatrixXd& affinity = prepared.affinity;
  const int m = prepared.patches;
  result.patches = m;
  if (k == 1 || m == 1)
  {
    result.labels.assign(n, 0);
    return result;
  }
  const int dimensions = std::min(k, m);
  Eigen::VectorXd values;
  Eigen::MatrixXd embedding = leadingEigenvectors(affinity, dimensions, values);
  for (int p = 0; p < m; ++p)
  {
    const double norm = embedding.row(p).norm();
    if (norm > 0.0)
    {
      embedding.row(p) /= norm;
    }
  }
  const std::vector<int> cluster = clusterEmbedding(embedding, area, std::min(k, m), result.kMeansIterations);
  std::vector<int> labels(n);
  for (int f = 0; f < n; ++f)
  {
    labels[f] = cluster[patch[f]];
  }
  result.labels = finalizeSegments(graph, labels, k);
  return result;
}
} // namespace

std::vector<int> spectralPatches(const FaceGraph& graph, const SpectralSegmentationOptions& options)
{
  return patchesOf(graph.faceCount(), options,
    [&graph]() { return buildFaceClusterHierarchy(graph, HierarchicalClusteringOptions()); });
}

Eigen::MatrixXd spectralAffinity(const FaceGraph& graph, const std::vector<int>& patch,
  const SpectralSegmentationOptions& options, std::vector<double>& area)
{
  const int n = graph.faceCount();
  const int m = *std::max_element(patch.begin(), patch.end()) + 1;
  area.assign(m, 0.0);
  std::vector<Vector3> centroid(m, Vector3::Zero());
  for (int f = 0; f < n; ++f)
  {
    area[patch[f]] += graph.area(f);
    centroid[patch[f]] += graph.area(f) * graph.centroid(f);
  }
  for (int p = 0; p < m; ++p)
  {
    centroid[p] = area[p] > 0.0 ? Vector3(centroid[p] / area[p]) : centroid[p];
  }
  // Liu and Zhang 2004, section 3: angular distance eta (1 - cos alpha), eta = 1 where concave.
  std::vector<double> angular(graph.edgeCount());
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const DualEdge& d = graph.edge(e);
    angular[e] = (d.bend < 0.0 ? 1.0 : options.convexAngleWeight) * (1.0 - d.normalCosine);
  }
  // Patch boundaries: length, length-weighted angular distance and midpoint.
  struct Boundary
  {
    double length = 0.0, angular = 0.0;
    Vector3 middle = Vector3::Zero();
  };
  std::vector<std::map<int, Boundary>> boundaries(m);
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const DualEdge& d = graph.edge(e);
    const int a = patch[d.faces[0]], b = patch[d.faces[1]];
    if (a == b)
    {
      continue;
    }
    const TriangleMesh& mesh = graph.mesh();
    const Vector3 middle =
      0.5 * (mesh.point(mesh.edgeVertices(d.meshEdge)[0]) + mesh.point(mesh.edgeVertices(d.meshEdge)[1]));
    Boundary& boundary = boundaries[std::min(a, b)][std::max(a, b)];
    boundary.length += d.length;
    boundary.angular += d.length * angular[e];
    boundary.middle += d.length * middle;
  }
  struct PatchEdge
  {
    int a, b;
    double geodesic, angular;
  };
  std::vector<PatchEdge> patchEdges;
  double meanGeodesic = 0.0, meanPatchAngular = 0.0;
  for (int a = 0; a < m; ++a)
  {
    for (const auto& [b, boundary] : boundaries[a])
    {
      const double length = std::max(boundary.length, std::numeric_limits<double>::min());
      const Vector3 middle = boundary.middle / length;
      const PatchEdge edge{ a, b, (centroid[a] - middle).norm() + (centroid[b] - middle).norm(),
        boundary.angular / length };
      meanGeodesic += edge.geodesic;
      meanPatchAngular += edge.angular;
      patchEdges.push_back(edge);
    }
  }
  const double edges = std::max<double>(1.0, static_cast<double>(patchEdges.size()));
  meanGeodesic = meanGeodesic > 0.0 ? meanGeodesic / edges : 1.0;
  meanPatchAngular = meanPatchAngular > 0.0 ? meanPatchAngular / edges : 1.0;
  std::vector<std::vector<std::pair<int, double>>> adjacency(m);
  for (const PatchEdge& edge : patchEdges)
  {
    // Liu and Zhang 2004, section 3: Dist = delta Geod / avg(Geod) + (1 - delta) Ang / avg(Ang).
    const double distance = options.geodesicWeight * edge.geodesic / meanGeodesic +
      (1.0 - options.geodesicWeight) * edge.angular / meanPatchAngular;
    adjacency[edge.a].push_back({ edge.b, distance });
    adjacency[edge.b].push_back({ edge.a, distance });
  }
  // All-pairs shortest paths on the patch graph.
  Eigen::MatrixXd distance = Eigen::MatrixXd::Constant(m, m, std::numeric_limits<double>::infinity());
  for (int source = 0; source < m; ++source)
  {
    DistanceQueue heap;
    distance(source, source) = 0.0;
    heap.emplace(0.0, source);
    searchShortestPaths(
      heap, [&](int p) -> double& { return distance(source, p); },
      [&](int p, double d, const auto& lower) {
        for (const auto& [q, w] : adjacency[p])
        {
          lower(q, d + w);
        }
      });
  }
  const double sigma = std::max(distance.mean(), std::numeric_limits<double>::min());
  // W = exp(-Dist / (2 sigma^2)), N = D^-1/2 W D^-1/2 (Liu and Zhang 2004, section 3).
  Eigen::MatrixXd affinity = (-distance / (2.0 * sigma * sigma)).array().exp().matrix();
  const Eigen::VectorXd degree = affinity.rowwise().sum().cwiseMax(std::numeric_limits<double>::min());
  const Eigen::VectorXd scale = degree.cwiseSqrt().cwiseInverse();
  affinity = scale.asDiagonal() * affinity * scale.asDiagonal();
  return affinity;
}

namespace
{
void checkSpectralOptions(int k, int faces, const SpectralSegmentationOptions& options)
{
  checkSegmentCount(k, faces);
  if (!(options.geodesicWeight >= 0.0 && options.geodesicWeight <= 1.0) ||
    !(options.convexAngleWeight >= 0.0 && options.convexAngleWeight <= 1.0))
  {
    throw Error("the spectral distance weights delta and eta must lie in [0, 1]");
  }
  if (options.patchCount < 2)
  {
    throw Error("the spectral affinity needs at least 2 patches");
  }
}

SpectralSegmentationResult segmentGraph(const FaceGraph& graph, int k, const SpectralSegmentationOptions& options)
{
  return segmentConnected(graph, prepare(graph, spectralPatches(graph, options), options), k);
}
} // namespace

SpectralSegmentationResult segmentSpectrally(const FaceGraph& graph, int k, const SpectralSegmentationOptions& options)
{
  checkSpectralOptions(k, graph.faceCount(), options);
  if (graph.componentCount() == 1)
  {
    return segmentGraph(graph, k, options);
  }
  SpectralSegmentationResult result;
  result.labels = segmentComponents(graph, k, [&](const TriangleMesh& part, int partK) {
    const SpectralSegmentationResult partResult = segmentGraph(FaceGraph(part), partK, options);
    result.patches += partResult.patches;
    return partResult.labels;
  });
  return result;
}

SpectralSegmentationResult segmentSpectrally(const Surface& surface, int k, const SpectralSegmentationOptions& options)
{
  const FaceGraph& graph = faceGraph(surface);
  checkSpectralOptions(k, graph.faceCount(), options);
  if (graph.componentCount() > 1)
  {
    SpectralSegmentationResult result;
    result.labels = segmentSurfaceComponents(surface, k, [&](const Surface& part, int partK) {
      const SpectralSegmentationResult partResult = segmentSpectrally(part, partK, options);
      result.patches += partResult.patches;
      return partResult.labels;
    });
    return result;
  }
  // The patches come from the surface's cached face-cluster tree, the one spectralPatches builds.
  const std::string key = "spectral-affinity:delta=" + cacheKey(options.geodesicWeight) +
    " eta=" + cacheKey(options.convexAngleWeight) + " patches=" + std::to_string(options.patchCount);
  const SpectralPreparation& prepared = surface.derived<SpectralPreparation>(key, [&] {
    const std::vector<int> patch = patchesOf(graph.faceCount(), options,
      [&surface]() { return faceClusterHierarchy(surface, HierarchicalClusteringOptions()); });
    return prepare(graph, patch, options);
  });
  return segmentConnected(graph, prepared, k);
}

namespace
{
// Spectra's relative residual target, ||A x - theta x|| <= tol |theta|: tight enough that the
// eigenvalues and the subspace match the tridiagonal route's to rounding.
constexpr double LanczosTolerance = 1e-12;

void checkLeadingCount(const Eigen::MatrixXd& symmetric, int count)
{
  if (symmetric.cols() != symmetric.rows() || count < 1 || count > symmetric.rows())
  {
    throw Error("leading eigenvectors need a square matrix and a count between 1 and its size");
  }
}
} // namespace

Eigen::MatrixXd leadingEigenvectors(const Eigen::MatrixXd& symmetric, int count, Eigen::VectorXd& values)
{
  checkLeadingCount(symmetric, count);
  const Eigen::Index n = symmetric.rows();
  const Eigen::Index subspace = std::max<Eigen::Index>(2 * count + 1, 20);
  if (subspace < n)
  {
    // Spectra's implicitly restarted Lanczos (its fixed start vector keeps it deterministic):
    // products with the matrix, no O(n^3) reduction.
    Spectra::DenseSymMatProd<double> product(symmetric);
    Spectra::SymEigsSolver<Spectra::DenseSymMatProd<double>> solver(product, count, subspace);
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, LanczosTolerance, Spectra::SortRule::SmallestAlge);
    if (solver.info() == Spectra::CompInfo::Successful)
    {
      Eigen::VectorXd lanczosValues = solver.eigenvalues();
      Eigen::MatrixXd vectors = solver.eigenvectors();
      // Checked, not trusted, as the tridiagonal route checks its own; the infinity norm bounds the
      // spectrum's scale.
      const double scale =
        std::max(symmetric.cwiseAbs().rowwise().sum().maxCoeff(), std::numeric_limits<double>::min());
      const double residual = (symmetric * vectors - vectors * lanczosValues.asDiagonal()).colwise().norm().maxCoeff();
      if (residual <= 1e-8 * scale &&
        (vectors.transpose() * vectors - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff() <= 1e-8)
      {
        values = lanczosValues;
        return vectors;
      }
    }
  }
  return tridiagonalLeadingEigenvectors(symmetric, count, values);
}

Eigen::MatrixXd tridiagonalLeadingEigenvectors(const Eigen::MatrixXd& symmetric, int count, Eigen::VectorXd& values)
{
  checkLeadingCount(symmetric, count);
  const Eigen::Index n = symmetric.rows();
  const Eigen::Tridiagonalization<Eigen::MatrixXd> reduction(symmetric);
  const Eigen::VectorXd diagonal = reduction.diagonal();
  const Eigen::VectorXd offDiagonal = reduction.subDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum;
  spectrum.computeFromTridiagonal(diagonal, offDiagonal, Eigen::EigenvaluesOnly);
  if (spectrum.info() != Eigen::Success)
  {
    throw Error("the eigenvalues of the spectral embedding's matrix did not converge");
  }
  values = spectrum.eigenvalues().tail(count);
  const double scale = std::max({ std::abs(spectrum.eigenvalues()[0]), std::abs(spectrum.eigenvalues()[n - 1]),
    std::numeric_limits<double>::min() });
  const double tiny = std::numeric_limits<double>::epsilon() * scale; // a zero pivot's stand-in (LAPACK's dlagts)
  Eigen::MatrixXd vectors(n, count);
  // The tridiagonal system (T - s I) y = x by Gaussian elimination with partial pivoting (the
  // elimination of LAPACK's dgtsv), s a hair away from the eigenvalue so that it stays regular.
  Eigen::VectorXd lower(n), main(n), upper(n), second(n), x(n);
  for (int j = 0; j < count; ++j)
  {
    const double shift = values[j] + 1e-10 * scale;
    // A fixed start of its own for each vector, with no symmetry: a low-discrepancy sequence in
    // (-1, 1), shifted per vector so that the vectors of an exactly repeated eigenvalue (a
    // tridiagonal matrix that splits) start apart.
    for (Eigen::Index i = 0; i < n; ++i)
    {
      x[i] = 2.0 * std::fmod(0.5 + 0.6180339887498949 * static_cast<double>(i + 1) + 0.7548776662466927 * j, 1.0) - 1.0;
    }
    for (int iteration = 0; iteration < 3; ++iteration)
    {
      main = diagonal.array() - shift;
      if (n > 1)
      {
        lower.head(n - 1) = offDiagonal;
        upper.head(n - 1) = offDiagonal;
      }
      second.setZero();
      for (Eigen::Index i = 0; i + 1 < n; ++i)
      {
        if (std::abs(main[i]) >= std::abs(lower[i]))
        {
          if (main[i] == 0.0)
          {
            main[i] = tiny;
          }
          const double factor = lower[i] / main[i];
          main[i + 1] -= factor * upper[i];
          x[i + 1] -= factor * x[i];
        }
        else
        {
          const double factor = main[i] / lower[i];
          main[i] = lower[i];
          const double below = main[i + 1];
          main[i + 1] = upper[i] - factor * below;
          if (i + 2 < n)
          {
            second[i] = upper[i + 1];
            upper[i + 1] = -factor * second[i];
          }
          upper[i] = below;
          std::swap(x[i], x[i + 1]);
          x[i + 1] -= factor * x[i];
        }
      }
      if (main[n - 1] == 0.0)
      {
        main[n - 1] = tiny;
      }
      x[n - 1] /= main[n - 1];
      if (n > 1)
      {
        x[n - 2] = (x[n - 2] - upper[n - 2] * x[n - 1]) / main[n - 2];
      }
      for (Eigen::Index i = n - 3; i >= 0; --i)
      {
        x[i] = (x[i] - upper[i] * x[i + 1] - second[i] * x[i + 2]) / main[i];
      }
      for (int earlier = 0; earlier < j; ++earlier)
      {
        x -= vectors.col(earlier).dot(x) * vectors.col(earlier);
      }
      x /= std::max(x.norm(), std::numeric_limits<double>::min());
    }
    vectors.col(j) = x;
  }
  // Checked, not trusted: if a vector failed to converge (a residual far above rounding) or the
  // orthogonalisation emptied it, Eigen's full decomposition of the tridiagonal matrix decides.
  const Eigen::MatrixXd tridiagonal = reduction.matrixT();
  const double residual = (tridiagonal * vectors - vectors * values.asDiagonal()).colwise().norm().maxCoeff();
  if (!(residual <= 1e-8 * scale) ||
    !((vectors.transpose() * vectors - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff() <= 1e-8))
  {
    spectrum.computeFromTridiagonal(diagonal, offDiagonal, Eigen::ComputeEigenvectors);
    if (spectrum.info() != Eigen::Success)
    {
      throw Error("the eigenvectors of the spectral embedding's matrix did not converge");
    }
    vectors = spectrum.eigenvectors().rightCols(count);
  }
  return reduction.matrixQ() * vectors;
}

} // namespace kerf
