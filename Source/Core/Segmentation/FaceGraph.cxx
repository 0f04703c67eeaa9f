// The dual graph, dual-graph Dijkstra, and the region merging and clean-up every segmentation method shares.
#include "Segmentation/FaceGraph.h"

#include "Error.h"
#include "Mesh/ShortestPaths.h"
#include "Mesh/UnionFind.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace kerf
{

FaceGraph::FaceGraph(const TriangleMesh& mesh)
  : Mesh(&mesh)
{
  const int faces = mesh.faceCount();
  this->Areas.resize(faces);
  this->Perimeters.resize(faces);
  this->Normals.resize(faces);
  this->Centroids.resize(faces);
  this->FaceDualEdges.assign(faces, { { -1, -1, -1 } });
  this->FaceNeighbours.assign(faces, { { -1, -1, -1 } });
  for (int f = 0; f < faces; ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const Vector3 &a = mesh.point(t[0]), &b = mesh.point(t[1]), &c = mesh.point(t[2]);
    const Vector3 cross = (b - a).cross(c - a);
    const double norm = cross.norm();
    this->Areas[f] = 0.5 * norm;
    this->Normals[f] = norm > 0.0 && std::isfinite(norm) ? Vector3(cross / norm) : Vector3::Zero();
    this->Centroids[f] = (a + b + c) / 3.0;
    this->Perimeters[f] = (b - a).norm() + (c - b).norm() + (a - c).norm();
    this->TotalArea += this->Areas[f];
  }
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (mesh.edgeFaceCount(e) != 2)
    {
      continue;
    }
    DualEdge dual;
    dual.faces = mesh.edgeFaces(e);
    if (dual.faces[0] > dual.faces[1])
    {
      std::swap(dual.faces[0], dual.faces[1]);
    }
    dual.meshEdge = e;
    const Vector3& p = mesh.point(mesh.edgeVertices(e)[0]);
    const Vector3& q = mesh.point(mesh.edgeVertices(e)[1]);
    dual.length = (q - p).norm();
    const Vector3 middle = 0.5 * (p + q);
    const int fa = dual.faces[0], fb = dual.faces[1];
    dual.centroidPath = (this->Centroids[fa] - middle).norm() + (this->Centroids[fb] - middle).norm();
    const Vector3 &na = this->Normals[fa], &nb = this->Normals[fb];
    if (na.squaredNorm() > 0.0 && nb.squaredNorm() > 0.0)
    {
      dual.normalCosine = std::clamp(na.dot(nb), -1.0, 1.0);
      const double angle = std::atan2(na.cross(nb).norm(), na.dot(nb));
      // Convex where each face's neighbour lies below its plane (both terms negative).
      const double side =
        (this->Centroids[fb] - this->Centroids[fa]).dot(na) + (this->Centroids[fa] - this->Centroids[fb]).dot(nb);
      dual.bend = side > 0.0 ? -angle : angle;
    }
    const int index = static_cast<int>(this->Edges.size());
    for (int f : { fa, fb })
    {
      for (int s = 0; s < 3; ++s)
      {
        if (this->FaceDualEdges[f][s] < 0)
        {
          this->FaceDualEdges[f][s] = index;
          this->FaceNeighbours[f][s] = f == fa ? fb : fa;
          break;
        }
      }
    }
    this->Edges.push_back(dual);
  }
  // Components by breadth-first search, numbered by first face.
  this->Components.assign(faces, -1);
  std::vector<int> queue;
  for (int start = 0; start < faces; ++start)
  {
    if (this->Components[start] >= 0)
    {
      continue;
    }
    this->Components[start] = this->ComponentCount;
    queue.assign(1, start);
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      for (int e : this->FaceDualEdges[queue[i]])
      {
        if (e >= 0)
        {
          const int g = this->opposite(e, queue[i]);
          if (this->Components[g] < 0)
          {
            this->Components[g] = this->ComponentCount;
            queue.push_back(g);
          }
        }
      }
    }
    ++this->ComponentCount;
  }
}

const FaceGraph& faceGraph(const Surface& surface)
{
  return surface.derived<FaceGraph>("face-graph", [&surface]() { return FaceGraph(surface.mesh()); });
}

void checkSegmentCount(int k, int faceCount)
{
  if (k < 1)
  {
    throw Error("the number of segments must be at least 1, got " + std::to_string(k));
  }
  if (k > faceCount)
  {
    throw Error("cannot make " + std::to_string(k) + " segments from " + std::to_string(faceCount) + " faces");
  }
}

