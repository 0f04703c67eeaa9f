// Strokes snapped to vertices, multi-source growing under the isophotic metric, face labels and boundaries.
#include "Segmentation/RegionGrowing.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/MinimumCut.h"
#include "Mesh/ShortestPaths.h"
#include "Segmentation/RandomWalk.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace kerf
{

namespace
{
std::string numberText(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

void checkCutPlacementOptions(const CutPlacementOptions& options)
{
  if (!(options.band >= 0.0 && options.band < 1.0))
  {
    throw Error("the cut band must lie in [0, 1), not " + numberText(options.band));
  }
  if (!(options.convexWeight >= 0.0 && options.dataWeight >= 0.0) || !std::isfinite(options.convexWeight) ||
    !std::isfinite(options.dataWeight))
  {
    throw Error("the cut placement's weights must be finite and not negative");
  }
}
} // namespace

std::string boundaryPlacementName(BoundaryPlacement placement)
{
  switch (placement)
  {
    case BoundaryPlacement::Fronts:
      return "fronts";
    case BoundaryPlacement::MinimumCut:
      return "minimum-cut";
    case BoundaryPlacement::RandomWalks:
      return "random-walks";
  }
  throw Error("unknown boundary placement " + std::to_string(static_cast<int>(placement)));
}

BoundaryPlacement parseBoundaryPlacement(const std::string& name)
{
  for (BoundaryPlacement placement :
    { BoundaryPlacement::Fronts, BoundaryPlacement::MinimumCut, BoundaryPlacement::RandomWalks })
  {
    if (name == boundaryPlacementName(placement))
    {
      return placement;
    }
  }
  throw Error("unknown boundary placement \"" + name + "\" (fronts, minimum-cut or random-walks)");
}

StrokeSeeds snapStrokes(const TriangleMesh& mesh, const ClosestPointLocator& locator,
  const std::vector<LabelledStroke>& strokes, double maximumDistance)
{
  if (strokes.empty())
  {
    throw Error("there is no stroke; region growing needs strokes of at least two labels");
  }
  if (mesh.empty())
  {
    throw Error("the surface has no triangles");
  }
  const double spacing = 0.5 * mesh.meanEdgeLength();
  // A segment longer than the surface is sampled no finer than this (a point far off the surface
  // must not make millions of samples).
  const double longest = 4.0 * mesh.boundingBoxDiagonal() + 2.0 * maximumDistance;
  StrokeSeeds seeds;
  std::unordered_map<int, int> seedLabel;
  auto mark = [&](int vertex, int label) {
    const auto [found, added] = seedLabel.emplace(vertex, label);
    if (added)
    {
      seeds.vertices.push_back(vertex);
      seeds.labels.push_back(label);
    }
    else if (found->second != label)
    {
      ++seeds.contested;
    }
  };
  // Marks `vertex` after `previous` along a stroke; where they are not neighbours, first the
  // common neighbour nearest to their midpoint, so that the marked vertices form a chain.
  auto follow = [&](int previous, int vertex, int label) {
    if (vertex == previous)
    {
      return;
    }
    const IndexRange around = mesh.vertexNeighbors(previous);
    if (std::find(around.begin(), around.end(), vertex) == around.end())
    {
      const Vector3 middle = 0.5 * (mesh.point(previous) + mesh.point(vertex));
      int bridge = -1;
      for (int w : mesh.vertexNeighbors(vertex))
      {
        if (std::find(around.begin(), around.end(), w) != around.end() &&
          (bridge < 0 || (mesh.point(w) - middle).squaredNorm() < (mesh.point(bridge) - middle).squaredNorm()))
        {
          bridge = w;
        }
      }
      if (bridge >= 0)
      {
        mark(bridge, label);
      }
    }
    mark(vertex, label);
  };
  auto snap = [&](const Vector3& point, std::size_t stroke, std::size_t index, bool sample) {
    const ClosestPointLocator::Hit hit = locator.closest(point);
    if (!sample && maximumDistance > 0.0 && hit.distance > maximumDistance)
    {
      throw Error("point " + std::to_string(index) + " of stroke " + std::to_string(stroke) + " is " +
        numberText(hit.distance) + " away from the surface, farther than the allowed " + numberText(maximumDistance));
    }
    return snapToVertex(mesh, hit);
  };
  for (std::size_t s = 0; s < strokes.size(); ++s)
  {
    const LabelledStroke& stroke = strokes[s];
    if (stroke.label < 0)
    {
      throw Error("stroke " + std::to_string(s) + " has the label " + std::to_string(stroke.label) +
        "; labels must be non-negative (-1 marks vertices no stroke reaches)");
    }
    if (stroke.points.empty())
    {
      throw Error("stroke " + std::to_string(s) + " has no points");
    }
    for (std::size_t i = 0; i < stroke.points.size(); ++i)
    {
      if (!stroke.points[i].allFinite() || stroke.points[i].cwiseAbs().maxCoeff() > CoordinateLimit)
      {
        throw Error("point " + std::to_string(i) + " of stroke " + std::to_string(s) +
          " has a NaN, infinite or huge coordinate (beyond 1e50)");
      }
    }
    int previous = snap(stroke.points[0], s, 0, false);
    mark(previous, stroke.label);
    for (std::size_t i = 1; i < stroke.points.size(); ++i)
    {
      const Vector3& a = stroke.points[i - 1];
      const Vector3& b = stroke.points[i];
      const int end = snap(b, s, i, false);
      const double length = std::min((b - a).norm(), longest);
      const int samples = spacing > 0.0 ? static_cast<int>(std::ceil(length / spacing)) : 1;
      for (int k = 1; k < samples; ++k)
      {
        const int vertex = snap(a + (b - a) * (static_cast<double>(k) / samples), s, i, true);
        follow(previous, vertex, stroke.label);
        previous = vertex;
      }
      follow(previous, end, stroke.label);
      previous = end;
    }
  }
  return seeds;
}

void growFromSeeds(const TriangleMesh& mesh, const std::vector<double>& edgeLengths, const StrokeSeeds& seeds,
  std::vector<int>& labels, std::vector<double>& distances)
{
  if (static_cast<int>(edgeLengths.size()) != mesh.edgeCount())
  {
    throw Error("the edge lengths do not belong to this mesh");
  }
  const double infinity = std::numeric_limits<double>::infinity();
  labels.assign(static_cast<std::size_t>(mesh.vertexCount()), -1);
  distances.assign(static_cast<std::size_t>(mesh.vertexCount()), infinity);
  std::vector<DistanceEntry> heapStorage;
  heapStorage.reserve(static_cast<std::size_t>(mesh.vertexCount()));
  DistanceQueue queue(std::greater<DistanceEntry>(), std::move(heapStorage));
  for (std::size_t i = 0; i < seeds.vertices.size(); ++i)
  {
    const int v = seeds.vertices[i];
    if (v < 0 || v >= mesh.vertexCount())
    {
      throw Error("seed vertex " + std::to_string(v) + " is not a vertex of the mesh");
    }
    if (distances[v] != 0.0)
    {
      distances[v] = 0.0;
      labels[v] = seeds.labels[i];
      queue.emplace(0.0, v);
    }
  }
  searchShortestPaths(
    queue, [&](int v) -> double& { return distances[v]; },
    [&](int v, double d, const auto& lower) {
      const IndexRange neighbors = mesh.vertexNeighbors(v);
      const IndexRange edges = mesh.vertexEdges(v);
      for (std::size_t i = 0; i < neighbors.size(); ++i)
      {
        const int w = neighbors[i];
        if (lower(w, d + edgeLengths[static_cast<std::size_t>(edges[i])]))
        {
          labels[w] = labels[v];
        }
      }
    });
}

NearestLabels nearestTwoLabels(
  const TriangleMesh& mesh, const std::vector<double>& edgeLengths, const StrokeSeeds& seeds)
{
  if (static_cast<int>(edgeLengths.size()) != mesh.edgeCount())
  {
    throw Error("the edge lengths do not belong to this mesh");
  }
  const double infinity = std::numeric_limits<double>::infinity();
  const std::size_t n = static_cast<std::size_t>(mesh.vertexCount());
  NearestLabels nearest;
  const std::set<int> distinct(seeds.labels.begin(), seeds.labels.end());
  nearest.labels.assign(distinct.begin(), distinct.end());
  nearest.first.assign(n, -1);
  nearest.second.assign(n, -1);
  nearest.firstDistance.assign(n, infinity);
  nearest.secondDistance.assign(n, infinity);
  // Entries (distance, label index << 32 | vertex); an entry is current while it matches its
  // vertex's first or second label and distance.
  using Entry = std::pair<double, std::uint64_t>;
  std::vector<Entry> heapStorage;
  heapStorage.reserve(2 * n);
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue(
    std::greater<Entry>(), std::move(heapStorage));
  auto push = [&queue](double d, int v, int l) {
    queue.emplace(d, static_cast<std::uint64_t>(l) << 32 | static_cast<std::uint32_t>(v));
  };
  // Offers label l at distance d to vertex w; true when it enters w's two nearest.
  // The search keeps each vertex's two labels together, one cache line for the four numbers.
  struct Slot
  {
    double d1, d2;
    int first, second;
  };
  std::vector<Slot> slots(n, Slot{ infinity, infinity, -1, -1 });
  auto offer = [&slots](int w, int l, double d) {
    Slot& slot = slots[static_cast<std::size_t>(w)];
    int& first = slot.first;
    int& second = slot.second;
    double& d1 = slot.d1;
    double& d2 = slot.d2;
    if (l == first)
    {
      if (d < d1)
      {
        d1 = d;
        return true;
      }
      return false;
    }
    if (d < d1)
    {
      second = first; // the old first is second now, whatever the old second was
      d2 = d1;
      first = l;
      d1 = d;
      return true;
    }
    if (d < d2)
    {
      second = l;
      d2 = d;
      return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < seeds.vertices.size(); ++i)
  {
    const int v = seeds.vertices[i];
    if (v < 0 || v >= mesh.vertexCount())
    {
      throw Error("seed vertex " + std::to_string(v) + " is not a vertex of the mesh");
    }
    const int l = static_cast<int>(
      std::lower_bound(nearest.labels.begin(), nearest.labels.end(), seeds.labels[i]) - nearest.labels.begin());
    if (offer(v, l, 0.0))
    {
      push(0.0, v, l);
    }
  }
  while (!queue.empty())
  {
    const auto [d, key] = queue.top();
    queue.pop();
    const int v = static_cast<int>(key & 0xffffffffu);
    const int l = static_cast<int>(key >> 32);
    const Slot& slot = slots[static_cast<std::size_t>(v)];
    const bool current = (l == slot.first && d == slot.d1) || (l == slot.second && d == slot.d2);
    if (!current)
    {
      continue; // stale: v was reached by a shorter path, or l left its two nearest
    }
    const IndexRange neighbors = mesh.vertexNeighbors(v);
    const IndexRange edges = mesh.vertexEdges(v);
    for (std::size_t i = 0; i < neighbors.size(); ++i)
    {
      const double candidate = d + edgeLengths[static_cast<std::size_t>(edges[i])];
      if (offer(neighbors[i], l, candidate))
      {
        push(candidate, neighbors[i], l);
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    nearest.first[v] = slots[v].first;
    nearest.second[v] = slots[v].second;
    nearest.firstDistance[v] = slots[v].d1;
    nearest.secondDistance[v] = slots[v].d2;
  }
  return nearest;
}

void placeCuts(const TriangleMesh& mesh, const NearestLabels& nearest, const CutPlacementOptions& options,
  std::vector<int>& labels, std::vector<double>& distances)
{
  checkCutPlacementOptions(options);
  const double band = options.band;
  const int n = mesh.vertexCount();
  if (static_cast<int>(labels.size()) != n || static_cast<int>(distances.size()) != n ||
    static_cast<int>(nearest.first.size()) != n || static_cast<int>(nearest.second.size()) != n ||
    static_cast<int>(nearest.firstDistance.size()) != n || static_cast<int>(nearest.secondDistance.size()) != n)
  {
    throw Error("the labels, distances and nearest labels do not belong to this mesh");
  }
  // The freed vertices of each pair of labels (label indices, smaller first).
  std::map<std::pair<int, int>, std::vector<int>> freed;
  for (int v = 0; v < n; ++v)
  {
    const double d1 = nearest.firstDistance[v], d2 = nearest.secondDistance[v];
    if (nearest.second[v] >= 0 && d1 > band * d2)
    {
      const int a = nearest.first[v], b = nearest.second[v];
      freed[{ std::min(a, b), std::max(a, b) }].push_back(v);
    }
  }
  if (freed.empty())
  {
    return;
  }
  // Capacities: the dual edge's length over 1 + the dihedral term's share of its mean (Katz and
  // Tal 2003, section 4.2), so concave edges are cheap to cut. Computed where the cuts need them,
  // with only the means over the whole mesh, so that a narrow band costs little on a large mesh.
  auto centroidOf = [&mesh](int f) {
    const Triangle& t = mesh.triangle(f);
    return Vector3((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
  };
  auto normalOf = [&mesh](int f) {
    const Triangle& t = mesh.triangle(f);
    const Vector3 c = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0]));
    const double length = c.norm();
    return length > 0.0 && std::isfinite(length) ? Vector3(c / length) : Vector3(0.0, 0.0, 0.0);
  };
  auto dihedralOf = [&](int e) {
    if (mesh.edgeFaceCount(e) != 2)
    {
      return 0.0;
    }
    const auto& faces = mesh.edgeFaces(e);
    const Vector3 n1 = normalOf(faces[0]);
    const Vector3 n2 = normalOf(faces[1]);
    if (n1.squaredNorm() == 0.0 || n2.squaredNorm() == 0.0)
    {
      return 0.0; // a degenerate face has no normal: no bend to count
    }
    const bool concave = n1.dot(centroidOf(faces[1]) - centroidOf(faces[0])) > 0.0;
    return (concave ? 1.0 : options.convexWeight) * std::max(0.0, 1.0 - n1.dot(n2));
  };
  double dihedralSum = 0.0, areaSum = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    dihedralSum += dihedralOf(e);
  }
  auto areaOf = [&mesh](int f) {
    const Triangle& t = mesh.triangle(f);
    const double area = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm() / 2.0;
    return std::isfinite(area) ? area : 0.0;
  };
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    areaSum += areaOf(f);
  }
  const double dihedralMean = mesh.edgeCount() > 0 ? dihedralSum / mesh.edgeCount() : 0.0;
  const double meanLength = mesh.meanEdgeLength();
  const double lengthMean = meanLength > 0.0 ? meanLength : 1.0;
  // Areas: a third of each corner's faces, over their mean (the total area over the vertices).
  const double areaMean = n > 0 && areaSum > 0.0 ? areaSum / n : 1.0;
  auto capacityOf = [&](int e) {
    const auto [a, b] = mesh.edgeVertices(e);
    const Vector3 middle = (mesh.point(a) + mesh.point(b)) / 2.0;
    const auto& faces = mesh.edgeFaces(e);
    double dual = 0.0;
    for (int j = 0; j < std::min(mesh.edgeFaceCount(e), 2); ++j)
    {
      dual += (centroidOf(faces[j]) - middle).norm();
    }
    return dual / lengthMean / (dihedralMean > 0.0 ? 1.0 + dihedralOf(e) / dihedralMean : 1.0);
  };
  auto vertexArea = [&](int v) {
    double sum = 0.0;
    for (int f : mesh.vertexFaces(v))
    {
      sum += areaOf(f) / 3.0;
    }
    return sum / areaMean;
  };
  const double infinite = std::numeric_limits<double>::max() / 4.0;
  std::vector<int> node(static_cast<std::size_t>(n), -1);
  std::vector<char> isFreed(static_cast<std::size_t>(n), 0);
  // Pairs in label order; a vertex freed for another pair anchors this pair's cut with its label
  // at that moment (grown, or placed by an earlier pair's cut). Anchoring only on vertices outside
  // every band was measured: 0.1015 on the benchmark's one-stroke protocol against 0.0952.
  for (const auto& [pair, vertices] : freed)
  {
    const int labelA = nearest.labels[pair.first], labelB = nearest.labels[pair.second];
    std::vector<int> nodes = vertices;
    std::vector<double> sourceCapacity, sinkCapacity;
    std::vector<std::array<int, 2>> edges;
    std::vector<double> edgeCapacity;
    bool anySource = false, anySink = false;
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
      const int v = vertices[i];
      node[v] = static_cast<int>(i);
      isFreed[v] = 1;
      // The data term: what giving v the farther label costs, its distances' relative difference.
      const double da = nearest.first[v] == pair.first ? nearest.firstDistance[v] : nearest.secondDistance[v];
      const double db = nearest.first[v] == pair.first ? nearest.secondDistance[v] : nearest.firstDistance[v];
      const double cost = options.dataWeight * vertexArea(v) * std::abs(da - db) / (da + db);
      sourceCapacity.push_back(da < db ? cost : 0.0);
      sinkCapacity.push_back(da < db ? 0.0 : cost);
    }
    for (int v : vertices)
    {
      const IndexRange neighbors = mesh.vertexNeighbors(v);
      const IndexRange vertexEdges = mesh.vertexEdges(v);
      for (std::size_t j = 0; j < neighbors.size(); ++j)
      {
        const int w = neighbors[j];
        if (isFreed[w] && w < v)
        {
          continue; // the edge is added from its smaller end
        }
        if (!isFreed[w])
        {
          if (labels[w] != labelA && labels[w] != labelB)
          {
            continue; // a third label's vertex: no terminal for this pair
          }
          if (node[w] < 0)
          {
            node[w] = static_cast<int>(nodes.size());
            nodes.push_back(w);
            const bool isA = labels[w] == labelA;
            sourceCapacity.push_back(isA ? infinite : 0.0);
            sinkCapacity.push_back(isA ? 0.0 : infinite);
            anySource = anySource || isA;
            anySink = anySink || !isA;
          }
        }
        edges.push_back({ node[v], node[w] });
        edgeCapacity.push_back(capacityOf(vertexEdges[j]));
      }
    }
    if (anySource && anySink)
    {
      const MinimumCut cut =
        minimumCut(static_cast<int>(nodes.size()), edges, edgeCapacity, sourceCapacity, sinkCapacity);
      for (std::size_t i = 0; i < vertices.size(); ++i)
      {
        const int v = vertices[i];
        const int chosen = cut.sourceSide[i] ? pair.first : pair.second;
        labels[v] = nearest.labels[chosen];
        distances[v] = chosen == nearest.first[v] ? nearest.firstDistance[v] : nearest.secondDistance[v];
      }
    }
    for (int v : nodes)
    {
      node[v] = -1;
      isFreed[v] = 0;
    }
  }
}

std::vector<int> faceLabelsFromVertices(
  const TriangleMesh& mesh, const std::vector<int>& vertexLabels, const std::vector<double>& distances)
{
  std::vector<int> faceLabels(static_cast<std::size_t>(mesh.faceCount()), -1);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const int a = vertexLabels[t[0]], b = vertexLabels[t[1]], c = vertexLabels[t[2]];
    int label = a;
    if (b == c)
    {
      label = b;
    }
    else if (a != b && a != c)
    {
      // Three labels: the corner nearest to its stroke (the most certain) decides.
      int best = 0;
      for (int k = 1; k < 3; ++k)
      {
        const double dk = distances[t[k]], db = distances[t[best]];
        if (dk < db || (dk == db && vertexLabels[t[k]] < vertexLabels[t[best]]))
        {
          best = k;
        }
      }
      label = vertexLabels[t[best]];
    }
    faceLabels[static_cast<std::size_t>(f)] = label;
  }
  return faceLabels;
}

