// Ensemble segmentation: the members' segmentations, their atoms, and average linkage of the co-association.
#include "Segmentation/EnsembleSegmentation.h"

#include "Error.h"
#include "Geometry/ConvexHull.h"
#include "Mesh/MeshValidation.h"
#include "Segmentation/PartitionDistance.h"
#include "Surface/Surface.h"
#include "Threads.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>
#include <queue>
#include <string>
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

// A member of the ensemble: its vote and its segmentation of a connected surface into k parts, and
// for the members that share work across counts, its segmentations at every count of a range.
struct Member
{
  double weight;
  std::function<std::vector<int>(const Surface&, int)> segment;
  std::function<std::vector<std::vector<int>>(const Surface&, int, int)> segmentAtCounts = nullptr;

  // The segmentations of a connected surface at every count from lowest to highest, each equal
  // to segment at its count.
  std::vector<std::vector<int>> atCounts(const Surface& surface, int lowest, int highest) const
  {
    if (segmentAtCounts)
    {
      return segmentAtCounts(surface, lowest, highest);
    }
    std::vector<std::vector<int>> labels;
    for (int k = lowest; k <= highest; ++k)
    {
      labels.push_back(segment(surface, k));
    }
    return labels;
  }
};

// The labels of a member's results at each count.
template <typename Result>
std::vector<std::vector<int>> labelsOf(std::vector<Result> results)
{
  std::vector<std::vector<int>> labels;
  for (Result& result : results)
  {
    labels.push_back(std::move(result.labels));
  }
  return labels;
}

// A member's options with the count it segments into (the members that read it from their options).
template <typename Options>
Options withSegmentCount(Options options, int k)
{
  options.segmentCount = k;
  return options;
}

// The members, in a fixed order (the order of their votes in the co-association).
std::vector<Member> ensembleMembers(const EnsembleSegmentationOptions& options)
{
  return {
    { options.consensusCutsWeight,
      [&options](
        const Surface& surface, int k) { return segmentByConsensusCuts(surface, k, options.consensusCuts).labels; } },
    { options.spectralWeight,
      [&options](const Surface& surface, int k) { return segmentSpectrally(surface, k, options.spectral).labels; } },
    { options.convexFloodingWeight,
      [&options](const Surface& surface, int k) {
        return segmentByConvexFlooding(faceGraph(surface), withSegmentCount(options.convexFlooding, k)).labels;
      } },
    { options.kMeansWeight,
      [&options](
        const Surface& surface, int k) { return segmentByKMeans(faceGraph(surface), k, options.kMeans).labels; },
      [&options](const Surface& surface, int lowest, int highest) {
        return labelsOf(segmentByKMeansAtCounts(faceGraph(surface), lowest, highest, options.kMeans));
      } },
    { options.watershedWeight,
      [&options](const Surface& surface, int k) {
        return segmentByWatershed(faceGraph(surface), withSegmentCount(options.watershed, k)).labels;
      },
      [&options](const Surface& surface, int lowest, int highest) {
        return labelsOf(segmentByWatershedAtCounts(faceGraph(surface), options.watershed, lowest, highest));
      } },
    { options.faceClusteringWeight,
      [&options](const Surface& surface, int k) {
        return cutHierarchyAtCount(faceClusterHierarchy(surface, options.faceClustering), k);
      } },
    { options.coreExtractionWeight,
      [&options](const Surface& surface, int) {
        return segmentByCoreExtraction(faceGraph(surface), options.coreExtraction).labels;
      } },
  };
}

// The members with a positive weight, in their order.
std::vector<Member> votingMembers(const EnsembleSegmentationOptions& options)
{
  std::vector<Member> voting;
  for (Member& member : ensembleMembers(options))
  {
    if (member.weight > 0.0)
    {
      voting.push_back(std::move(member));
    }
  }
  return voting;
}