DualDistances dualDijkstra(
  const FaceGraph& graph, const std::vector<double>& edgeLengths, const std::vector<int>& sources, double limit)
{
  DualDistances result;
  result.distance.assign(graph.faceCount(), std::numeric_limits<double>::infinity());
  result.nearest.assign(graph.faceCount(), -1);
  DistanceQueue heap;
  for (std::size_t s = 0; s < sources.size(); ++s)
  {
    const int f = sources[s];
    if (result.distance[f] > 0.0)
    {
      result.distance[f] = 0.0;
      result.nearest[f] = static_cast<int>(s);
      heap.emplace(0.0, f);
    }
  }
  // A face reached at an equal distance from two sources goes to the smaller source, without
  // being queued again.
  searchShortestPaths(
    heap, [&](int f) -> double& { return result.distance[f]; },
    [&](int f, double d, const auto& lower) {
      const std::array<int, 3>& edges = graph.faceEdges(f);
      const std::array<int, 3>& neighbours = graph.faceNeighbours(f);
      for (int s = 0; s < 3; ++s)
      {
        const int g = neighbours[s];
        if (g < 0)
        {
          continue;
        }
        const double candidate = d + edgeLengths[edges[s]];
        if (candidate > limit)
        {
          continue;
        }
        if (lower(g, candidate) || (candidate == result.distance[g] && result.nearest[f] < result.nearest[g]))
        {
          result.nearest[g] = result.nearest[f];
        }
      }
    });
  return result;
}

std::vector<int> numberByFirstFace(const std::vector<int>& labels)
{
  std::vector<int> renumbered(labels.size());
  std::vector<int> map;
  int next = 0;
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    const int label = labels[f];
    if (label >= static_cast<int>(map.size()))
    {
      map.resize(static_cast<std::size_t>(label) + 1, -1);
    }
    if (map[label] < 0)
    {
      map[label] = next++;
    }
    renumbered[f] = map[label];
  }
  return renumbered;
}

std::vector<int> splitIntoConnectedSegments(const FaceGraph& graph, const std::vector<int>& labels)
{
  std::vector<int> result(labels.size(), -1);
  std::vector<int> queue;
  int next = 0;
  for (int start = 0; start < graph.faceCount(); ++start)
  {
    if (result[start] >= 0)
    {
      continue;
    }
    result[start] = next;
    queue.assign(1, start);
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      for (int e : graph.faceEdges(queue[i]))
      {
        if (e >= 0)
        {
          const int g = graph.opposite(e, queue[i]);
          if (result[g] < 0 && labels[g] == labels[start])
          {
            result[g] = next;
            queue.push_back(g);
          }
        }
      }
    }
    ++next;
  }
  return result;
}

RegionAdjacency::RegionAdjacency(
  const FaceGraph& graph, const std::vector<int>& labels, const std::vector<double>* edgeHeight)
  : FaceRegion(labels)
{
  const int count = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  this->Areas.assign(count, 0.0);
  this->Neighbours.resize(count);
  this->Parent.resize(count);
  std::iota(this->Parent.begin(), this->Parent.end(), 0);
  this->Live = count;
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    this->Areas[labels[f]] += graph.area(f);
  }
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const int a = labels[graph.edge(e).faces[0]], b = labels[graph.edge(e).faces[1]];
    if (a == b)
    {
      continue;
    }
    const double height = edgeHeight ? (*edgeHeight)[e] : 0.0;
    for (const auto& [from, to] : { std::pair<int, int>{ a, b }, std::pair<int, int>{ b, a } })
    {
      auto& list = this->Neighbours[from];
      auto found = std::find_if(list.begin(), list.end(), [to = to](const auto& n) { return n.first == to; });
      if (found == list.end())
      {
        list.push_back({ to, Boundary{ 0.0, height } });
        found = list.end() - 1;
      }
      found->second.length += graph.edge(e).length;
      found->second.lowestHeight = std::min(found->second.lowestHeight, height);
    }
  }
  for (auto& list : this->Neighbours)
  {
    std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  }
}

int RegionAdjacency::find(int r) const
{
  return findRoot(this->Parent, r);
}