namespace
{
// The walks' boundaries moved by a minimum cut through the band where each vertex's two most
// probable labels are close: kerf::placeCuts with 1 - p as the distance to a label. A vertex the
// cut gives its second label trades the two labels (the cut's label takes the larger probability,
// as the label the vertex is most sure of), and every face around it takes again the label whose
// corner probabilities (the corners' two labels) sum highest, ties to the smaller label, unless
// that would leave it an island (below); the other faces keep the walks' labels.
void placeCutsOnWalks(const TriangleMesh& mesh, const CutPlacementOptions& options, RandomWalkLabelling& walks)
{
  const int n = mesh.vertexCount();
  const auto indexOf = [&walks](int label) {
    return static_cast<int>(std::lower_bound(walks.labels.begin(), walks.labels.end(), label) - walks.labels.begin());
  };
  NearestLabels band;
  band.labels = walks.labels;
  band.first.assign(static_cast<std::size_t>(n), -1);
  band.second.assign(static_cast<std::size_t>(n), -1);
  band.firstDistance.assign(static_cast<std::size_t>(n), 1.0);
  band.secondDistance.assign(static_cast<std::size_t>(n), 1.0);
  for (int v = 0; v < n; ++v)
  {
    if (walks.vertexLabels[v] >= 0)
    {
      band.first[v] = indexOf(walks.vertexLabels[v]);
      band.firstDistance[v] = 1.0 - walks.vertexProbabilities[v];
      if (walks.secondLabels[v] >= 0)
      {
        band.second[v] = indexOf(walks.secondLabels[v]);
        band.secondDistance[v] = 1.0 - walks.secondProbabilities[v];
      }
    }
  }
  std::vector<int> labels = walks.vertexLabels;
  std::vector<double> distances = band.firstDistance;
  placeCuts(mesh, band, options, labels, distances);
  // The faces around moved vertices, ascending.
  std::vector<int> relabelled;
  for (int v = 0; v < n; ++v)
  {
    if (labels[v] != walks.vertexLabels[v])
    {
      std::swap(walks.vertexLabels[v], walks.secondLabels[v]);
      for (const int f : mesh.vertexFaces(v))
      {
        relabelled.push_back(f);
      }
    }
  }
  if (relabelled.empty())
  {
    return;
  }
  std::sort(relabelled.begin(), relabelled.end());
  relabelled.erase(std::unique(relabelled.begin(), relabelled.end()), relabelled.end());
  for (const int f : relabelled)
  {
    const Triangle& t = mesh.triangle(f);
    std::array<std::pair<int, double>, 6> sums{};
    int used = 0;
    const auto add = [&](int label, double p) {
      if (label < 0)
      {
        return;
      }
      int i = 0;
      while (i < used && sums[i].first != label)
      {
        ++i;
      }
      if (i == used)
      {
        sums[used++] = { label, 0.0 };
      }
      sums[i].second += p;
    };
    for (const int v : t)
    {
      add(walks.vertexLabels[v], walks.vertexProbabilities[v]);
      add(walks.secondLabels[v], walks.secondProbabilities[v]);
    }
    int best = 0;
    for (int i = 1; i < used; ++i)
    {
      if (sums[i].second > sums[best].second ||
        (sums[i].second == sums[best].second && sums[i].first < sums[best].first))
      {
        best = i;
      }
    }
    walks.faceLabels[f] = sums[best].first;
  }
  // A relabelled face none of whose neighbours shares its label would be an island joined to its
  // part by a corner: it takes its neighbours' most common label (ties to the smaller), unless it
  // is its label's only face (a click's part is never removed).
  const std::vector<int> faceLabels = walks.faceLabels;
  std::map<int, int> faceCount;
  for (const int label : faceLabels)
  {
    ++faceCount[label];
  }
  for (const int f : relabelled)
  {
    std::array<int, 3> around{ -1, -1, -1 };
    bool alone = true;
    for (int k = 0; k < 3; ++k)
    {
      const int g = mesh.faceNeighbor(f, k);
      around[k] = g >= 0 ? faceLabels[g] : -1;
      alone = alone && around[k] != faceLabels[f];
    }
    std::sort(around.begin(), around.end());
    if (!alone || around[2] < 0 || faceCount[faceLabels[f]] == 1)
    {
      continue;
    }
    // Sorted, absent neighbours (-1) first: a label held twice sits in two adjacent places;
    // otherwise the smallest label present.
    int label = around[1] >= 0 && around[1] == around[2] ? around[1]
                                                         : (around[0] >= 0 && around[0] == around[1] ? around[0] : -1);
    if (label < 0)
    {
      label = around[0] >= 0 ? around[0] : (around[1] >= 0 ? around[1] : around[2]);
    }
    walks.faceLabels[f] = label;
  }
}
} // namespace

