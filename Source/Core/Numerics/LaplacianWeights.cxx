// Laplacian edge weights (uniform, cotangent, intrinsic Delaunay, Au et al. 2011, ROI Scissor) and assembly.
#include "Numerics/LaplacianWeights.h"

#include "CacheKey.h"
#include "Error.h"
#include "Mesh/MeshValidation.h"
#include "Numerics/IntrinsicTriangulation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace kerf
{

namespace
{
// Cotangent of the angle between a and b, clamped.
double cotangent(const Vector3& a, const Vector3& b)
{
  const double sine = a.cross(b).norm();
  const double cosine = a.dot(b);
  if (sine <= 0.0)
  {
    return cosine >= 0.0 ? CotangentLimit : -CotangentLimit;
  }
  return std::clamp(cosine / sine, -CotangentLimit, CotangentLimit);
}

std::vector<double> cotangentWeights(const TriangleMesh& mesh)
{
  const std::vector<double> cotangents = cornerCotangents(mesh);
  std::vector<double> weights(mesh.edgeCount(), 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    // Edge k joins corners k and k+1; the angle opposite it is at corner k+2.
    for (int k = 0; k < 3; ++k)
    {
      const int e = mesh.faceEdge(f, k);
      if (e >= 0)
      {
        weights[e] += 0.5 * cotangents[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>((k + 2) % 3)];
      }
    }
  }
  return weights;
}

// The intrinsic Delaunay weights on the mesh's own edges; throws if a flip made a new vertex pair.
std::vector<double> intrinsicDelaunayWeights(const TriangleMesh& mesh)
{
  IntrinsicTriangulation triangulation(mesh);
  triangulation.flipToDelaunay();
  std::vector<double> weights(mesh.edgeCount(), 0.0);
  int missing = 0;
  for (const IntrinsicTriangulation::PairWeight& pair : triangulation.cotangentWeights())
  {
    const IndexRange neighbors = mesh.vertexNeighbors(pair.i);
    const auto found = std::find(neighbors.begin(), neighbors.end(), pair.j);
    if (found != neighbors.end())
    {
      weights[mesh.vertexEdges(pair.i)[static_cast<std::size_t>(found - neighbors.begin())]] = pair.weight;
    }
    else if (pair.weight > 0.0)
    {
      ++missing;
    }
  }
  if (missing > 0)
  {
    throw Error("the intrinsic Delaunay triangulation of this mesh joins " + std::to_string(missing) +
      " vertex pairs that no mesh edge joins, so its Laplacian has no weights on the mesh's edges; "
      "solve on the mesh of intrinsicDelaunayLaplacian() instead");
  }
  return weights;
}

// The value below which a fraction q of the values lie (q = 1: the maximum).
double quantile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return 0.0;
  }
  const std::size_t k = std::min(values.size() - 1,
    static_cast<std::size_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1))));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

std::vector<double> concavityWeights(
  const TriangleMesh& mesh, const LaplacianWeightOptions& options, const SurfaceDescriptors& d)
{
  const int edges = mesh.edgeCount();
  std::vector<double> G(edges);
  for (int e = 0; e < edges; ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    G[e] = std::abs(d.gaussianCurvature[ev[0]]) + std::abs(d.gaussianCurvature[ev[1]]);
  }
  // The regularisation's scale is the mean total curvature k1^2 + k2^2 (at least 1 / diagonal^2),
  // so that flat or cylindrical regions, whose Gaussian curvature is rounding noise, get uniform
  // finite weights instead of weights set by that noise.
  double totalCurvature = 0.0;
  int used = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.vertexFaces(v).empty())
    {
      totalCurvature += d.maximumCurvature[v] * d.maximumCurvature[v] + d.minimumCurvature[v] * d.minimumCurvature[v];
      ++used;
    }
  }
  const double diagonal = mesh.boundingBoxDiagonal();
  const double scale =
    std::max(used > 0 ? totalCurvature / used : 0.0, diagonal > 0.0 ? 1.0 / (diagonal * diagonal) : 1.0);
  const double epsilon = options.curvatureRegularization * scale;

  // ROI Scissor's H_max over the concave mean curvature (positive where concave).
  double hMax = 0.0;
  if (options.weighting == LaplacianWeighting::SmoothConcavity)
  {
    std::vector<double> concaveH;
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      if (!mesh.vertexFaces(v).empty() && -d.meanCurvature[v] > 0.0)
      {
        concaveH.push_back(-d.meanCurvature[v]);
      }
    }
    hMax = quantile(concaveH, options.concavityQuantile);
  }

  std::vector<double> weights(edges);
  for (int e = 0; e < edges; ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    const double length = (mesh.point(ev[1]) - mesh.point(ev[0])).norm();
    double beta = 1.0;
    if (options.weighting == LaplacianWeighting::ConcavityAware)
    {
      beta = (d.concave[ev[0]] || d.concave[ev[1]]) ? options.concaveBeta : 1.0;
    }
    else if (hMax > 0.0)
    {
      const double t = std::min((-d.meanCurvature[ev[0]] - d.meanCurvature[ev[1]]) / (2.0 * hMax), 1.0);
      beta = t > 0.0 ? 1.0 / (1.0 + 100.0 * t * t) : 1.0;
    }
    weights[e] = length / (G[e] + epsilon) * beta;
  }
  return weights;
}
} // namespace