void RegionAdjacency::merge(int from, int into)
{
  if (from == into || !this->alive(from) || !this->alive(into))
  {
    throw Error("internal: merging regions that are not two live regions");
  }
  this->Parent[from] = into;
  this->Areas[into] += this->Areas[from];
  --this->Live;
  // Combine the two sorted neighbour lists, dropping the pair itself.
  std::vector<std::pair<int, Boundary>> combined;
  const auto& x = this->Neighbours[into];
  const auto& y = this->Neighbours[from];
  std::size_t i = 0, j = 0;
  while (i < x.size() || j < y.size())
  {
    std::pair<int, Boundary> next;
    if (j == y.size() || (i < x.size() && x[i].first < y[j].first))
    {
      next = x[i++];
    }
    else if (i == x.size() || y[j].first < x[i].first)
    {
      next = y[j++];
    }
    else
    {
      next = x[i++];
      next.second.length += y[j].second.length;
      next.second.lowestHeight = std::min(next.second.lowestHeight, y[j].second.lowestHeight);
      ++j;
    }
    if (next.first != into && next.first != from)
    {
      combined.push_back(next);
    }
  }
  this->Neighbours[into] = std::move(combined);
  this->Neighbours[from].clear();
  // The neighbours now see `into` where they saw `from`.
  for (const auto& [n, boundary] : this->Neighbours[into])
  {
    auto& list = this->Neighbours[n];
    auto old = std::find_if(list.begin(), list.end(), [from](const auto& p) { return p.first == from; });
    auto kept = std::find_if(list.begin(), list.end(), [into](const auto& p) { return p.first == into; });
    if (old != list.end())
    {
      list.erase(old);
    }
    kept = std::find_if(list.begin(), list.end(), [into](const auto& p) { return p.first == into; });
    if (kept != list.end())
    {
      kept->second = boundary;
    }
    else
    {
      list.insert(
        std::lower_bound(list.begin(), list.end(), into, [](const auto& p, int value) { return p.first < value; }),
        { into, boundary });
    }
  }
}

std::vector<int> RegionAdjacency::labels() const
{
  std::vector<int> result(this->FaceRegion.size());
  for (std::size_t f = 0; f < result.size(); ++f)
  {
    result[f] = this->find(this->FaceRegion[f]);
  }
  return numberByFirstFace(result);
}

int RegionAdjacency::longestBoundaryNeighbour(int r) const
{
  int best = -1;
  double longest = -1.0;
  for (const auto& [n, boundary] : this->Neighbours[r])
  {
    if (boundary.length > longest)
    {
      longest = boundary.length;
      best = n;
    }
  }
  return best;
}

int RegionAdjacency::largestNeighbour(int r) const
{
  int best = -1;
  double largest = -1.0;
  for (const auto& neighbour : this->Neighbours[r])
  {
    if (this->Areas[neighbour.first] > largest)
    {
      largest = this->Areas[neighbour.first];
      best = neighbour.first;
    }
  }
  return best;
}

namespace
{
// Live regions by increasing area (ties by index), re-checked as they come off the heap.
template <typename Stop>
void mergeSmallestFirst(
  RegionAdjacency& regions, const Stop& stop, const std::function<int(const RegionAdjacency&, int)>& chooser)
{
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (int r = 0; r < regions.regionCount(); ++r)
  {
    if (regions.alive(r))
    {
      heap.emplace(regions.area(r), r);
    }
  }
  while (!heap.empty())
  {
    const auto [area, r] = heap.top();
    heap.pop();
    if (!regions.alive(r) || area != regions.area(r))
    {
      continue;
    }
    if (stop(regions, r))
    {
      return;
    }
    const int into = chooser(regions, r);
    if (into < 0)
    {
      continue;
    }
    regions.merge(r, into);
    heap.emplace(regions.area(into), into);
  }
}
} // namespace

void mergeSmallRegions(
  RegionAdjacency& regions, double minimumArea, const std::function<int(const RegionAdjacency&, int)>& chooser)
{
  mergeSmallestFirst(
    regions, [minimumArea](const RegionAdjacency& r, int smallest) { return r.area(smallest) >= minimumArea; },
    chooser);
}

void mergeSmallestUntil(
  RegionAdjacency& regions, int count, const std::function<int(const RegionAdjacency&, int)>& chooser)
{
  mergeSmallestFirst(
    regions, [count](const RegionAdjacency& r, int) { return r.liveCount() <= count; },
    chooser ? chooser : [](const RegionAdjacency& r, int region) { return r.longestBoundaryNeighbour(region); });
}

std::vector<int> finalizeSegments(const FaceGraph& graph, const std::vector<int>& labels, int k)
{
  if (static_cast<int>(labels.size()) != graph.faceCount())
  {
    throw Error("internal: a label per face is needed");
  }
  RegionAdjacency regions(graph, splitIntoConnectedSegments(graph, labels));
  mergeSmallestUntil(regions, k);
  return regions.labels();
}