RegionGrowingResult growRegions(
  const Surface& surface, const std::vector<LabelledStroke>& strokes, const RegionGrowingOptions& options)
{
  checkIsophoticMetricOptions(options.metric);
  if (!(options.maximumDistance >= 0.0))
  {
    throw Error("the maximum distance of stroke points must be a non-negative number");
  }
  checkCutPlacementOptions(options.cutPlacement);
  if (options.placement != BoundaryPlacement::Fronts && options.placement != BoundaryPlacement::MinimumCut &&
    options.placement != BoundaryPlacement::RandomWalks)
  {
    throw Error("unknown boundary placement " + std::to_string(static_cast<int>(options.placement)));
  }
  const TriangleMesh& mesh = surface.mesh();
  RegionGrowingResult result;
  result.seeds = snapStrokes(mesh, surface.locator(), strokes, options.maximumDistance);
  std::set<int> labels(result.seeds.labels.begin(), result.seeds.labels.end());
  result.labels.assign(labels.begin(), labels.end());
  if (result.labels.size() < 2)
  {
    throw Error("every stroke has the label " + std::to_string(result.labels.front()) +
      "; region growing needs strokes of at least two labels");
  }
  const std::vector<double>& edgeLengths = surfaceIsophoticEdgeLengths(surface, options.metric);
  if (options.placement == BoundaryPlacement::MinimumCut && options.cutPlacement.band > 0.0)
  {
    // The nearest label of the two-label search is the growing's (up to which of two labels at
    // exactly equal distance reached a vertex first).
    const NearestLabels nearest = nearestTwoLabels(mesh, edgeLengths, result.seeds);
    result.vertexLabels.assign(static_cast<std::size_t>(mesh.vertexCount()), -1);
    result.distances = nearest.firstDistance;
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      result.vertexLabels[v] = nearest.first[v] >= 0 ? nearest.labels[nearest.first[v]] : -1;
    }
    placeCuts(mesh, nearest, options.cutPlacement, result.vertexLabels, result.distances);
  }
  else
  {
    growFromSeeds(mesh, edgeLengths, result.seeds, result.vertexLabels, result.distances);
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (result.vertexLabels[v] < 0)
    {
      result.distances[v] = -1.0;
      result.unreachableVertices += mesh.vertexComponent(v) >= 0 ? 1 : 0;
    }
  }
  if (options.placement == BoundaryPlacement::RandomWalks)
  {
    // The walks reach exactly the components the fronts do (those with a stroke).
    RandomWalkLabelling walks = randomWalkLabels(
      mesh, surface.laplacianWeights(options.walkWeights).weights, result.seeds.vertices, result.seeds.labels);
    if (options.cutPlacement.band > 0.0)
    {
      placeCutsOnWalks(mesh, options.cutPlacement, walks);
    }
    result.vertexLabels = std::move(walks.vertexLabels);
    result.probabilities = std::move(walks.vertexProbabilities);
    result.faceLabels = std::move(walks.faceLabels);
    return result;
  }
  result.faceLabels = faceLabelsFromVertices(mesh, result.vertexLabels, result.distances);
  return result;
}