// The members' segmentations at every count from lowest to highest, those with a positive weight:
// per count, in the members' order, each member on a thread of its own (parallelFor). On a
// connected surface a member shares its work across the counts (Member::atCounts); on one of
// several components each count is shared out over them (segmentSurfaceComponents).
std::vector<std::vector<WeightedPartition>> memberPartitionsAtCounts(
  const Surface& surface, int lowest, int highest, const EnsembleSegmentationOptions& options)
{
  const std::vector<Member> voting = votingMembers(options);
  const bool connected = faceGraph(surface).componentCount() == 1;
  std::vector<std::vector<std::vector<int>>> labels(voting.size());
  parallelFor(static_cast<int>(voting.size()), [&](int m) {
    const Member& member = voting[static_cast<std::size_t>(m)];
    if (connected)
    {
      labels[static_cast<std::size_t>(m)] = member.atCounts(surface, lowest, highest);
      return;
    }
    for (int count = lowest; count <= highest; ++count)
    {
      labels[static_cast<std::size_t>(m)].push_back(segmentSurfaceComponents(surface, count, member.segment));
    }
  });
  std::vector<std::vector<WeightedPartition>> partitions(static_cast<std::size_t>(highest - lowest + 1));
  for (std::size_t m = 0; m < voting.size(); ++m)
  {
    for (std::size_t c = 0; c < partitions.size(); ++c)
    {
      partitions[c].push_back({ std::move(labels[m][c]), voting[m].weight });
    }
  }
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

// The weighted mean 1 - Rand index of `labels` against the pooled partitions.
double meanDistanceToPool(const std::vector<int>& labels, const std::vector<WeightedPartition>& pool)
{
  double score = 0.0, weight = 0.0;
  for (const WeightedPartition& partition : pool)
  {
    score += partition.weight * randIndexError(labels, partition.labels);
    weight += partition.weight;
  }
  return score / weight;
}

// The count of a connected surface chosen among [lowest, highest]: the ensemble at each count, and
// the one whose partition is nearest, in mean 1 - Rand index, to every member's partition at every
// count (a median partition of the members across counts; Fred and Jain 2005 pool partitions of
// several counts in the same way). The smaller count wins a tie.
EnsembleSegmentationResult segmentConnectedChoosingCount(
  const Surface& surface, int lowest, int highest, const EnsembleSegmentationOptions& options)
{
  std::vector<std::vector<WeightedPartition>> atCounts = memberPartitionsAtCounts(surface, lowest, highest, options);
  // The ensemble at each count, then each scored against the pool, the counts on Kerf's threads.
  std::vector<EnsembleSegmentationResult> candidates(atCounts.size());
  parallelFor(static_cast<int>(atCounts.size()), [&](int c) {
    candidates[static_cast<std::size_t>(c)] =
      joinMembers(surface, lowest + c, atCounts[static_cast<std::size_t>(c)], options);
  });
  std::vector<WeightedPartition> pool;
  for (std::vector<WeightedPartition>& partitions : atCounts)
  {
    pool.insert(pool.end(), std::make_move_iterator(partitions.begin()), std::make_move_iterator(partitions.end()));
  }
  parallelFor(static_cast<int>(candidates.size()), [&](int c) {
    candidates[static_cast<std::size_t>(c)].countScore =
      meanDistanceToPool(candidates[static_cast<std::size_t>(c)].labels, pool);
  });
  std::size_t best = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c)
  {
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

ConsensusHierarchy consensusHierarchy(
  const FaceGraph& graph, const std::vector<WeightedPartition>& partitions, bool areaWeighted, int lowestCount)
{
  const int n = graph.faceCount();
  checkSegmentCount(lowestCount, n);
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
  ConsensusHierarchy result;
  result.atomOfFace = atom;
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
  int live = static_cast<int>(groups.size());
  while (live > lowestCount && !heap.empty())
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
    result.merges.push_back({ a, b });
    result.linkages.push_back(linkage);
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
  }
  return result;
}

PartitionConsensus cutConsensusHierarchy(const FaceGraph& graph, const ConsensusHierarchy& hierarchy, int k)
{
  const int n = graph.faceCount();
  checkSegmentCount(k, n);
  if (static_cast<int>(hierarchy.atomOfFace.size()) != n)
  {
    throw Error("a consensus hierarchy of " + std::to_string(hierarchy.atomOfFace.size()) +
      " faces cut on a surface of " + std::to_string(n));
  }
  const auto outside = [&hierarchy](int atom) { return atom < 0 || atom >= hierarchy.atoms; };
  if (std::any_of(hierarchy.atomOfFace.begin(), hierarchy.atomOfFace.end(), outside) ||
    std::any_of(hierarchy.merges.begin(), hierarchy.merges.end(),
      [&outside](const std::array<int, 2>& merge) { return outside(merge[0]) || outside(merge[1]); }))
  {
    throw Error("a consensus hierarchy names an atom outside its " + std::to_string(hierarchy.atoms) + " atoms");
  }
  // The first atoms - k merges (all when there are fewer), replayed: merged groups point at the
  // group that kept them.
  std::vector<int> joined(static_cast<std::size_t>(hierarchy.atoms));
  for (int g = 0; g < hierarchy.atoms; ++g)
  {
    joined[static_cast<std::size_t>(g)] = g;
  }
  const std::size_t replayed =
    std::min(hierarchy.merges.size(), static_cast<std::size_t>(std::max(hierarchy.atoms - k, 0)));
  for (std::size_t m = 0; m < replayed; ++m)
  {
    joined[static_cast<std::size_t>(hierarchy.merges[m][1])] = hierarchy.merges[m][0];
  }
  PartitionConsensus result;
  result.atoms = hierarchy.atoms;
  result.merges = static_cast<int>(replayed);
  const std::vector<int>& atom = hierarchy.atomOfFace;
  // Each face takes the group its atom ended in.
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

PartitionConsensus combinePartitions(
  const FaceGraph& graph, const std::vector<WeightedPartition>& partitions, int k, bool areaWeighted)
{
  checkSegmentCount(k, graph.faceCount());
  return cutConsensusHierarchy(graph, consensusHierarchy(graph, partitions, areaWeighted, k), k);
}

EnsembleSegmentationResult segmentByEnsemble(const Surface& surface, int k, const EnsembleSegmentationOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkSegmentCount(k, mesh.faceCount());
  checkEnsembleOptions(mesh, options);
  EnsembleSegmentationResult result;
  result.labels = segmentSurfaceComponents(surface, k, [&](const Surface& part, int partK) {
    const EnsembleSegmentationResult partResult =
      joinMembers(part, partK, memberPartitionsAtCounts(part, partK, partK, options).front(), options);
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
// The range of counts the members run at, the convex tolerance and the ensemble's options
// (segmentByEnsembleChoosingCount, ensembleHierarchy).
void checkCountChoice(const TriangleMesh& mesh, int minimumCount, int maximumCount,
  const EnsembleSegmentationOptions& options, const std::string& what)
{
  checkSegmentCount(1, mesh.faceCount());
  if (minimumCount < 2 || maximumCount < minimumCount)
  {
    throw Error(what + " needs 2 <= minimum <= maximum, got " + std::to_string(minimumCount) + " and " +
      std::to_string(maximumCount));
  }
  if (maximumCount - minimumCount >= MaximumCountsToChoose)
  {
    throw Error(what + " among " + std::to_string(maximumCount - minimumCount + 1) + " counts: at most " +
      std::to_string(MaximumCountsToChoose) + " (the members run once per count)");
  }
  if (maximumCount > mesh.faceCount())
  {
    throw Error(what + " up to " + std::to_string(maximumCount) + " on a surface of " +
      std::to_string(mesh.faceCount()) + " faces: the maximum count can be at most the number of faces");
  }
  if (!(options.convexTolerance >= 0.0 && options.convexTolerance < 1.0))
  {
    throw Error("the convex tolerance must be at least 0 and below 1, got " + std::to_string(options.convexTolerance));
  }
  checkEnsembleOptions(mesh, options);
}
} // namespace

EnsembleSegmentationResult segmentByEnsembleChoosingCount(
  const Surface& surface, int minimumCount, int maximumCount, const EnsembleSegmentationOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkCountChoice(mesh, minimumCount, maximumCount, options, "choosing the segment count");
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

EnsembleHierarchy ensembleHierarchy(
  const Surface& surface, int minimumCount, int maximumCount, const EnsembleSegmentationOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkCountChoice(mesh, minimumCount, maximumCount, options, "an ensemble hierarchy");
  // Every member at every count, each dual-graph component with its share of the count.
  std::vector<WeightedPartition> pool;
  for (std::vector<WeightedPartition>& partitions :
    memberPartitionsAtCounts(surface, minimumCount, maximumCount, options))
  {
    pool.insert(pool.end(), std::make_move_iterator(partitions.begin()), std::make_move_iterator(partitions.end()));
  }
  EnsembleHierarchy hierarchy;
  hierarchy.consensus = consensusHierarchy(faceGraph(surface), pool, options.areaWeighted);
  hierarchy.members = static_cast<int>(pool.size());
  hierarchy.minimumCount = minimumCount;
  hierarchy.maximumCount = maximumCount;
  // The count: the cut nearest to every member at every count (as segmentConnectedChoosingCount
  // chooses among the ensembles at each count), or 1 for a connected surface without parts.
  if (faceGraph(surface).componentCount() == 1 && options.convexTolerance > 0.0 &&
    hullDepthOfFaces(mesh) < options.convexTolerance)
  {
    hierarchy.chosenCount = 1;
    return hierarchy;
  }
  // Each count's refined cut and its score, the counts on Kerf's threads (kept once all are cut:
  // cutEnsembleHierarchy reads the kept cuts).
  const int counts = maximumCount - minimumCount + 1;
  std::vector<std::vector<int>> refinedCuts(static_cast<std::size_t>(counts));
  std::vector<double> countScores(static_cast<std::size_t>(counts));
  parallelFor(counts, [&](int c) {
    const std::size_t at = static_cast<std::size_t>(c);
    refinedCuts[at] = cutEnsembleHierarchy(surface, hierarchy, minimumCount + c, options.refinement).labels;
    countScores[at] = meanDistanceToPool(refinedCuts[at], pool);
  });
  hierarchy.refinedCuts = std::move(refinedCuts);
  hierarchy.countScores = std::move(countScores);
  hierarchy.refinedWith = options.refinement;
  hierarchy.chosenCount = minimumCount +
    static_cast<int>(
      std::min_element(hierarchy.countScores.begin(), hierarchy.countScores.end()) - hierarchy.countScores.begin());
  return hierarchy;
}

EnsembleSegmentationResult cutEnsembleHierarchy(
  const Surface& surface, const EnsembleHierarchy& hierarchy, int k, const BoundaryRefinementOptions& refinement)
{
  checkBoundaryRefinementOptions(refinement);
  const FaceGraph& graph = faceGraph(surface);
  const PartitionConsensus consensus = cutConsensusHierarchy(graph, hierarchy.consensus, k);
  const std::size_t kept = static_cast<std::size_t>(k - hierarchy.minimumCount);
  const bool scored = k >= hierarchy.minimumCount && kept < hierarchy.refinedCuts.size() &&
    refinement.bandWidth == hierarchy.refinedWith.bandWidth &&
    refinement.convexWeight == hierarchy.refinedWith.convexWeight;
  EnsembleSegmentationResult result;
  result.labels =
    scored ? hierarchy.refinedCuts[kept] : refineSegmentBoundaries(graph, consensus.labels, refinement).labels;
  result.members = hierarchy.members;
  result.atoms = hierarchy.consensus.atoms;
  result.segmentCount = 1 + *std::max_element(result.labels.begin(), result.labels.end());
  return result;
}

} // namespace kerf
