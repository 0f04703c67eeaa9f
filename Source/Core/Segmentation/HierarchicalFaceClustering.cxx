// Hierarchical face clustering (Garland et al. 2001): quadrics, the contraction heap, and cuts of the merge tree.
#include "Segmentation/HierarchicalFaceClustering.h"

#include "Error.h"
#include "Session/Surface.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

namespace kerf
{

std::string cacheKey(const HierarchicalClusteringOptions& options)
{
  return "a1=" + cacheKey(options.directionWeight) + " a2=" + cacheKey(options.shapeWeight);
}

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A cluster's quadrics and shape (Garland et al. 2001, section 3): fit P = (A, b, c), direction
// R = (D, e, f) weighted by area, area and perimeter.
struct ClusterState
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Vector3 b = Vector3::Zero();
  double c = 0.0;
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  Vector3 e = Vector3::Zero();
  double f = 0.0;
  double area = 0.0;
  double perimeter = 0.0;

  void add(const ClusterState& o)
  {
    A += o.A;
    b += o.b;
    c += o.c;
    D += o.D;
    e += o.e;
    f += o.f;
    area += o.area;
  }
};

double irregularity(double perimeter, double area)
{
  return area > 0.0 ? perimeter * perimeter / (4.0 * Pi * area) : 1.0;
}

// E = E_fit + a1 E_dir + a2 E_shape of joining x and y, which share a boundary of length `shared`.
double contractionCost(const ClusterState& x, const ClusterState& y, double shared,
  const HierarchicalClusteringOptions& options)
{
  ClusterState sum = x;
  sum.add(y);
  // Best plane: the eigenvector of Z = A - b b^T / c with the smallest eigenvalue (section 3.1).
  const Eigen::Matrix3d Z = sum.A - sum.b * sum.b.transpose() / sum.c;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(Z);
  Vector3 n = eigen.eigenvectors().col(0);
  const double fit = std::max(0.0, eigen.eigenvalues()(0)) / sum.c;
  // The plane's normal faces the way the cluster's faces do (e = -sum w_i n_i).
  if (n.dot(sum.e) > 0.0)
  {
    n = -n;
  }
  double direction = 0.0;
  if (sum.f > 0.0)
  {
    direction = std::max(0.0, (n.dot(sum.D * n) + 2.0 * sum.e.dot(n) + sum.f) / sum.f);
  }
  // E_shape = (gamma - max(gamma_1, gamma_2)) / gamma, gamma = p^2 / (4 pi w) (section 3.2).
  const double gamma = irregularity(x.perimeter + y.perimeter - 2.0 * shared, sum.area);
  const double shape =
    gamma > 0.0 ? (gamma - std::max(irregularity(x.perimeter, x.area), irregularity(y.perimeter, y.area))) / gamma : 0.0;
  return fit + options.directionWeight * direction + options.shapeWeight * shape;
}

struct HeapEntry
{
  double cost;
  int x, y;          // cluster slots, x < y
  unsigned vx, vy;   // their versions when the cost was computed
  bool operator>(const HeapEntry& o) const
  {
    return cost != o.cost ? cost > o.cost : (x != o.x ? x > o.x : y > o.y);
  }
};

// Union-find labels after the first `count` merges, numbered by first face.
std::vector<int> applyMerges(const FaceClusterHierarchy& hierarchy, std::size_t count)
{
  const int n = hierarchy.faceCount;
  std::vector<int> parent(static_cast<std::size_t>(n) + count);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int a) {
    while (parent[a] != a)
    {
      parent[a] = parent[parent[a]];
      a = parent[a];
    }
    return a;
  };
  for (std::size_t i = 0; i < count; ++i)
  {
    const int node = n + static_cast<int>(i);
    parent[find(hierarchy.merges[i][0])] = node;
    parent[find(hierarchy.merges[i][1])] = node;
  }
  std::vector<int> labels(n);
  for (int f = 0; f < n; ++f)
  {
    labels[f] = find(f);
  }
  return numberByFirstFace(labels);
}
} // namespace

