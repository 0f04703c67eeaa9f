// Core extraction: coarsening, multidimensional scaling, feature points, the mirrored core and its pieces.
#include "Segmentation/CoreExtraction.h"

#include "Error.h"
#include "Geometry/ConvexHull.h"
#include "Mesh/ShortestPaths.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace kerf
{

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double Pi = 3.14159265358979323846;

// The coarse graph of one component: samples (faces), each face's nearest sample, and the samples'
// neighbours with the length of the shortest path through their two cells.
struct CoarseGraph
{
  std::vector<int> samples;
  std::vector<std::vector<std::pair<int, double>>> neighbours;
  std::vector<double> areas; ///< of each sample's cell
};

// Farthest-point sampling (each sample the face farthest from those before, by a Dijkstra search
// that only lowers distances) over the faces of one component; `nearest` gets each face's sample.
CoarseGraph coarsen(const FaceGraph& graph, const std::vector<int>& faces, int size, std::vector<double>& distance,
  std::vector<int>& nearest)
{
  const auto length = [&graph](int e) { return graph.edge(e).centroidPath; };
  const auto grow = [&](int source, int sample) {
    DistanceQueue queue;
    distance[source] = 0.0;
    nearest[source] = sample;
    queue.emplace(0.0, source);
    searchShortestPaths(
      queue, [&](int f) -> double& { return distance[f]; },
      [&](int f, double d, auto&& lower) {
        for (int e : graph.faceEdges(f))
        {
          if (e >= 0)
          {
            const int g = graph.opposite(e, f);
            if (lower(g, d + length(e)))
            {
              nearest[g] = nearest[f];
            }
          }
        }
      });
  };
  const auto farthestFace = [&]() {
    int best = faces.front();
    for (int f : faces)
    {
      if (distance[f] > distance[best])
      {
        best = f;
      }
    }
    return best;
  };
  // The first sample is the face farthest from the component's first face, so that the samples do
  // not depend on where the numbering starts more than they must.
  grow(faces.front(), 0);
  CoarseGraph coarse;
  coarse.samples.push_back(farthestFace());
  for (int f : faces)
  {
    distance[f] = Infinity;
  }
  grow(coarse.samples.front(), 0);
  while (static_cast<int>(coarse.samples.size()) < size)
  {
    const int next = farthestFace();
    if (!(distance[next] > 0.0))
    {
      break;
    }
    coarse.samples.push_back(next);
    grow(next, static_cast<int>(coarse.samples.size()) - 1);
  }
  const int m = static_cast<int>(coarse.samples.size());
  std::map<std::pair<int, int>, double> joins;
  coarse.areas.assign(m, 0.0);
  for (int f : faces)
  {
    coarse.areas[nearest[f]] += graph.area(f);
    for (int e : graph.faceEdges(f))
    {
      if (e < 0)
      {
        continue;
      }
      const int g = graph.opposite(e, f);
      const int a = nearest[f];
      const int b = nearest[g];
      if (a < b)
      {
        const double through = distance[f] + length(e) + distance[g];
        auto [it, added] = joins.emplace(std::make_pair(a, b), through);
        if (!added)
        {
          it->second = std::min(it->second, through);
        }
      }
    }
  }
  coarse.neighbours.assign(m, {});
  for (const auto& [pair, through] : joins)
  {
    coarse.neighbours[pair.first].emplace_back(pair.second, through);
    coarse.neighbours[pair.second].emplace_back(pair.first, through);
  }
  for (auto& list : coarse.neighbours)
  {
    std::sort(list.begin(), list.end());
  }
  return coarse;
}

// Geodesic distances between all samples on the coarse graph.
Eigen::MatrixXd sampleDistances(const CoarseGraph& coarse)
{
  const int m = static_cast<int>(coarse.samples.size());
  Eigen::MatrixXd distances = Eigen::MatrixXd::Constant(m, m, Infinity);
  for (int s = 0; s < m; ++s)
  {
    DistanceQueue queue;
    distances(s, s) = 0.0;
    queue.emplace(0.0, s);
    searchShortestPaths(
      queue, [&](int v) -> double& { return distances(v, s); },
      [&](int v, double d, auto&& lower) {
        for (const auto& [w, length] : coarse.neighbours[v])
        {
          lower(w, d + length);
        }
      });
  }
  // Each column is one search; the matrix is symmetric up to rounding: make it exactly so.
  return 0.5 * (distances + distances.transpose());
}

// Classical multidimensional scaling (Torgerson 1952) into 3D: B = -1/2 J D^2 J, coordinates from
// the three largest eigenpairs.
std::vector<Vector3> embed(const Eigen::MatrixXd& distances)
{
  const Eigen::MatrixXd squared = distances.cwiseProduct(distances);
  const Eigen::VectorXd rowMeans = squared.rowwise().mean();
  const double mean = rowMeans.mean();
  Eigen::MatrixXd b = -0.5 * squared;
  b.colwise() += 0.5 * rowMeans;
  b.rowwise() += 0.5 * rowMeans.transpose();
  b.array() -= 0.5 * mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(b);
  const int m = static_cast<int>(distances.rows());
  std::vector<Vector3> points(m, Vector3::Zero());
  for (int k = 0; k < 3 && k < m; ++k)
  {
    const int column = m - 1 - k;
    const double scale = std::sqrt(std::max(solver.eigenvalues()(column), 0.0));
    Eigen::VectorXd v = solver.eigenvectors().col(column);
    // A fixed sign (the largest entry positive) so that the embedding is one, whatever the solver's.
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    if (v(largest) < 0.0)
    {
      v = -v;
    }
    for (int i = 0; i < m; ++i)
    {
      points[i][k] = scale * v(i);
    }
  }
  return points;
}

// Pieces of the coarse graph outside `core`, and how many feature points each holds.
struct Pieces
{
  std::vector<int> piece; ///< per sample, -1 in the core
  std::vector<int> features;
  int separated = 0; ///< pieces holding at least one feature point
  bool allSeparated = true;
};

Pieces piecesOutside(const CoarseGraph& coarse, const std::vector<char>& core, const std::vector<char>& feature)
{
  const int m = static_cast<int>(coarse.samples.size());
  Pieces pieces;
  pieces.piece.assign(m, -1);
  std::vector<int> stack;
  for (int s = 0; s < m; ++s)
  {
    if (core[s] || pieces.piece[s] >= 0)
    {
      continue;
    }
    const int id = static_cast<int>(pieces.features.size());
    pieces.features.push_back(0);
    pieces.piece[s] = id;
    stack.push_back(s);
    while (!stack.empty())
    {
      const int v = stack.back();
      stack.pop_back();
      pieces.features[id] += feature[v] ? 1 : 0;
      for (const auto& [w, length] : coarse.neighbours[v])
      {
        if (!core[w] && pieces.piece[w] < 0)
        {
          pieces.piece[w] = id;
          stack.push_back(w);
        }
      }
    }
  }
  for (int count : pieces.features)
  {
    pieces.separated += count > 0 ? 1 : 0;
    pieces.allSeparated = pieces.allSeparated && count <= 1;
  }
  return pieces;
}

// The distance from `core` to the nearest of the feature points outside `outside` (0 for one that
// `core` holds; infinite if there is none).
double coreDistance(const Eigen::MatrixXd& distances, const std::vector<char>& core, const std::vector<char>& outside,
  const std::vector<char>& feature)
{
  double nearest = Infinity;
  const int m = static_cast<int>(core.size());
  for (int f = 0; f < m; ++f)
  {
    if (!feature[f] || outside[f])
    {
      continue;
    }
    for (int c = 0; c < m; ++c)
    {
      if (core[c])
      {
        nearest = std::min(nearest, distances(f, c));
      }
    }
  }
  return nearest;
}

// True when every face of the component lies within a degree of its mean plane's orientation.
bool isPlanar(const FaceGraph& graph, const std::vector<int>& faces)
{
  Vector3 mean = Vector3::Zero();
  for (int f : faces)
  {
    mean += graph.area(f) * graph.normal(f);
  }
  if (!(mean.norm() > 0.0))
  {
    return false;
  }
  mean.normalize();
  const double cosine = std::cos(Pi / 180.0);
  return std::all_of(faces.begin(), faces.end(),
    [&](int f) { return graph.normal(f).squaredNorm() == 0.0 || graph.normal(f).dot(mean) >= cosine; });
}

struct ComponentResult
{
  std::vector<int> sampleLabel; ///< 0 for the core, 1.. for the segments
  std::vector<char> sampleCore;
  std::vector<int> featureSamples;
  int extensions = 0;
};

// A planar component, one of fewer than ten samples or with a flat embedding is one segment.
ComponentResult extractCore(
  const CoarseGraph& coarse, double componentArea, bool planar, const CoreExtractionOptions& options)
{
  const int m = static_cast<int>(coarse.samples.size());
  ComponentResult result;
  result.sampleLabel.assign(m, 0);
  result.sampleCore.assign(m, 1);
  if (m < 10 || planar)
  {
    return result;
  }
  const Eigen::MatrixXd distances = sampleDistances(coarse);
  const std::vector<Vector3> embedding = embed(distances);
  Vector3 centre = Vector3::Zero();
  for (const Vector3& p : embedding)
  {
    centre += p;
  }
  centre /= m;
  double radius = 0.0;
  for (const Vector3& p : embedding)
  {
    radius = std::max(radius, (p - centre).norm());
  }
  const double tolerance = options.hullTolerance * radius;
  const ConvexHull hull = convexHull(embedding, tolerance);
  if (!(radius > 0.0) || hull.flat)
  {
    return result; // a flat embedding: one segment
  }
  const std::vector<double> depths = hullDepths(hull, embedding);
  // Feature points: on the hull and the largest sum of geodesic distances nearby (equation 1).
  const Eigen::VectorXd sums = distances.rowwise().sum();
  const double reach = options.featureRadius * distances.maxCoeff();
  std::vector<char> feature(m, 0);
  for (int i = 0; i < m; ++i)
  {
    if (depths[i] > tolerance)
    {
      continue;
    }
    bool largest = true;
    for (int j = 0; j < m && largest; ++j)
    {
      if (j != i && distances(i, j) <= reach)
      {
        largest = sums(i) > sums(j) || (sums(i) == sums(j) && i < j);
      }
    }
    feature[i] = largest ? 1 : 0;
  }

  // The core: samples on the hull of the embedding mirrored in its bounding sphere.
  std::vector<Vector3> mirrored(m);
  for (int i = 0; i < m; ++i)
  {
    const Vector3 offset = embedding[i] - centre;
    const double r = offset.norm();
    mirrored[i] = r > 0.0 ? Vector3(centre + (2.0 * radius - r) / r * offset) : centre;
  }
  const ConvexHull mirrorHull = convexHull(mirrored, tolerance);
  const std::vector<double> mirrorDepths = hullDepths(mirrorHull, mirrored);
  std::vector<char> core(m, 0);
  for (int i = 0; i < m; ++i)
  {
    core[i] = mirrorHull.flat || mirrorDepths[i] <= tolerance || embedding[i] == centre ? 1 : 0;
  }

  // Grown ring by ring until the feature points are separated; back to the last separation when a
  // ring comes too close to a feature point.
  Pieces pieces = piecesOutside(coarse, core, feature);
  std::vector<char> best = core;
  int bestSeparated = pieces.separated;
  int bestExtensions = 0;
  int extensions = 0;
  const std::vector<char> initial = core;
  const double initialDistance = coreDistance(distances, initial, initial, feature);
  while (!pieces.allSeparated)
  {
    std::vector<char> grown = core;
    for (int v = 0; v < m; ++v)
    {
      if (core[v])
      {
        for (const auto& [w, length] : coarse.neighbours[v])
        {
          grown[w] = 1;
        }
      }
    }
    if (grown == core)
    {
      break;
    }
    // To the feature points outside the initial core (one the ring swallows is at 0), against
    // the initial core's distance to them.
    if (!(coreDistance(distances, grown, initial, feature) >= options.extensionFactor * initialDistance))
    {
      break;
    }
    core = std::move(grown);
    ++extensions;
    pieces = piecesOutside(coarse, core, feature);
    if (pieces.separated > bestSeparated || pieces.allSeparated)
    {
      best = core;
      bestSeparated = pieces.separated;
      bestExtensions = extensions;
    }
  }
  core = best;
  result.extensions = bestExtensions;
  pieces = piecesOutside(coarse, core, feature);

  // Pieces with a feature point and enough area are segments; the rest joins the core.
  std::vector<double> pieceArea(pieces.features.size(), 0.0);
  for (int s = 0; s < m; ++s)
  {
    if (pieces.piece[s] >= 0)
    {
      pieceArea[pieces.piece[s]] += coarse.areas[s];
    }
  }
  std::vector<int> pieceLabel(pieces.features.size(), 0);
  int next = 1;
  for (std::size_t p = 0; p < pieceLabel.size(); ++p)
  {
    if (pieces.features[p] > 0 && pieceArea[p] >= options.minimumSegmentArea * componentArea)
    {
      pieceLabel[p] = next++;
    }
  }
  for (int s = 0; s < m; ++s)
  {
    result.sampleLabel[s] = pieces.piece[s] >= 0 ? pieceLabel[pieces.piece[s]] : 0;
    result.sampleCore[s] = core[s];
    if (feature[s])
    {
      result.featureSamples.push_back(s);
    }
  }
  return result;
}
} // namespace

