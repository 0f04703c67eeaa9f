// Ensemble segmentation: the members' segmentations, their atoms, and average linkage of the co-association.
#include "Segmentation/EnsembleSegmentation.h"

#include "Error.h"
#include "Geometry/ConvexHull.h"
#include "Mesh/MeshValidation.h"
#include "Segmentation/PartitionDistance.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <queue>
#include <tuple>
#include <utility>

namespace kerf
{

namespace
{

// A group of atoms: its weight and, per member label ("slot"), how much of the group carries it.
struct Group
{
  std::vector<std::pair<int, double>> histogram; // (slot, weight), sorted by slot
  std::vector<int> neighbours;                   // adjacent live groups, sorted
  double weight = 0.0;
  int version = 0;
  bool alive = true;
};

std::vector<std::pair<int, double>> mergedHistogram(
  const std::vector<std::pair<int, double>>& a, const std::vector<std::pair<int, double>>& b)
{
  std::vector<std::pair<int, double>> sum;
  sum.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size())
  {
    if (j == b.size() || (i < a.size() && a[i].first < b[j].first))
    {
      sum.push_back(a[i++]);
    }
    else if (i == a.size() || b[j].first < a[i].first)
    {
      sum.push_back(b[j++]);
    }
    else
    {
      sum.push_back({ a[i].first, a[i].second + b[j].second });
      ++i;
      ++j;
    }
  }
  return sum;
}

// Fred and Jain 2005, section 4: the mean co-association of two groups, sum over the members of
// w_m sum_l n_a(m, l) n_b(m, l), divided by the two groups' weights.
double averageLinkage(const Group& a, const Group& b, const std::vector<double>& slotWeight)
{
  double sum = 0.0;
  std::size_t i = 0, j = 0;
  while (i < a.histogram.size() && j < b.histogram.size())
  {
    if (a.histogram[i].first < b.histogram[j].first)
    {
      ++i;
    }
    else if (b.histogram[j].first < a.histogram[i].first)
    {
      ++j;
    }
    else
    {
      sum += slotWeight[a.histogram[i].first] * a.histogram[i].second * b.histogram[j].second;
      ++i;
      ++j;
    }
  }
  return sum / (a.weight * b.weight);
}

void insertSorted(std::vector<int>& list, int value)
{
  const auto at = std::lower_bound(list.begin(), list.end(), value);
  if (at == list.end() || *at != value)
  {
    list.insert(at, value);
  }
}

void eraseSorted(std::vector<int>& list, int value)
{
  const auto at = std::lower_bound(list.begin(), list.end(), value);
  if (at != list.end() && *at == value)
  {
    list.erase(at);
  }
}

// The members' segmentations of a connected surface into k parts, those with a positive weight.
std::vector<WeightedPartition> memberPartitions(
  const Surface& surface, int k, const EnsembleSegmentationOptions& options)
{
  const FaceGraph& graph = faceGraph(surface);
  std::vector<WeightedPartition> partitions;
  auto vote = [&partitions](double weight, auto segment) {
    if (weight > 0.0)
    {
      partitions.push_back({ segment(), weight });
    }
  };
  vote(options.consensusCutsWeight, [&] { return segmentByConsensusCuts(surface, k, options.consensusCuts).labels; });
  vote(options.spectralWeight, [&] { return segmentSpectrally(surface, k, options.spectral).labels; });
  vote(options.convexFloodingWeight, [&] {
    ConvexFloodingOptions flooding = options.convexFlooding;
    flooding.segmentCount = k;
    return segmentByConvexFlooding(graph, flooding).labels;
  });
  vote(options.kMeansWeight, [&] { return segmentByKMeans(graph, k, options.kMeans).labels; });
  vote(options.watershedWeight, [&] {
    WatershedOptions watershed = options.watershed;
    watershed.segmentCount = k;
    return segmentByWatershed(graph, watershed).labels;
  });
  vote(options.faceClusteringWeight,
    [&] { return cutHierarchyAtCount(faceClusterHierarchy(surface, options.faceClustering), k); });
  vote(options.coreExtractionWeight, [&] { return segmentByCoreExtraction(graph, options.coreExtraction).labels; });
  return partitions;
}

// The members' votes joined into k parts and the boundaries refined.
EnsembleSegmentationResult joinMembers(const Surface& surface, int k, const std::vector<WeightedPartition>& partitions,
  const EnsembleSegmentationOptions& options)
{
  const FaceGraph& graph = faceGraph(surface);
  const PartitionConsensus consensus = combinePartitions(graph, partitions, k, options.areaWeighted);
  EnsembleSegmentationResult result;
  result.labels = refineSegmentBoundaries(graph, consensus.labels, options.refinement).labels;
  result.members = static_cast<int>(partitions.size());
  result.atoms = consensus.atoms;
  result.segmentCount = k;
  return result;
}

// The count of a connected surface chosen among [lowest, highest]: the ensemble at each count, and
// the one whose partition is nearest, in mean 1 - Rand index, to every member's partition at every
// count (a median partition of the members across counts; Fred and Jain 2005 pool partitions of
// several counts in the same way). The smaller count wins a tie.
EnsembleSegmentationResult segmentConnectedChoosingCount(
  const Surface& surface, int lowest, int highest, const EnsembleSegmentationOptions& options)
{
  std::vector<WeightedPartition> pool;
  std::vector<EnsembleSegmentationResult> candidates;
  for (int k = lowest; k <= highest; ++k)
  {
    std::vector<WeightedPartition> partitions = memberPartitions(surface, k, options);
    candidates.push_back(joinMembers(surface, k, partitions, options));
    pool.insert(pool.end(), std::make_move_iterator(partitions.begin()), std::make_move_iterator(partitions.end()));
  }
  double poolWeight = 0.0;
  for (const WeightedPartition& partition : pool)
  {
    poolWeight += partition.weight;
  }
  std::size_t best = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c)
  {
    double score = 0.0;
    for (const WeightedPartition& partition : pool)
    {
      score += partition.weight * randIndexError(candidates[c].labels, partition.labels);
    }
    candidates[c].countScore = score / poolWeight;
    if (candidates[c].countScore < candidates[best].countScore)
    {
      best = c;
    }
  }
  EnsembleSegmentationResult result = std::move(candidates[best]);
  for (const EnsembleSegmentationResult& candidate : candidates)
  {
    result.countScores.push_back(candidate.countScore);
  }
  return result;
}