std::vector<LabelBoundary> labelBoundaries(const TriangleMesh& mesh, const std::vector<int>& faceLabels)
{
  if (static_cast<int>(faceLabels.size()) != mesh.faceCount())
  {
    throw Error("the face labels do not belong to this mesh");
  }
  // Boundary edges: two faces with different labels.
  std::vector<char> isBoundary(static_cast<std::size_t>(mesh.edgeCount()), 0);
  std::vector<int> degree(static_cast<std::size_t>(mesh.vertexCount()), 0);
  auto pairOf = [&](int e) {
    const auto& faces = mesh.edgeFaces(e);
    const int a = faceLabels[faces[0]], b = faceLabels[faces[1]];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const auto& faces = mesh.edgeFaces(e);
    if (mesh.edgeFaceCount(e) == 2 && faceLabels[faces[0]] != faceLabels[faces[1]])
    {
      isBoundary[e] = 1;
      for (int v : mesh.edgeVertices(e))
      {
        ++degree[v];
      }
    }
  }
  // Chain ends: vertices with other than two boundary edges, or two of different label pairs.
  std::vector<char> isEnd(static_cast<std::size_t>(mesh.vertexCount()), 0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (degree[v] == 0)
    {
      continue;
    }
    if (degree[v] != 2)
    {
      isEnd[v] = 1;
      continue;
    }
    std::vector<std::pair<int, int>> pairs;
    for (int e : mesh.vertexEdges(v))
    {
      if (isBoundary[e])
      {
        pairs.push_back(pairOf(e));
      }
    }
    isEnd[v] = pairs[0] != pairs[1] ? 1 : 0;
  }
  std::vector<char> used(static_cast<std::size_t>(mesh.edgeCount()), 0);
  std::vector<LabelBoundary> boundaries;
  // Walks from vertex `start` along boundary edge `first` until an end (or back to the start).
  auto walk = [&](int start, int first) {
    LabelBoundary chain;
    chain.vertices.push_back(start);
    int v = start, e = first;
    while (true)
    {
      used[e] = 1;
      const auto& ev = mesh.edgeVertices(e);
      const int w = ev[0] == v ? ev[1] : ev[0];
      if (w == start)
      {
        chain.closed = true;
        break;
      }
      chain.vertices.push_back(w);
      if (isEnd[w])
      {
        break;
      }
      v = w;
      e = -1;
      for (int next : mesh.vertexEdges(v))
      {
        if (isBoundary[next] && !used[next])
        {
          e = next;
          break;
        }
      }
      if (e < 0)
      {
        break;
      }
    }
    // Orientation: the face in which the first edge runs from vertices[0] to vertices[1] is on the left.
    const int a = chain.vertices[0], b = chain.vertices[1];
    const auto& faces = mesh.edgeFaces(first);
    int leftFace = faces[0];
    const Triangle& t = mesh.triangle(faces[0]);
    bool forward = false;
    for (int k = 0; k < 3; ++k)
    {
      forward = forward || (t[k] == a && t[(k + 1) % 3] == b);
    }
    if (!forward)
    {
      leftFace = faces[1];
    }
    const int rightFace = leftFace == faces[0] ? faces[1] : faces[0];
    chain.leftLabel = faceLabels[leftFace];
    chain.rightLabel = faceLabels[rightFace];
    if (chain.leftLabel > chain.rightLabel)
    {
      std::swap(chain.leftLabel, chain.rightLabel);
      std::reverse(chain.vertices.begin(), chain.vertices.end());
      if (chain.closed)
      {
        // Keep the smallest vertex first, as the walk started there.
        std::rotate(chain.vertices.begin(), chain.vertices.end() - 1, chain.vertices.end());
      }
    }
    boundaries.push_back(std::move(chain));
  };
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!isEnd[v])
    {
      continue;
    }
    for (int e : mesh.vertexEdges(v))
    {
      if (isBoundary[e] && !used[e])
      {
        walk(v, e);
      }
    }
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    for (int e : mesh.vertexEdges(v))
    {
      if (isBoundary[e] && !used[e])
      {
        walk(v, e);
      }
    }
  }
  return boundaries;
}

} // namespace kerf