FaceClusterHierarchy buildFaceClusterHierarchy(const FaceGraph& graph, const HierarchicalClusteringOptions& options)
{
  if (!(options.directionWeight >= 0.0) || !(options.shapeWeight >= 0.0) || !std::isfinite(options.directionWeight) ||
    !std::isfinite(options.shapeWeight))
  {
    throw Error("the clustering weights must be finite and non-negative");
  }
  const TriangleMesh& mesh = graph.mesh();
  const int n = graph.faceCount();
  FaceClusterHierarchy hierarchy;
  hierarchy.faceCount = n;
  if (n == 0)
  {
    return hierarchy;
  }
  // Positions relative to the bounding box, in units of its diagonal.
  Vector3 low = mesh.point(mesh.triangle(0)[0]), high = low;
  for (const Triangle& t : mesh.triangles())
  {
    for (int v : t)
    {
      low = low.cwiseMin(mesh.point(v));
      high = high.cwiseMax(mesh.point(v));
    }
  }
  const Vector3 centre = 0.5 * (low + high);
  const double diagonal = (high - low).norm();
  const double scale = diagonal > 0.0 ? 1.0 / diagonal : 1.0;
  const double lengthScale = scale;

  std::vector<ClusterState> clusters(n);
  std::vector<std::vector<std::pair<int, double>>> adjacency(n); // neighbour slot, shared length
  for (int f = 0; f < n; ++f)
  {
    ClusterState& s = clusters[f];
    for (int v : mesh.triangle(f))
    {
      const Vector3 p = (mesh.point(v) - centre) * scale;
      s.A += p * p.transpose();
      s.b += p;
      s.c += 1.0;
    }
    const double w = graph.area(f) * scale * scale;
    const Vector3& normal = graph.normal(f);
    s.D = w * normal * normal.transpose();
    s.e = -w * normal;
    s.f = w;
    s.area = w;
    s.perimeter = graph.perimeter(f) * lengthScale;
  }
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const DualEdge& dual = graph.edge(e);
    adjacency[dual.faces[0]].push_back({ dual.faces[1], dual.length * lengthScale });
    adjacency[dual.faces[1]].push_back({ dual.faces[0], dual.length * lengthScale });
  }
  for (auto& list : adjacency)
  {
    std::sort(list.begin(), list.end());
  }

  std::vector<unsigned> version(n, 0);
  std::vector<int> node(n);
  std::iota(node.begin(), node.end(), 0);
  std::vector<char> alive(n, 1);
  std::vector<HeapEntry> storage;
  storage.reserve(static_cast<std::size_t>(graph.edgeCount()) * 2);
  std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<HeapEntry>> heap(
    std::greater<HeapEntry>(), std::move(storage));
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const DualEdge& dual = graph.edge(e);
    const int x = dual.faces[0], y = dual.faces[1];
    heap.push({ contractionCost(clusters[x], clusters[y], dual.length * lengthScale, options), x, y, 0, 0 });
    ++hierarchy.costEvaluations;
  }
  hierarchy.merges.reserve(static_cast<std::size_t>(n) - 1);
  hierarchy.costs.reserve(static_cast<std::size_t>(n) - 1);
  std::vector<std::pair<int, double>> combined;
  while (!heap.empty())
  {
    const HeapEntry top = heap.top();
    heap.pop();
    if (!alive[top.x] || !alive[top.y] || version[top.x] != top.vx || version[top.y] != top.vy)
    {
      continue;
    }
    // The larger neighbour list survives, so lists are copied O(n log n) times in all.
    int keep = top.x, gone = top.y;
    if (adjacency[gone].size() > adjacency[keep].size())
    {
      std::swap(keep, gone);
    }
    double shared = 0.0;
    for (const auto& [m, length] : adjacency[keep])
    {
      if (m == gone)
      {
        shared = length;
      }
    }
    hierarchy.merges.push_back({ { std::min(node[keep], node[gone]), std::max(node[keep], node[gone]) } });
    hierarchy.costs.push_back(top.cost);
    node[keep] = n + static_cast<int>(hierarchy.merges.size()) - 1;
    clusters[keep].add(clusters[gone]);
    clusters[keep].perimeter = clusters[keep].perimeter + clusters[gone].perimeter - 2.0 * shared;
    alive[gone] = 0;
    ++version[keep];
    // Merge the two sorted neighbour lists; the neighbours of `gone` now see `keep`.
    combined.clear();
    const auto& a = adjacency[keep];
    const auto& b = adjacency[gone];
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size())
    {
      std::pair<int, double> next;
      if (j == b.size() || (i < a.size() && a[i].first < b[j].first))
      {
        next = a[i++];
      }
      else if (i == a.size() || b[j].first < a[i].first)
      {
        next = b[j++];
      }
      else
      {
        next = { a[i].first, a[i].second + b[j].second };
        ++i;
        ++j;
      }
      if (next.first != keep && next.first != gone)
      {
        combined.push_back(next);
      }
    }
    adjacency[keep].swap(combined);
    std::vector<std::pair<int, double>>().swap(adjacency[gone]);
    for (const auto& [m, length] : adjacency[keep])
    {
      auto& list = adjacency[m];
      list.erase(std::remove_if(list.begin(), list.end(),
                   [keep, gone](const auto& p) { return p.first == keep || p.first == gone; }),
        list.end());
      list.insert(std::lower_bound(list.begin(), list.end(), std::make_pair(keep, 0.0),
                    [](const auto& p, const auto& q) { return p.first < q.first; }),
        { keep, length });
      const int x = std::min(keep, m), y = std::max(keep, m);
      heap.push({ contractionCost(clusters[keep], clusters[m], length, options), x, y, version[x], version[y] });
      ++hierarchy.costEvaluations;
    }
  }
  return hierarchy;
}

const FaceClusterHierarchy& faceClusterHierarchy(const Surface& surface, const HierarchicalClusteringOptions& options)
{
  return surface.derived<FaceClusterHierarchy>("face-cluster-hierarchy:" + cacheKey(options),
    [&]() { return buildFaceClusterHierarchy(faceGraph(surface), options); });
}

std::vector<int> cutHierarchyAtCount(const FaceClusterHierarchy& hierarchy, int k)
{
  checkSegmentCount(k, hierarchy.faceCount);
  const std::size_t wanted = static_cast<std::size_t>(hierarchy.faceCount - k);
  return applyMerges(hierarchy, std::min(wanted, hierarchy.merges.size()));
}

std::vector<int> cutHierarchyAtError(const FaceClusterHierarchy& hierarchy, double maximumError)
{
  if (std::isnan(maximumError))
  {
    throw Error("the maximum contraction error is NaN");
  }
  std::size_t count = 0;
  while (count < hierarchy.costs.size() && hierarchy.costs[count] <= maximumError)
  {
    ++count;
  }
  return applyMerges(hierarchy, count);
}

} // namespace kerf