void checkCoreExtractionOptions(const CoreExtractionOptions& options)
{
  if (options.coarseSize < 10)
  {
    throw Error("core extraction's coarse size must be at least 10, not " + std::to_string(options.coarseSize));
  }
  if (!(options.featureRadius > 0.0 && options.featureRadius <= 1.0))
  {
    throw Error("core extraction's feature radius must lie in (0, 1]");
  }
  if (!(options.hullTolerance >= 0.0 && options.hullTolerance < 1.0))
  {
    throw Error("core extraction's hull tolerance must lie in [0, 1)");
  }
  if (!(options.extensionFactor > 0.0 && options.extensionFactor < 1.0))
  {
    throw Error("core extraction's extension factor must lie in (0, 1)");
  }
  if (!(options.minimumSegmentArea >= 0.0 && options.minimumSegmentArea < 1.0))
  {
    throw Error("core extraction's minimum segment area must lie in [0, 1)");
  }
  checkBoundaryRefinementOptions(options.refinement);
}

CoreExtractionResult segmentByCoreExtraction(const FaceGraph& graph, const CoreExtractionOptions& options)
{
  checkCoreExtractionOptions(options);
  const int n = graph.faceCount();
  CoreExtractionResult result;
  result.core.assign(n, 0);
  if (n == 0)
  {
    return result;
  }
  std::vector<std::vector<int>> components(graph.componentCount());
  for (int f = 0; f < n; ++f)
  {
    components[graph.component(f)].push_back(f);
  }
  std::vector<double> distance(n, Infinity);
  std::vector<int> nearest(n, -1);
  std::vector<int> labels(n, 0);
  int offset = 0;
  for (const std::vector<int>& faces : components)
  {
    double area = 0.0;
    for (int f : faces)
    {
      area += graph.area(f);
    }
    const CoarseGraph coarse = coarsen(graph, faces, options.coarseSize, distance, nearest);
    // A planar patch has nothing that protrudes: one segment.
    const ComponentResult component = extractCore(coarse, area, isPlanar(graph, faces), options);
    int largest = 0;
    for (int f : faces)
    {
      const int s = nearest[f];
      labels[f] = offset + component.sampleLabel[s];
      result.core[f] = component.sampleCore[s];
      largest = std::max(largest, component.sampleLabel[s]);
    }
    for (int s : component.featureSamples)
    {
      result.featureFaces.push_back(coarse.samples[s]);
    }
    result.coreExtensions += component.extensions;
    offset += largest + 1;
  }
  result.featurePoints = static_cast<int>(result.featureFaces.size());
  result.labels = options.refinement.bandWidth > 0.0 ? refineSegmentBoundaries(graph, labels, options.refinement).labels
                                                     : finalizeSegments(graph, labels, offset);
  result.segmentCount = result.labels.empty() ? 0 : *std::max_element(result.labels.begin(), result.labels.end()) + 1;
  return result;
}

} // namespace kerf
