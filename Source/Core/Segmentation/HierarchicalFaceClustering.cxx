// Hierarchical face clustering (Garland et al. 2001): quadrics, the contraction heap, and cuts of the merge tree.
#include "Segmentation/HierarchicalFaceClustering.h"

#include "Error.h"
#include "Mesh/UnionFind.h"
#include "Numerics/HugePages.h"
#include "Surface/Surface.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

namespace kerf
{

std::string cacheKey(const HierarchicalClusteringOptions& options)
{
  return "a1=" + cacheKey(options.directionWeight) + " a2=" + cacheKey(options.shapeWeight) +
    " exact=" + std::to_string(options.exactClusterCount) + " block=" + std::to_string(options.blockSize);
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

// a2-free E_shape = (gamma - max(gamma_1, gamma_2)) / gamma, gamma = p^2 / (4 pi w), of joining x
// and y, which share a boundary of length `shared` (Garland et al. 2001, section 3.2).
double shapeError(const ClusterState& x, const ClusterState& y, double shared, double area)
{
  const double gamma = irregularity(x.perimeter + y.perimeter - 2.0 * shared, area);
  return gamma > 0.0 ? (gamma - std::max(irregularity(x.perimeter, x.area), irregularity(y.perimeter, y.area))) / gamma
                     : 0.0;
}

// E = E_fit + a1 E_dir + a2 E_shape of joining x and y, which share a boundary of length `shared`;
// `smallestEigenvalue` receives the smallest eigenvalue of the joined cluster's Z.
double contractionCost(const ClusterState& x, const ClusterState& y, double shared,
  const HierarchicalClusteringOptions& options, double& smallestEigenvalue)
{
  ClusterState sum = x;
  sum.add(y);
  // Best plane: the eigenvector of Z = A - b b^T / c with the smallest eigenvalue (section 3.1).
  const Eigen::Matrix3d Z = sum.A - sum.b * sum.b.transpose() / sum.c;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(Z);
  Vector3 n = eigen.eigenvectors().col(0);
  smallestEigenvalue = eigen.eigenvalues()(0);
  const double fit = std::max(0.0, smallestEigenvalue) / sum.c;
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
  const double shape = shapeError(x, y, shared, sum.area);
  return fit + options.directionWeight * direction + options.shapeWeight * shape;
}

// A lower bound of min over unit n of the direction quadric n^T D n + 2 e.n + f = sum w_i (1 - n_i.n)^2.
// By Lagrange duality (the trust-region subproblem; More and Sorensen 1983), every mu with D - mu I
// positive definite gives f + mu - e^T (D - mu I)^{-1} e below it; mu follows More and Sorensen's
// Newton iteration on 1 / |(D - mu I)^{-1} e| = 1 from the left, where each iterate is such a mu.
// The factorization (with reciprocal pivots) is backward stable, so the rounding stays near
// eps (f + |mu|), far below the margin.
double directionQuadricMinimumBound(const Eigen::Matrix3d& D, const Vector3& e, double f)
{
  const double eNorm = e.norm();
  if (!(f > 0.0) || !(eNorm > 0.0))
  {
    return 0.0;
  }
  double mu = -eNorm; // |(D - mu I)^{-1} e| <= |e| / |mu| = 1 as D is positive semidefinite
  double best = 0.0;
  for (int iteration = 0; iteration < 6; ++iteration)
  {
    // Cholesky factor L of D - mu I.
    const double m00 = D(0, 0) - mu;
    if (!(m00 > 0.0))
    {
      break;
    }
    const double l00 = std::sqrt(m00), r00 = 1.0 / l00, l10 = D(1, 0) * r00, l20 = D(2, 0) * r00;
    const double m11 = D(1, 1) - mu - l10 * l10;
    if (!(m11 > 0.0))
    {
      break;
    }
    const double l11 = std::sqrt(m11), r11 = 1.0 / l11, l21 = (D(2, 1) - l20 * l10) * r11;
    const double m22 = D(2, 2) - mu - l20 * l20 - l21 * l21;
    if (!(m22 > 0.0))
    {
      break;
    }
    const double r22 = 1.0 / std::sqrt(m22);
    // z = L^{-1} e, so e^T (D - mu I)^{-1} e = |z|^2; y = L^{-T} z.
    const double z0 = e(0) * r00, z1 = (e(1) - l10 * z0) * r11, z2 = (e(2) - l20 * z0 - l21 * z1) * r22;
    best = std::max(best, f + mu - (z0 * z0 + z1 * z1 + z2 * z2) - 1e-10 * (f + std::abs(mu)));
    const double y2 = z2 * r22, y1 = (z1 - l21 * y2) * r11, y0 = (z0 - l10 * y1 - l20 * y2) * r00;
    const double yNorm = std::sqrt(y0 * y0 + y1 * y1 + y2 * y2);
    // Near |y| = 1 the dual value is flat (its derivative is 1 - |y|^2): stopping at 1e-3 loses
    // about 1e-6 of |mu|, which costs no measurable cost evaluations.
    if (std::abs(yNorm - 1.0) < 1e-3)
    {
      break;
    }
    // q = L^{-1} y; the Newton step of More and Sorensen (1983), equation 3.5 (lambda = -mu).
    const double q0 = y0 * r00, q1 = (y1 - l10 * q0) * r11, q2 = (y2 - l20 * q0 - l21 * q1) * r22;
    mu -= (yNorm * yNorm / (q0 * q0 + q1 * q1 + q2 * q2)) * (yNorm - 1.0);
  }
  return best;
}

// What contractionCostLowerBound reads of a cluster, packed for the neighbour loops: from its
// state, and the smallest eigenvalue of its Z and a lower bound of its direction quadric's minimum
// (both 0 for a face: its corners span a plane, and one normal fits it exactly).
struct ClusterSummary
{
  double c = 0.0;
  double traceA = 0.0;
  Vector3 b = Vector3::Zero();
  double f = 0.0;
  double area = 0.0;
  double perimeter = 0.0;
  double irregularity = 0.0;
  double smallestEigenvalue = 0.0;
  double directionMinimum = 0.0;

  ClusterSummary() = default;
  explicit ClusterSummary(const ClusterState& s, double lambda = 0.0, double direction = 0.0)
    : c(s.c)
    , traceA(s.A.trace())
    , b(s.b)
    , f(s.f)
    , area(s.area)
    , perimeter(s.perimeter)
    , irregularity(kerf::irregularity(s.perimeter, s.area))
    , smallestEigenvalue(lambda)
    , directionMinimum(direction)
  {
  }
};

// A lower bound of contractionCost(x, y) without its eigenproblem. Z of the join is Z_x + Z_y plus
// a positive semidefinite term, so its smallest eigenvalue is at least lambda_x + lambda_y (Weyl's
// inequality); the join's direction quadric is the sum of x's and y's, so its value at the fitted
// normal is at least the sum of their minima. The margins cover rounding: about 1e-15 tr(A) in
// forming Z, at worst sqrt(eps) tr(Z) (1.5e-8) in the closed-form eigenvalues where two of them
// nearly coincide, and about 1e-15 f in E_dir. E_shape is computed as the cost computes it and the
// terms are summed in the cost's order, so the bound never exceeds the cost computed in floating point.
double contractionCostLowerBound(
  const ClusterSummary& x, const ClusterSummary& y, double shared, const HierarchicalClusteringOptions& options)
{
  const double c = x.c + y.c;
  const double traceA = x.traceA + y.traceA;
  const double traceZ = std::max(0.0, traceA - (x.b + y.b).squaredNorm() / c);
  const double fitMargin = 1e-6 * traceZ + 1e-10 * traceA;
  const double fit = std::max(0.0, x.smallestEigenvalue + y.smallestEigenvalue - fitMargin) / c;
  const double f = x.f + y.f;
  double direction = 0.0;
  if (f > 0.0)
  {
    direction = std::max(0.0, (x.directionMinimum + y.directionMinimum - 1e-10 * f) / f);
  }
  const double gamma = irregularity(x.perimeter + y.perimeter - 2.0 * shared, x.area + y.area);
  const double shape = gamma > 0.0 ? (gamma - std::max(x.irregularity, y.irregularity)) / gamma : 0.0;
  return fit + options.directionWeight * direction + options.shapeWeight * shape;
}

// An indexed binary min-heap of cluster pairs ordered by (key, x, y): one entry per pair, whose
// key is raised or lowered in place and which is removed when the pair disappears, so the heap
// never holds more entries than the dual graph has edges.
class PairHeap
{
public:
  struct Entry
  {
    double key;
    int x, y; // cluster slots, x < y
    int pair;
  };

  explicit PairHeap(int pairCount)
    : Position(static_cast<std::size_t>(pairCount), -1)
  {
    this->Entries.reserve(static_cast<std::size_t>(pairCount));
  }

  /// Empties the heap for `pairCount` pairs, keeping its buffers.
  void reset(int pairCount)
  {
    this->Entries.clear();
    this->Entries.reserve(static_cast<std::size_t>(pairCount));
    this->Position.assign(static_cast<std::size_t>(pairCount), -1);
  }

  bool empty() const { return this->Entries.empty(); }
  const Entry& top() const { return this->Entries.front(); }

  /// Adds entries in any order; heapify() orders them (Floyd's linear-time construction).
  void append(const Entry& entry)
  {
    this->Position[entry.pair] = static_cast<int>(this->Entries.size());
    this->Entries.push_back(entry);
  }
  void heapify()
  {
    for (std::size_t i = this->Entries.size() / 2; i-- > 0;)
    {
      const Entry entry = this->Entries[i];
      this->siftDown(i, entry);
    }
  }

  /// Sets the key and slots of a pair in the heap.
  void update(const Entry& entry)
  {
    const std::size_t i = static_cast<std::size_t>(this->Position[entry.pair]);
    if (less(entry, this->Entries[i]))
    {
      this->siftUp(i, entry);
    }
    else
    {
      this->siftDown(i, entry);
    }
  }

  void remove(int pair)
  {
    const std::size_t i = static_cast<std::size_t>(this->Position[pair]);
    this->Position[pair] = -1;
    const Entry last = this->Entries.back();
    this->Entries.pop_back();
    if (i == this->Entries.size())
    {
      return;
    }
    if (less(last, this->Entries[i]))
    {
      this->siftUp(i, last);
    }
    else
    {
      this->siftDown(i, last);
    }
  }

private:
  static bool less(const Entry& a, const Entry& b)
  {
    return a.key != b.key ? a.key < b.key : (a.x != b.x ? a.x < b.x : a.y < b.y);
  }

  void place(std::size_t i, const Entry& entry)
  {
    this->Entries[i] = entry;
    this->Position[entry.pair] = static_cast<int>(i);
  }

  void siftUp(std::size_t i, const Entry& entry)
  {
    while (i > 0)
    {
      const std::size_t parent = (i - 1) / 2;
      if (!less(entry, this->Entries[parent]))
      {
        break;
      }
      this->place(i, this->Entries[parent]);
      i = parent;
    }
    this->place(i, entry);
  }

  void siftDown(std::size_t i, const Entry& entry)
  {
    const std::size_t size = this->Entries.size();
    for (;;)
    {
      std::size_t child = 2 * i + 1;
      if (child >= size)
      {
        break;
      }
      if (child + 1 < size && less(this->Entries[child + 1], this->Entries[child]))
      {
        ++child;
      }
      if (!less(this->Entries[child], entry))
      {
        break;
      }
      this->place(i, this->Entries[child]);
      i = child;
    }
    this->place(i, entry);
  }

  HugePageVector<Entry> Entries;
  HugePageVector<int> Position; // index in Entries of each pair, -1 when absent
};

// Union-find labels after the first `count` merges, numbered by first face.
std::vector<int> applyMerges(const FaceClusterHierarchy& hierarchy, std::size_t count)
{
  const int n = hierarchy.faceCount;
  std::vector<int> parent(static_cast<std::size_t>(n) + count);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < count; ++i)
  {
    const int node = n + static_cast<int>(i);
    parent[findRoot(parent, hierarchy.merges[i][0])] = node;
    parent[findRoot(parent, hierarchy.merges[i][1])] = node;
  }
  std::vector<int> labels(n);
  for (int f = 0; f < n; ++f)
  {
    labels[f] = findRoot(parent, f);
  }
  return numberByFirstFace(labels);
}

// One pair of adjacent clusters before contraction starts: slots x < y and their shared boundary.
struct PairSeed
{
  int x, y;
  double length;
};

// One contraction: the surviving slot, the absorbed one, and E.
struct Contraction
{
  int keep, gone;
  double cost;
};

// The greedy contraction of Garland et al. (2001) on clusters 0..s-1 (their states and summaries,
// edited in place) joined by `seeds`: the least (cost, x, y) pair is contracted until `mergeLimit`
// contractions are done, the least cost exceeds `costLimit`, or no pair is left. Buffers are kept
// between runs (the blocks of a build).
class ContractionRun
{
public:
  long long evaluations = 0;
  /// Keep the buffers of absorbed clusters' neighbour lists for the next run (small runs).
  bool keepLists = false;