void checkEnsembleOptions(const TriangleMesh& mesh, const EnsembleSegmentationOptions& options)
{
  const double weights[] = { options.consensusCutsWeight, options.spectralWeight, options.convexFloodingWeight,
    options.kMeansWeight, options.watershedWeight, options.faceClusteringWeight, options.coreExtractionWeight };
  double total = 0.0;
  for (double weight : weights)
  {
    if (!(weight >= 0.0) || !std::isfinite(weight))
    {
      throw Error("an ensemble member's weight is negative or not finite");
    }
    total += weight;
  }
  if (!(total > 0.0))
  {
    throw Error("an ensemble needs a member with a positive weight");
  }
  checkBoundaryRefinementOptions(options.refinement);
  requireOrientedManifold(mesh, "ensemble segmentation");
}

} // namespace

PartitionConsensus combinePartitions(
  const FaceGraph& graph, const std::vector<WeightedPartition>& partitions, int k, bool areaWeighted)
{
  const int n = graph.faceCount();
  checkSegmentCount(k, n);
  if (partitions.empty())
  {
    throw Error("combining partitions needs at least one partition");
  }
  double totalWeight = 0.0;
  for (std::size_t m = 0; m < partitions.size(); ++m)
  {
    const WeightedPartition& partition = partitions[m];
    if (static_cast<int>(partition.labels.size()) != n)
    {
      throw Error("partition " + std::to_string(m) + " labels " + std::to_string(partition.labels.size()) +
        " faces, the surface has " + std::to_string(n));
    }
    if (!(partition.weight >= 0.0) || !std::isfinite(partition.weight))
    {
      throw Error("partition " + std::to_string(m) + " has a negative or non-finite weight");
    }
    if (std::any_of(partition.labels.begin(), partition.labels.end(), [](int label) { return label < 0; }))
    {
      throw Error("partition " + std::to_string(m) + " has a negative label");
    }
    totalWeight += partition.weight;
  }
  if (!(totalWeight > 0.0))
  {
    throw Error("combining partitions needs a partition with a positive weight");
  }

  // Slots: one per (partition, label) of the partitions that vote, numbered in order of first face.
  std::vector<double> slotWeight;
  std::vector<std::vector<int>> slots;
  for (const WeightedPartition& partition : partitions)
  {
    if (partition.weight == 0.0)
    {
      continue;
    }
    std::map<int, int> dense;
    slots.emplace_back(n);
    for (int f = 0; f < n; ++f)
    {
      const auto [at, added] = dense.insert({ partition.labels[f], static_cast<int>(slotWeight.size()) });
      if (added)
      {
        slotWeight.push_back(partition.weight);
      }
      slots.back()[f] = at->second;
    }
  }
  auto together = [&slots](int f, int g) {
    return std::all_of(slots.begin(), slots.end(), [f, g](const std::vector<int>& s) { return s[f] == s[g]; });
  };

  // Areas in units of the mean face area, so that products of group weights neither underflow
  // nor overflow on meshes of any scale.
  const double areaScale = graph.totalArea() > 0.0 ? n / graph.totalArea() : 1.0;

  // Atoms: edge-connected faces that every partition keeps together.
  std::vector<int> atom(n, -1);
  std::vector<Group> groups;
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed)
  {
    if (atom[seed] >= 0)
    {
      continue;
    }
    const int id = static_cast<int>(groups.size());
    groups.emplace_back();
    atom[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      groups[id].weight += areaWeighted ? graph.area(f) * areaScale : 1.0;
      for (int e : graph.faceEdges(f))
      {
        const int g = e >= 0 ? graph.opposite(e, f) : -1;
        if (g >= 0 && atom[g] < 0 && together(f, g))
        {
          atom[g] = id;
          stack.push_back(g);
        }
      }
    }
    for (const std::vector<int>& s : slots)
    {
      groups[id].histogram.push_back({ s[seed], groups[id].weight });
    }
    std::sort(groups[id].histogram.begin(), groups[id].histogram.end());
  }
  for (const DualEdge& edge : graph.edges())
  {
    const int a = atom[edge.faces[0]], b = atom[edge.faces[1]];
    if (a != b)
    {
      insertSorted(groups[a].neighbours, b);
      insertSorted(groups[b].neighbours, a);
    }
  }
  PartitionConsensus result;
  result.atoms = static_cast<int>(groups.size());
  if (areaWeighted)
  {
    // Zero-area atoms (degenerate faces only) weigh as the smallest positive weight, so that the
    // linkage stays defined.
    double smallest = 0.0;
    for (const Group& group : groups)
    {
      if (group.weight > 0.0 && (smallest == 0.0 || group.weight < smallest))
      {
        smallest = group.weight;
      }
    }
    for (Group& group : groups)
    {
      if (!(group.weight > 0.0))
      {
        const double scale = smallest > 0.0 ? smallest : 1.0;
        for (auto& entry : group.histogram)
        {
          entry.second = scale;
        }
        group.weight = scale;
      }
    }
  }

  // Average linkage across shared edges, the largest mean co-association first, and among equal
  // ones the pair whose smaller group is smallest (a fragment joins before two large parts do);
  // a pair's entry is stale once either group changed (its version) and is skipped at the top.
  // With whole weights and faces counted once, the sums are exact integers, so equal means tie
  // exactly instead of by rounding.
  using Entry = std::tuple<double, double, int, int, int, int>; // linkage, -smaller weight, -a, -b, versions
  std::priority_queue<Entry> heap;
  auto push = [&](int a, int b) {
    if (a > b)
    {
      std::swap(a, b);
    }
    heap.push({ averageLinkage(groups[a], groups[b], slotWeight), -std::min(groups[a].weight, groups[b].weight), -a, -b,
      groups[a].version, groups[b].version });
  };
  for (int a = 0; a < static_cast<int>(groups.size()); ++a)
  {
    for (int b : groups[a].neighbours)
    {
      if (a < b)
      {
        push(a, b);
      }
    }
  }
  std::vector<int> joined(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    joined[g] = static_cast<int>(g);
  }
  int live = static_cast<int>(groups.size());
  while (live > k && !heap.empty())
  {
    const auto [linkage, smaller, minusA, minusB, versionA, versionB] = heap.top();
    heap.pop();
    const int a = -minusA, b = -minusB;
    if (!groups[a].alive || !groups[b].alive || groups[a].version != versionA || groups[b].version != versionB)
    {
      continue;
    }
    // b joins a (a < b).
    Group& kept = groups[a];
    Group& gone = groups[b];
    kept.histogram = mergedHistogram(kept.histogram, gone.histogram);
    kept.weight += gone.weight;
    ++kept.version;
    gone.alive = false;
    joined[b] = a;
    for (int c : gone.neighbours)
    {
      if (c != a)
      {
        eraseSorted(groups[c].neighbours, b);
        insertSorted(groups[c].neighbours, a);
        insertSorted(kept.neighbours, c);
      }
    }
    eraseSorted(kept.neighbours, b);
    gone.neighbours.clear();
    gone.histogram.clear();
    for (int c : kept.neighbours)
    {
      push(a, c);
    }
    --live;
    ++result.merges;
  }
  // Each face takes the group its atom ended in (merged groups point at the group that kept them).
  std::vector<int> labels(n);
  for (int f = 0; f < n; ++f)
  {
    int root = atom[f];
    while (joined[root] != root)
    {
      root = joined[root];
    }
    for (int g = atom[f]; joined[g] != root && g != root;)
    {
      const int next = joined[g];
      joined[g] = root;
      g = next;
    }
    labels[f] = root;
  }
  result.labels = finalizeSegments(graph, labels, k);
  return result;
}