std::vector<int> segmentsPerComponent(const FaceGraph& graph, int k)
{
  const int components = graph.componentCount();
  std::vector<double> area(components, 0.0);
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    area[graph.component(f)] += graph.area(f);
  }
  std::vector<int> share(components, 1);
  std::vector<int> faces(components, 0);
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    ++faces[graph.component(f)];
  }
  int left = k - components;
  const double total = std::max(graph.totalArea(), std::numeric_limits<double>::min());
  std::vector<double> remainder(components, 0.0);
  for (int c = 0; c < components && left > 0; ++c)
  {
    const double ideal = left * area[c] / total;
    const int whole = std::min(static_cast<int>(std::floor(ideal)), faces[c] - share[c]);
    share[c] += whole;
    remainder[c] = ideal - whole;
  }
  left = k - std::accumulate(share.begin(), share.end(), 0);
  while (left > 0)
  {
    int best = -1;
    for (int c = 0; c < components; ++c)
    {
      if (share[c] < faces[c] && (best < 0 || remainder[c] > remainder[best]))
      {
        best = c;
      }
    }
    if (best < 0)
    {
      break;
    }
    ++share[best];
    remainder[best] = -1.0;
    --left;
  }
  return share;
}

namespace
{
// Each component as a mesh of its own, segmented by `segmentComponent` with its share (one
// segment, without the call, where the share is 1), the labels joined and numbered by first face.
std::vector<int> segmentComponentsWithShares(const FaceGraph& graph, const std::vector<int>& shares,
  const std::function<std::vector<int>(const TriangleMesh&, int)>& segmentComponent)
{
  const TriangleMesh& mesh = graph.mesh();
  std::vector<int> labels(graph.faceCount(), 0);
  int offset = 0;
  for (int c = 0; c < graph.componentCount(); ++c)
  {
    std::vector<int> faces;
    std::vector<int> vertexMap(mesh.vertexCount(), -1);
    std::vector<Vector3> points;
    std::vector<Triangle> triangles;
    for (int f = 0; f < graph.faceCount(); ++f)
    {
      if (graph.component(f) != c)
      {
        continue;
      }
      faces.push_back(f);
      Triangle t = mesh.triangle(f);
      for (int& v : t)
      {
        if (vertexMap[v] < 0)
        {
          vertexMap[v] = static_cast<int>(points.size());
          points.push_back(mesh.point(v));
        }
        v = vertexMap[v];
      }
      triangles.push_back(t);
    }
    const TriangleMesh part(std::move(points), std::move(triangles));
    const std::vector<int> partLabels =
      shares[c] == 1 ? std::vector<int>(faces.size(), 0) : segmentComponent(part, shares[c]);
    int largest = 0;
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
      labels[faces[i]] = offset + partLabels[i];
      largest = std::max(largest, partLabels[i]);
    }
    offset += largest + 1;
  }
  return numberByFirstFace(labels);
}

// A Surface for each component's mesh (a connected surface is handed over itself).
std::vector<int> segmentSurfaceComponentsWithShares(const Surface& surface, const std::vector<int>& shares,
  const std::function<std::vector<int>(const Surface&, int)>& segmentComponent)
{
  const FaceGraph& graph = faceGraph(surface);
  if (graph.componentCount() == 1)
  {
    return segmentComponent(surface, shares[0]);
  }
  return segmentComponentsWithShares(graph, shares, [&segmentComponent](const TriangleMesh& part, int partK) {
    const Surface partSurface(part);
    return segmentComponent(partSurface, partK);
  });
}

// How many of k segments each component gets (segmentsPerComponent; one each when k is smaller
// than the number of components).
std::vector<int> sharesOf(const FaceGraph& graph, int k)
{
  return graph.componentCount() == 1 ? std::vector<int>{ k }
    : k >= graph.componentCount()    ? segmentsPerComponent(graph, k)
                                     : std::vector<int>(graph.componentCount(), 1);
}
} // namespace

std::vector<int> segmentComponents(
  const FaceGraph& graph, int k, const std::function<std::vector<int>(const TriangleMesh&, int)>& segmentComponent)
{
  if (graph.componentCount() == 1)
  {
    return segmentComponent(graph.mesh(), k);
  }
  return segmentComponentsWithShares(graph, sharesOf(graph, k), segmentComponent);
}

std::vector<int> segmentSurfaceComponents(
  const Surface& surface, int k, const std::function<std::vector<int>(const Surface&, int)>& segmentComponent)
{
  return segmentSurfaceComponentsWithShares(surface, sharesOf(faceGraph(surface), k), segmentComponent);
}

std::vector<int> segmentEachSurfaceComponent(
  const Surface& surface, const std::function<std::vector<int>(const Surface&)>& segmentComponent)
{
  // Each component's share is its face count, so only a single face is not handed over.
  const FaceGraph& graph = faceGraph(surface);
  std::vector<int> faces(graph.componentCount(), 0);
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    ++faces[graph.component(f)];
  }
  return segmentSurfaceComponentsWithShares(
    surface, faces, [&segmentComponent](const Surface& part, int) { return segmentComponent(part); });
}

} // namespace kerf