  void run(HugePageVector<ClusterState>& clusters, HugePageVector<ClusterSummary>& summaries,
    const HugePageVector<PairSeed>& seeds, std::size_t mergeLimit, double costLimit,
    const HierarchicalClusteringOptions& options, HugePageVector<Contraction>& merges)
  {
    const int n = static_cast<int>(clusters.size());
    // One record per pair of adjacent clusters, made from a seed; when a cluster is absorbed its
    // records pass to the survivor, or fold into the survivor's record with the same neighbour.
    HugePageVector<ClusterPair>& pairs = this->Pairs;
    pairs.clear();
    pairs.reserve(seeds.size());
    if (this->Adjacency.size() < static_cast<std::size_t>(n))
    {
      this->Adjacency.resize(static_cast<std::size_t>(n));
      this->NeighbourPair.resize(static_cast<std::size_t>(n), -1);
      this->Mark.resize(static_cast<std::size_t>(n), -1);
    }
    std::vector<std::vector<int>>& adjacency = this->Adjacency; // the pairs of each cluster
    for (int s = 0; s < n; ++s)
    {
      adjacency[s].clear();
    }
    const auto other = [&pairs](int pair, int slot) { return pairs[pair].x == slot ? pairs[pair].y : pairs[pair].x; };
    for (const PairSeed& seed : seeds)
    {
      const int x = seed.x, y = seed.y;
      // Two faces with two or three common edges (a closed pair of triangles) form one pair.
      const auto twin = std::find_if(adjacency[x].begin(), adjacency[x].end(), [&](int q) { return other(q, x) == y; });
      if (twin != adjacency[x].end())
      {
        pairs[*twin].length += seed.length;
        continue;
      }
      adjacency[x].push_back(static_cast<int>(pairs.size()));
      adjacency[y].push_back(static_cast<int>(pairs.size()));
      pairs.push_back({ x, y, seed.length, 0.0, 0.0, 0.0, false });
    }

    // Costs are evaluated lazily: a pair enters the heap keyed on a lower bound of its cost, which
    // is computed only when the bound reaches the top. The popped exact entry is then the least
    // (cost, x, y) of all pairs, as if every cost had been computed. A key may also lag below its
    // pair's bound (kept when a merge raised the bound); it is raised when it reaches the top.
    const auto bound = [&](int q) {
      ClusterPair& p = pairs[q];
      p.key = contractionCostLowerBound(summaries[p.x], summaries[p.y], p.length, options);
      p.exact = false;
      p.heapKey = p.key;
      return PairHeap::Entry{ p.key, p.x, p.y, q };
    };
    PairHeap& heap = this->Heap;
    heap.reset(static_cast<int>(pairs.size()));
    for (int q = 0; q < static_cast<int>(pairs.size()); ++q)
    {
      heap.append(bound(q));
    }
    heap.heapify();

    // For each neighbour of the surviving cluster, its pair with it, valid while mark == stamp.
    std::vector<int>& neighbourPair = this->NeighbourPair;
    std::vector<int>& mark = this->Mark;
    std::size_t done = 0;
    while (!heap.empty() && done < mergeLimit)
    {
      const int top = heap.top().pair;
      ClusterPair& contracted = pairs[top];
      if (contracted.key > heap.top().key)
      {
        // A key left below the pair's bound: raised to it now that it is on top.
        contracted.heapKey = contracted.key;
        heap.update({ contracted.key, contracted.x, contracted.y, top });
        continue;
      }
      if (!contracted.exact)
      {
        contracted.key = contractionCost(
          clusters[contracted.x], clusters[contracted.y], contracted.length, options, contracted.smallestEigenvalue);
        contracted.exact = true;
        contracted.heapKey = contracted.key;
        ++this->evaluations;
        heap.update({ contracted.key, contracted.x, contracted.y, top });
        continue;
      }
      if (contracted.key > costLimit)
      {
        break;
      }
      heap.remove(top);
      // The larger neighbour list survives (ties: the smaller slot), so lists are copied
      // O(n log n) times in all.
      int keep = contracted.x, gone = contracted.y;
      if (adjacency[gone].size() > adjacency[keep].size())
      {
        std::swap(keep, gone);
      }
      const double shared = contracted.length;
      const int stamp = this->Stamp++;
      ++done;
      merges.push_back({ keep, gone, contracted.key });
      clusters[keep].add(clusters[gone]);
      clusters[keep].perimeter = clusters[keep].perimeter + clusters[gone].perimeter - 2.0 * shared;
      summaries[keep] = ClusterSummary(clusters[keep], contracted.smallestEigenvalue,
        directionQuadricMinimumBound(clusters[keep].D, clusters[keep].e, clusters[keep].f));

      // The neighbours of `keep`, without the contracted pair.
      std::vector<int>& kept = adjacency[keep];
      kept.erase(std::find(kept.begin(), kept.end(), top));
      const std::size_t own = kept.size(); // pairs whose slots stay as they are
      for (int q : kept)
      {
        const int m = other(q, keep);
        neighbourPair[m] = q;
        mark[m] = stamp;
      }
      // The neighbours of `gone` now see `keep`: a common neighbour's two pairs fold into one.
      for (int q : adjacency[gone])
      {
        if (q == top)
        {
          continue;
        }
        const int m = other(q, gone);
        if (mark[m] == stamp)
        {
          ClusterPair& common = pairs[neighbourPair[m]];
          common.length = common.length + pairs[q].length;
          heap.remove(q);
          std::vector<int>& list = adjacency[m];
          *std::find(list.begin(), list.end(), q) = list.back();
          list.pop_back();
        }
        else
        {
          pairs[q].x = std::min(keep, m);
          pairs[q].y = std::max(keep, m);
          kept.push_back(q);
        }
      }
      if (this->keepLists)
      {
        adjacency[gone].clear(); // its buffer serves the next run
      }
      else
      {
        std::vector<int>().swap(adjacency[gone]);
      }
      // `keep` changed, so every cost of its pairs did.
      for (std::size_t i = 0; i < kept.size(); ++i)
      {
        const int q = kept[i];
        ClusterPair& p = pairs[q];
        const double heapKey = p.heapKey;
        const PairHeap::Entry entry = bound(q);
        // A key at or below the new bound still bounds the cost from below, which is all the order
        // needs: the entry stays where it is (same slots, so ties break the same way) and is raised
        // when it reaches the top.
        if (i < own && heapKey <= entry.key)
        {
          p.heapKey = heapKey;
          continue;
        }
        heap.update(entry);
      }
    }
  }

private:
  struct ClusterPair
  {
    int x, y;                  // cluster slots, x < y
    double length;             // shared boundary
    double key;                // the cost if exact, else a lower bound of it
    double smallestEigenvalue; // of the joined Z, once the cost is exact
    double heapKey;            // the key of its heap entry: `key`, or a lower one left from before
    bool exact;
  };
  HugePageVector<ClusterPair> Pairs;
  std::vector<std::vector<int>> Adjacency;
  PairHeap Heap{ 0 };
  std::vector<int> NeighbourPair, Mark;
  int Stamp = 0;
};

// A face as a cluster: its corners' fit quadric (positions moved by `centre` and scaled by `scale`)
// and its area-weighted normal's direction quadric (Garland et al. 2001, section 3).
ClusterState faceCluster(const FaceGraph& graph, int f, const Vector3& centre, double scale)
{
  const TriangleMesh& mesh = graph.mesh();
  ClusterState s;
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
  s.perimeter = graph.perimeter(f) * scale;
  return s;
}

// Appends the merge of tree nodes a and b at `cost`; returns the new node.
int appendMerge(FaceClusterHierarchy& hierarchy, int a, int b, double cost)
{
  hierarchy.merges.push_back({ { std::min(a, b), std::max(a, b) } });
  hierarchy.costs.push_back(cost);
  return hierarchy.faceCount + static_cast<int>(hierarchy.merges.size()) - 1;
}

// Appends a contraction of slots keep and gone, `node` holding each slot's tree node.
void record(FaceClusterHierarchy& hierarchy, HugePageVector<int>& node, int keep, int gone, double cost)
{
  node[keep] = appendMerge(hierarchy, node[keep], node[gone], cost);
}

// One block in this many is contracted first to set the blocks' common cost threshold.
constexpr std::size_t BlockSampleStride = 16;

// Blocks of about `size` faces grown breadth-first over the dual graph from the smallest face
// not yet taken: each block's faces in increasing order, blocks in order of their first seed.
std::vector<std::vector<int>> growBlocks(const FaceGraph& graph, int size)
{
  const int n = graph.faceCount();
  std::vector<int> blockOf(static_cast<std::size_t>(n), -1);
  std::vector<int> sizes;
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(size));
  for (int seed = 0; seed < n; ++seed)
  {
    if (blockOf[seed] >= 0)
    {
      continue;
    }
    const int block = static_cast<int>(sizes.size());
    queue.clear();
    queue.push_back(seed);
    blockOf[seed] = block;
    for (std::size_t head = 0; head < queue.size() && static_cast<int>(queue.size()) < size; ++head)
    {
      for (int e : graph.faceEdges(queue[head]))
      {
        const int g = e < 0 ? -1 : graph.opposite(e, queue[head]);
        if (g >= 0 && blockOf[g] < 0 && static_cast<int>(queue.size()) < size)
        {
          blockOf[g] = block;
          queue.push_back(g);
        }
      }
    }
    sizes.push_back(static_cast<int>(queue.size()));
  }
  std::vector<std::vector<int>> blocks(sizes.size());
  for (std::size_t b = 0; b < sizes.size(); ++b)
  {
    blocks[b].reserve(static_cast<std::size_t>(sizes[b]));
  }
  for (int f = 0; f < n; ++f)
  {
    blocks[static_cast<std::size_t>(blockOf[f])].push_back(f);
  }
  return blocks;
}

} // namespace