EnsembleSegmentationResult segmentByEnsemble(const Surface& surface, int k, const EnsembleSegmentationOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkSegmentCount(k, mesh.faceCount());
  checkEnsembleOptions(mesh, options);
  EnsembleSegmentationResult result;
  result.labels = segmentSurfaceComponents(surface, k, [&](const Surface& part, int partK) {
    const EnsembleSegmentationResult partResult =
      joinMembers(part, partK, memberPartitions(part, partK, options), options);
    result.members = partResult.members;
    result.atoms += partResult.atoms;
    return partResult.labels;
  });
  result.segmentCount = 1 + *std::max_element(result.labels.begin(), result.labels.end());
  return result;
}

namespace
{
// Vertices that stand for a component in its convex hull test: a hull of 2,000 points costs about a
// millisecond, and a part deep enough to count reaches far below the hull over many vertices.
constexpr int HullDepthSamples = 2000;

// largestHullDepthFraction of the vertices that faces use (a mesh may hold points no face uses).
double hullDepthOfFaces(const TriangleMesh& mesh)
{
  std::vector<Vector3> points;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.vertexFaces(v).empty())
    {
      points.push_back(mesh.point(v));
    }
  }
  return largestHullDepthFraction(points, HullDepthSamples);
}
} // namespace

EnsembleSegmentationResult segmentByEnsembleChoosingCount(
  const Surface& surface, int minimumCount, int maximumCount, const EnsembleSegmentationOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkSegmentCount(1, mesh.faceCount());
  if (minimumCount < 2 || maximumCount < minimumCount)
  {
    throw Error("choosing the segment count needs 2 <= minimum <= maximum, got " + std::to_string(minimumCount) +
      " and " + std::to_string(maximumCount));
  }
  if (maximumCount - minimumCount >= MaximumCountsToChoose)
  {
    throw Error("choosing the segment count among " + std::to_string(maximumCount - minimumCount + 1) +
      " counts: at most " + std::to_string(MaximumCountsToChoose) + " (the ensemble runs once per count)");
  }
  if (maximumCount > mesh.faceCount())
  {
    throw Error("choosing the segment count up to " + std::to_string(maximumCount) + " on a surface of " +
      std::to_string(mesh.faceCount()) + " faces: the maximum count can be at most the number of faces");
  }
  if (!(options.convexTolerance >= 0.0 && options.convexTolerance < 1.0))
  {
    throw Error("the convex tolerance must be at least 0 and below 1, got " + std::to_string(options.convexTolerance));
  }
  checkEnsembleOptions(mesh, options);
  const int components = faceGraph(surface).componentCount();
  // Each component chooses its own count within the range (at most its faces).
  EnsembleSegmentationResult result;
  result.labels = segmentEachSurfaceComponent(surface, [&](const Surface& part) {
    if (options.convexTolerance > 0.0 && hullDepthOfFaces(part.mesh()) < options.convexTolerance)
    {
      return std::vector<int>(part.mesh().faceCount(), 0);
    }
    const int highest = std::min(maximumCount, part.mesh().faceCount());
    const EnsembleSegmentationResult partResult =
      segmentConnectedChoosingCount(part, std::min(minimumCount, highest), highest, options);
    result.members = partResult.members;
    result.atoms += partResult.atoms;
    if (components == 1)
    {
      result.countScores = partResult.countScores;
      result.countScore = partResult.countScore;
    }
    return partResult.labels;
  });
  result.segmentCount = 1 + *std::max_element(result.labels.begin(), result.labels.end());
  return result;
}

} // namespace kerf