std::vector<double> cornerCotangents(const TriangleMesh& mesh)
{
  std::vector<double> cotangents(3 * static_cast<std::size_t>(mesh.faceCount()), 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const Vector3& p0 = mesh.point(t[0]);
    const Vector3& p1 = mesh.point(t[1]);
    const Vector3& p2 = mesh.point(t[2]);
    const double longest = std::max({ (p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm() });
    if (isZeroArea((p1 - p0).cross(p2 - p0).norm(), longest))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const Vector3& corner = mesh.point(t[k]);
      cotangents[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)] =
        cotangent(mesh.point(t[(k + 1) % 3]) - corner, mesh.point(t[(k + 2) % 3]) - corner);
    }
  }
  return cotangents;
}

std::vector<double> computeLaplacianWeights(
  const TriangleMesh& mesh, const LaplacianWeightOptions& options, const SurfaceDescriptors* descriptors)
{
  std::vector<double> weights;
  switch (options.weighting)
  {
    case LaplacianWeighting::Uniform:
      weights.assign(mesh.edgeCount(), 1.0);
      break;
    case LaplacianWeighting::Cotangent:
      weights = cotangentWeights(mesh);
      break;
    case LaplacianWeighting::IntrinsicDelaunay:
      weights = intrinsicDelaunayWeights(mesh);
      break;
    case LaplacianWeighting::ConcavityAware:
    case LaplacianWeighting::SmoothConcavity:
    {
      if (descriptors)
      {
        weights = concavityWeights(mesh, options, *descriptors);
      }
      else
      {
        weights = concavityWeights(mesh, options, computeSurfaceDescriptors(mesh));
      }
      break;
    }
  }
  // Negative weights become 0 (an M-matrix); a vertex left with no positive weight gets the floor
  // on its edges, so that it stays connected.
  double sum = 0.0;
  int positive = 0;
  for (double& w : weights)
  {
    w = std::isfinite(w) ? std::max(w, 0.0) : 0.0;
    if (w > 0.0)
    {
      sum += w;
      ++positive;
    }
  }
  if (positive == 0)
  {
    if (mesh.edgeCount() > 0)
    {
      throw Error("every Laplacian weight is zero or negative; the mesh is degenerate");
    }
    return weights;
  }
  const double floor = WeightFloor * sum / positive;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    double total = 0.0;
    for (int e : mesh.vertexEdges(v))
    {
      total += weights[e];
    }
    if (total == 0.0)
    {
      for (int e : mesh.vertexEdges(v))
      {
        weights[e] = floor;
      }
    }
  }
  return weights;
}

bool needsDescriptors(LaplacianWeighting weighting)
{
  return weighting == LaplacianWeighting::ConcavityAware || weighting == LaplacianWeighting::SmoothConcavity;
}

namespace
{
const std::pair<LaplacianWeighting, const char*> WeightingNames[] = {
  { LaplacianWeighting::Uniform, "uniform" },
  { LaplacianWeighting::Cotangent, "cotangent" },
  { LaplacianWeighting::ConcavityAware, "concavity" },
  { LaplacianWeighting::SmoothConcavity, "smooth-concavity" },
  { LaplacianWeighting::IntrinsicDelaunay, "intrinsic-delaunay" },
};
} // namespace

std::string laplacianWeightingName(LaplacianWeighting weighting)
{
  for (const auto& entry : WeightingNames)
  {
    if (entry.first == weighting)
    {
      return entry.second;
    }
  }
  throw Error("unknown Laplacian weighting");
}

LaplacianWeighting parseLaplacianWeighting(const std::string& name)
{
  for (const auto& entry : WeightingNames)
  {
    if (name == entry.second)
    {
      return entry.first;
    }
  }
  throw Error(
    "weighting must be uniform, cotangent, concavity, smooth-concavity or intrinsic-delaunay, got '" + name + "'");
}

std::string cacheKey(const LaplacianWeightOptions& options)
{
  std::string key = laplacianWeightingName(options.weighting);
  if (needsDescriptors(options.weighting))
  {
    key += " beta=" + cacheKey(options.concaveBeta) + " regularization=" + cacheKey(options.curvatureRegularization) +
      " quantile=" + cacheKey(options.concavityQuantile);
  }
  return key;
}

double laplacianMeanDiagonal(const TriangleMesh& mesh, const std::vector<double>& edgeWeights)
{
  double sum = 0.0;
  for (double w : edgeWeights)
  {
    sum += 2.0 * w;
  }
  int used = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    used += mesh.vertexFaces(v).empty() ? 0 : 1;
  }
  return used > 0 && sum > 0.0 ? sum / used : 1.0;
}

Eigen::SparseMatrix<double> assembleLaplacian(const TriangleMesh& mesh, const std::vector<double>& edgeWeights)
{
  const int n = mesh.vertexCount();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n) + 2 * edgeWeights.size());
  std::vector<double> diagonal(n, 0.0);
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    entries.emplace_back(ev[0], ev[1], -edgeWeights[e]);
    entries.emplace_back(ev[1], ev[0], -edgeWeights[e]);
    diagonal[ev[0]] += edgeWeights[e];
    diagonal[ev[1]] += edgeWeights[e];
  }
  for (int v = 0; v < n; ++v)
  {
    entries.emplace_back(v, v, diagonal[v]);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

} // namespace kerf