FaceClusterHierarchy buildFaceClusterHierarchy(const FaceGraph& graph, const HierarchicalClusteringOptions& options)
{
  if (!(options.directionWeight >= 0.0) || !(options.shapeWeight >= 0.0) || !std::isfinite(options.directionWeight) ||
    !std::isfinite(options.shapeWeight))
  {
    throw Error("the clustering weights must be finite and non-negative");
  }
  if (options.exactClusterCount < 1 || options.blockSize < 1)
  {
    throw Error("the exact cluster count and the block size must be at least 1");
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
  hierarchy.merges.reserve(static_cast<std::size_t>(n) - 1);
  hierarchy.costs.reserve(static_cast<std::size_t>(n) - 1);
  ContractionRun contraction;
  HugePageVector<Contraction> merges;

  if (n <= options.exactClusterCount)
  {
    // The work buffers take huge pages (HugePages.h): at a million faces they fault in about 500 MB.
    HugePageVector<ClusterState> clusters(n);
    for (int f = 0; f < n; ++f)
    {
      clusters[f] = faceCluster(graph, f, centre, scale);
    }
    HugePageVector<ClusterSummary> summaries(clusters.begin(), clusters.end());
    HugePageVector<PairSeed> seeds;
    seeds.reserve(static_cast<std::size_t>(graph.edgeCount()));
    for (const DualEdge& dual : graph.edges())
    {
      seeds.push_back({ dual.faces[0], dual.faces[1], dual.length * scale });
    }
    merges.reserve(static_cast<std::size_t>(n) - 1);
    contraction.run(clusters, summaries, seeds, static_cast<std::size_t>(n), std::numeric_limits<double>::infinity(),
      options, merges);
    HugePageVector<int> node(n);
    std::iota(node.begin(), node.end(), 0);
    for (const Contraction& m : merges)
    {
      record(hierarchy, node, m.keep, m.gone, m.cost);
    }
    hierarchy.costEvaluations = contraction.evaluations;
    return hierarchy;
  }

  // Above exactClusterCount faces the contractions start inside blocks of nearby faces, each
  // greedy on the pairs within it, until its least cost exceeds a threshold common to all blocks
  // or it is down to half its share of exactClusterCount (so that a smooth block is not merged
  // into block-shaped clusters). The threshold is the cost at which blocks sampled evenly (one in
  // BlockSampleStride), contracted down to that floor, would leave their share: a block with sharp
  // features keeps more clusters, a smooth one fewer, as in the greedy over the whole mesh. The
  // greedy then runs on all clusters left.
  const std::vector<std::vector<int>> blocks = growBlocks(graph, options.blockSize);
  merges.reserve(static_cast<std::size_t>(n) - 1);
  // A block's share of exactClusterCount (its faces times exactClusterCount / n, rounded up), and
  // its floor: half the share, at least one cluster.
  const auto shareOf = [&](const std::vector<int>& block) {
    return (static_cast<long long>(block.size()) * options.exactClusterCount + n - 1) / n;
  };
  const auto floorOf = [&](const std::vector<int>& block) {
    return static_cast<int>(std::clamp((shareOf(block) + 1) / 2, 1LL, static_cast<long long>(block.size())));
  };
  HugePageVector<int> local(n, -1);
  HugePageVector<ClusterState> blockClusters;
  HugePageVector<ClusterSummary> blockSummaries;
  HugePageVector<PairSeed> blockSeeds;
  contraction.keepLists = true;
  // Contracts one block (local slots in face order); its contractions are appended to `merges` in
  // local slots.
  const auto contractBlock = [&](const std::vector<int>& block, double costLimit) {
    const int size = static_cast<int>(block.size());
    blockClusters.resize(block.size());
    blockSummaries.resize(block.size());
    for (int i = 0; i < size; ++i)
    {
      local[block[i]] = i;
      blockClusters[i] = faceCluster(graph, block[i], centre, scale);
      blockSummaries[i] = ClusterSummary(blockClusters[i]);
    }
    blockSeeds.clear();
    for (int i = 0; i < size; ++i)
    {
      for (int e : graph.faceEdges(block[i]))
      {
        const int g = e < 0 ? -1 : graph.opposite(e, block[i]);
        if (g > block[i] && local[g] >= 0)
        {
          blockSeeds.push_back({ i, local[g], graph.edge(e).length * scale });
        }
      }
    }
    for (int i = 0; i < size; ++i)
    {
      local[block[i]] = -1;
    }
    contraction.run(blockClusters, blockSummaries, blockSeeds, static_cast<std::size_t>(size - floorOf(block)),
      costLimit, options, merges);
  };

  // The threshold, from the sampled blocks' running maxima of cost.
  double threshold = std::numeric_limits<double>::infinity();
  {
    std::vector<double> runningMaxima;
    long long sampledFaces = 0, sampledShare = 0;
    for (std::size_t b = 0; b < blocks.size(); b += BlockSampleStride)
    {
      merges.clear();
      contractBlock(blocks[b], std::numeric_limits<double>::infinity());
      double runningMax = -std::numeric_limits<double>::infinity();
      for (const Contraction& m : merges)
      {
        runningMax = std::max(runningMax, m.cost);
        runningMaxima.push_back(runningMax);
      }
      sampledFaces += static_cast<long long>(blocks[b].size());
      sampledShare += shareOf(blocks[b]);
    }
    merges.clear();
    const long long needed = sampledFaces - sampledShare; // contractions that leave the sample's share
    if (needed > 0 && needed <= static_cast<long long>(runningMaxima.size()))
    {
      std::nth_element(runningMaxima.begin(), runningMaxima.begin() + (needed - 1), runningMaxima.end());
      threshold = runningMaxima[static_cast<std::size_t>(needed - 1)];
    }
  }

  // Each block's contractions, their two children written as tree nodes: a face, or -(1 + p) for
  // the node made by the contraction at position p of `merges` (numbered once the blocks
  // interleave). The clusters left: their first face, node, state, and each face's cluster.
  std::vector<int> survivors, survivorNodes;
  HugePageVector<ClusterState> survivorClusters;
  HugePageVector<ClusterSummary> survivorSummaries;
  HugePageVector<int> clusterOf(n);  // per face, its cluster's index in `survivors`
  std::vector<std::size_t> blockEnd; // per block, the end of its contractions in `merges`
  {
    std::vector<int> localNode, localParent, localSurvivor;
    for (const std::vector<int>& block : blocks)
    {
      const std::size_t first = merges.size();
      contractBlock(block, threshold);
      const int size = static_cast<int>(block.size());
      localNode.assign(block.begin(), block.end());
      localParent.resize(block.size());
      std::iota(localParent.begin(), localParent.end(), 0);
      for (std::size_t i = first; i < merges.size(); ++i)
      {
        Contraction& m = merges[i];
        const int keep = m.keep, gone = m.gone;
        m.keep = localNode[keep];
        m.gone = localNode[gone];
        localNode[keep] = -1 - static_cast<int>(i);
        localParent[gone] = keep;
      }
      blockEnd.push_back(merges.size());
      localSurvivor.assign(block.size(), -1);
      for (int i = 0; i < size; ++i)
      {
        if (localParent[i] == i)
        {
          localSurvivor[i] = static_cast<int>(survivors.size());
          survivors.push_back(block[i]);
          survivorNodes.push_back(localNode[i]);
          survivorClusters.push_back(blockClusters[i]);
          survivorSummaries.push_back(blockSummaries[i]);
        }
      }
      for (int i = 0; i < size; ++i)
      {
        int root = i;
        while (localParent[root] != root)
        {
          root = localParent[root];
        }
        clusterOf[block[i]] = localSurvivor[root];
      }
    }
  }
  // The blocks' contractions into the tree by their running maxima of cost (each block in its order).
  HugePageVector<int> treeIndex(merges.size()); // per position in `merges`, its merge in the tree
  const auto treeNode = [&](int child) {
    return child >= 0 ? child : n + treeIndex[static_cast<std::size_t>(-1 - child)];
  };
  {
    using Next = std::pair<double, std::size_t>; // (running maximum, block)
    std::priority_queue<Next, std::vector<Next>, std::greater<Next>> next;
    std::vector<std::size_t> position(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
      position[b] = b == 0 ? 0 : blockEnd[b - 1];
      if (position[b] < blockEnd[b])
      {
        next.push({ merges[position[b]].cost, b });
      }
    }
    while (!next.empty())
    {
      const auto [level, b] = next.top();
      next.pop();
      const std::size_t at = position[b]++;
      const Contraction& m = merges[at];
      treeIndex[at] = appendMerge(hierarchy, treeNode(m.keep), treeNode(m.gone), m.cost) - n;
      if (position[b] < blockEnd[b])
      {
        next.push({ std::max(level, merges[position[b]].cost), b });
      }
    }
  }
  // The clusters left, numbered in slot order, and their pairs (boundary lengths summed over dual
  // edges in edge order).
  std::vector<int> order(survivors.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return survivors[a] < survivors[b]; });
  HugePageVector<ClusterState> clusters(survivors.size());
  HugePageVector<ClusterSummary> summaries(survivors.size());
  HugePageVector<int> rank(survivors.size()), clusterNode(survivors.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    clusters[i] = survivorClusters[order[i]];
    summaries[i] = survivorSummaries[order[i]];
    clusterNode[i] = treeNode(survivorNodes[order[i]]);
    rank[order[i]] = static_cast<int>(i);
  }
  survivorClusters = {};
  survivorSummaries = {};
  struct Crossing
  {
    int x, y, edge;
  };
  HugePageVector<Crossing> crossings;
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const int a = rank[clusterOf[graph.edge(e).faces[0]]], b = rank[clusterOf[graph.edge(e).faces[1]]];
    if (a != b)
    {
      crossings.push_back({ std::min(a, b), std::max(a, b), e });
    }
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& p, const Crossing& q) {
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.edge < q.edge);
  });
  HugePageVector<PairSeed> seeds;
  for (const Crossing& c : crossings)
  {
    const double length = graph.edge(c.edge).length * scale;
    if (!seeds.empty() && seeds.back().x == c.x && seeds.back().y == c.y)
    {
      seeds.back().length += length;
    }
    else
    {
      seeds.push_back({ c.x, c.y, length });
    }
  }
  const std::size_t first = merges.size();
  contraction.keepLists = false;
  contraction.run(
    clusters, summaries, seeds, clusters.size(), std::numeric_limits<double>::infinity(), options, merges);
  for (std::size_t i = first; i < merges.size(); ++i)
  {
    record(hierarchy, clusterNode, merges[i].keep, merges[i].gone, merges[i].cost);
  }
  hierarchy.costEvaluations = contraction.evaluations;
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
