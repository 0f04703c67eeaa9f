// Consensus cuts: feature points, unit-current harmonic fields, isoline candidates, grouping and greedy selection.
#include "Segmentation/ConsensusCutSegmentation.h"

#include "CacheKey.h"
#include "Error.h"
#include "Geodesic/GraphDistance.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshValidation.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/SparseCholesky.h"
#include "Segmentation/RandomWalk.h"
#include "Segmentation/SegmentSpines.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

namespace kerf
{

namespace
{
using Bits = std::vector<std::uint64_t>;

// One candidate cut: the side it splits off (the smaller by area) and its score.
struct Candidate
{
  Bits side;
  double sideArea = 0.0;
  Vector3 centroid = Vector3::Zero(); ///< of the side, area-weighted
  double extent = 0.0;                ///< the side's bounding-box diagonal
  double score = 0.0;
};

// A group of candidates that split the surface the same way.
struct ConsensusCut
{
  int representative = -1; // the best-scoring candidate
  double bestScore = 0.0;
  std::vector<int> fields; // distinct fields that found it
  double rank = 0.0;
};

// The grouped candidate cuts, best rank first: the side each splits off, and the counts reported.
struct RankedCuts
{
  std::vector<Bits> sides;
  int featurePoints = 0;
  int fields = 0;
  int candidates = 0;
  int consensusCuts = 0;
};

// Whether the faces on one side of a and not of b, or of b and not of a, have at most `tolerance`
// area. The sum of non-negative areas only grows, so it stops as soon as it passes the tolerance.
bool symmetricDifferenceWithin(const Bits& a, const Bits& b, const std::vector<double>& area, double tolerance)
{
  double sum = 0.0;
  for (std::size_t w = 0; w < a.size(); ++w)
  {
    std::uint64_t x = a[w] ^ b[w];
    while (x)
    {
      const int bit = __builtin_ctzll(x);
      sum += area[w * 64 + static_cast<std::size_t>(bit)];
      x &= x - 1;
    }
    if (sum > tolerance)
    {
      return false;
    }
  }
  return true;
}

// Feature points: farthest-point sampling along the edges, starting from the vertex farthest
// from the first used vertex.
std::vector<int> farthestPoints(const TriangleMesh& mesh, int count)
{
  int start = 0;
  while (start < mesh.vertexCount() && mesh.vertexFaces(start).empty())
  {
    ++start;
  }
  auto farthest = [&mesh](const std::vector<double>& d) {
    int best = -1;
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      if (std::isfinite(d[v]) && !mesh.vertexFaces(v).empty() && (best < 0 || d[v] > d[best]))
      {
        best = v;
      }
    }
    return best;
  };
  std::vector<int> points{ farthest(edgeGraphDistances(mesh, { start })) };
  std::vector<double> distance = edgeGraphDistances(mesh, points);
  while (static_cast<int>(points.size()) < count)
  {
    const int next = farthest(distance);
    if (next < 0 || distance[next] <= 0.0)
    {
      break;
    }
    points.push_back(next);
    lowerEdgeGraphDistances(mesh, next, distance);
  }
  return points;
}

// The potential of a unit source at each feature point, with the sink at a ground vertex
// (L_rr G = e_i on the other vertices; the ground and unused vertices hold 0).
std::vector<std::vector<double>> unitPotentials(
  const TriangleMesh& mesh, const std::vector<double>& weights, const std::vector<int>& sources)
{
  const int n = mesh.vertexCount();
  const Eigen::SparseMatrix<double> laplacian = assembleLaplacian(mesh, weights);
  std::vector<int> reduced(n, -1);
  int ground = -1, free = 0;
  for (int v = 0; v < n; ++v)
  {
    if (mesh.vertexFaces(v).empty())
    {
      continue;
    }
    if (ground < 0)
    {
      ground = v;
      continue;
    }
    reduced[v] = free++;
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < laplacian.outerSize(); ++k)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, k); it; ++it)
    {
      const int r = reduced[it.row()], c = reduced[it.col()];
      if (r >= 0 && c >= 0 && r >= c)
      {
        entries.emplace_back(r, c, it.value());
      }
    }
  }
  Eigen::SparseMatrix<double> system(free, free);
  system.setFromTriplets(entries.begin(), entries.end());
  SparseCholesky cholesky;
  if (!cholesky.factor(system))
  {
    throw Error("the concavity-aware Laplacian could not be factored (is the surface connected?)");
  }
  std::vector<std::vector<double>> potentials;
  for (int s : sources)
  {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free);
    if (reduced[s] >= 0)
    {
      rhs[reduced[s]] = 1.0;
    }
    const Eigen::VectorXd x = cholesky.solve(rhs);
    std::vector<double> potential(n, 0.0);
    for (int v = 0; v < n; ++v)
    {
      if (reduced[v] >= 0)
      {
        potential[v] = x[reduced[v]];
      }
    }
    potentials.push_back(std::move(potential));
  }
  return potentials;
}

// The field f_ij = G_i - G_j clipped to its quantiles (the peaks at the two points cut off).
std::vector<double> clippedField(const TriangleMesh& mesh, const std::vector<double>& gi, const std::vector<double>& gj,
  double quantile, std::vector<double>& sorted)
{
  std::vector<double> field(gi.size());
  sorted.clear();
  for (std::size_t v = 0; v < gi.size(); ++v)
  {
    field[v] = gi[v] - gj[v];
    if (!mesh.vertexFaces(static_cast<int>(v)).empty())
    {
      sorted.push_back(field[v]);
    }
  }
  const std::size_t last = sorted.size() - 1;
  const auto low = sorted.begin() + static_cast<std::ptrdiff_t>(std::floor(quantile * last));
  const auto high = sorted.begin() + static_cast<std::ptrdiff_t>(std::ceil((1.0 - quantile) * last));
  std::nth_element(sorted.begin(), low, sorted.end());
  const double lo = *low;
  std::nth_element(low, high, sorted.end());
  const double hi = *high;
  for (double& value : field)
  {
    value = std::clamp(value, lo, hi);
  }
  return field;
}

// The smaller of the two sides an isoline component splits the surface into, found by flooding
// from the component's faces with a stop at half the area, so that it costs the smaller side.
class SideFinder
{
public:
  explicit SideFinder(const FaceGraph& graph)
    : Graph(graph)
    , Neighbours(graph.faceCount())
    , FaceMeans(graph.faceCount(), 0.0)
    , OnCut(graph.faceCount(), 0)
    , Visited(graph.faceCount(), 0)
    , Owner(graph.faceCount(), 0)
  {
    // The faces across each face's dual edges in faceEdges order (-1: none), packed so that the
    // floods read 12 bytes per face instead of whole dual edges.
    for (int f = 0; f < graph.faceCount(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int e = graph.faceEdges(f)[k];
        this->Neighbours[f][k] = e >= 0 ? graph.opposite(e, f) : -1;
      }
    }
  }

  /// The field whose isolines the following calls split the surface by: its mean per face.
  void setField(const std::vector<double>& field)
  {
    const TriangleMesh& mesh = this->Graph.mesh();
    for (int f = 0; f < this->Graph.faceCount(); ++f)
    {
      const Triangle& t = mesh.triangle(f);
      this->FaceMeans[f] = (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0;
    }
  }

  /// False when the component does not split the surface in two (the field of setField).
  bool smallerSide(double value, const Isoline& line, Candidate& candidate)
  {
    ++this->CutStamp;
    for (int f : line.faces)
    {
      this->OnCut[f] = this->CutStamp;
    }
    const std::vector<double>& means = this->FaceMeans;
    auto upper = [&means, value](int f) { return means[f] >= value; };
    const int first = line.faces.front();
    const bool firstUpper = upper(first);
    int second = -1; // a face across the cut from the first one's side
    for (int f : line.faces)
    {
      if (upper(f) != firstUpper)
      {
        second = f;
        break;
      }
      for (int g : this->Neighbours[f])
      {
        if (g >= 0 && upper(g) != firstUpper)
        {
          second = g;
          break;
        }
      }
      if (second >= 0)
      {
        break;
      }
    }
    if (second < 0)
    {
      return false;
    }
    // Both sides flood in turns, one face at a time; the first to finish is the smaller.
    const int stamp = ++this->VisitStamp;
    std::array<std::vector<int>, 2> queues{ { { first }, { second } } };
    std::array<std::size_t, 2> next{ { 0, 0 } };
    std::array<double, 2> areas{ { 0.0, 0.0 } };
    this->Visited[first] = stamp;
    this->Visited[second] = stamp;
    this->Owner[first] = 0;
    this->Owner[second] = 1;
    const double half = 0.5 * this->Graph.totalArea();
    for (int turn = 0;; turn = 1 - turn)
    {
      std::vector<int>& queue = queues[turn];
      if (next[turn] == queue.size())
      {
        if (areas[turn] > half)
        {
          return false; // the cut does not split the surface: one side reached the other
        }
        this->fill(queue, candidate);
        candidate.sideArea = areas[turn];
        return true;
      }
      const int f = queue[next[turn]++];
      areas[turn] += this->Graph.area(f);
      const bool fUpper = upper(f);
      for (int g : this->Neighbours[f])
      {
        if (g < 0)
        {
          continue;
        }
        const bool cutHere = this->OnCut[f] == this->CutStamp || this->OnCut[g] == this->CutStamp;
        if (cutHere && upper(g) != fUpper)
        {
          continue;
        }
        if (this->Visited[g] == stamp)
        {
          if (this->Owner[g] != turn)
          {
            return false; // the two sides meet: the cut does not split the surface
          }
          continue;
        }
        this->Visited[g] = stamp;
        this->Owner[g] = static_cast<char>(turn);
        queue.push_back(g);
      }
    }
  }

private:
  void fill(const std::vector<int>& faces, Candidate& candidate) const
  {
    candidate.side.assign((static_cast<std::size_t>(this->Graph.faceCount()) + 63) / 64, 0);
    Vector3 low = this->Graph.centroid(faces.front()), high = low;
    candidate.centroid.setZero();
    double area = 0.0;
    for (int f : faces)
    {
      candidate.side[static_cast<std::size_t>(f) / 64] |= std::uint64_t(1) << (f % 64);
      candidate.centroid += this->Graph.area(f) * this->Graph.centroid(f);
      area += this->Graph.area(f);
      low = low.cwiseMin(this->Graph.centroid(f));
      high = high.cwiseMax(this->Graph.centroid(f));
    }
    candidate.centroid /= std::max(area, std::numeric_limits<double>::min());
    candidate.extent = (high - low).norm();
  }

  const FaceGraph& Graph;
  std::vector<std::array<int, 3>> Neighbours;
  std::vector<double> FaceMeans;
  std::vector<int> OnCut;
  std::vector<int> Visited;
  std::vector<char> Owner;
  int CutStamp = 0;
  int VisitStamp = 0;
};

// Steps (1)-(3): the feature points, their potentials and each pair's candidate cuts. A count of p
// feature points takes the first p of the farthest-point sampling, which adds one point at a time,
// so the sampling runs once for options.maximumFeaturePoints and every count shares the pairs
// among its points; each pair's candidates are found when first asked for, then kept.
class FieldCandidates
{
public:
  FieldCandidates(const Surface& surface, const ConsensusCutOptions& options)
    : Owner(&surface)
    , Options(options)
    , Sides(faceGraph(surface))
  {
    const TriangleMesh& mesh = surface.mesh();
    this->Points = farthestPoints(mesh, std::max(2, options.maximumFeaturePoints));
    LaplacianWeightOptions weightOptions;
    weightOptions.weighting = options.weighting;
    this->Potentials = unitPotentials(mesh, surface.laplacianWeights(weightOptions).weights, this->Points);
    const std::size_t p = this->Points.size();
    this->Pairs.resize(p * p);
    this->Found.assign(p * p, 0);
  }

  int pointCount() const { return static_cast<int>(this->Points.size()); }

  /// The candidates of field f_ij (i < j).
  const std::vector<Candidate>& pair(int i, int j) const
  {
    const std::size_t slot = static_cast<std::size_t>(i) * this->Points.size() + static_cast<std::size_t>(j);
    if (!this->Found[slot])
    {
      this->Pairs[slot] = this->find(i, j);
      this->Found[slot] = 1;
    }
    return this->Pairs[slot];
  }

private:
  std::vector<Candidate> find(int i, int j) const
  {
    const TriangleMesh& mesh = this->Owner->mesh();
    const FaceGraph& graph = faceGraph(*this->Owner);
    const ConsensusCutOptions& options = this->Options;
    const double minimumArea = options.minimumSegmentArea * graph.totalArea();
    SideFinder& sides = this->Sides;
    std::vector<Candidate> candidates;
    const std::vector<double> field =
      clippedField(mesh, this->Potentials[i], this->Potentials[j], options.clipQuantile, this->Sorted);
    const std::vector<double> gradient = faceGradientMagnitudes(mesh, field);
    const std::vector<IsovalueScore> scores = scoreIsovalues(mesh, field, gradient, options.isovaluesPerField);
    sides.setField(field);
    // The peaks of the score along the isovalues, the strongest first (score times length^gamma).
    std::vector<std::pair<double, std::size_t>> peaks;
    for (std::size_t s = 0; s < scores.size(); ++s)
    {
      const double left = s > 0 ? scores[s - 1].score : 0.0;
      const double right = s + 1 < scores.size() ? scores[s + 1].score : 0.0;
      if (scores[s].score > left && scores[s].score >= right)
      {
        peaks.push_back({ -scores[s].score * std::pow(scores[s].length, options.lengthExponent), s });
      }
    }
    std::sort(peaks.begin(), peaks.end());
    peaks.resize(std::min<std::size_t>(peaks.size(), static_cast<std::size_t>(options.peaksPerField)));
    for (const auto& peak : peaks)
    {
      const std::size_t s = peak.second;
      const std::vector<Isoline> isolines = extractIsolines(mesh, field, scores[s].value);
      for (const Isoline& line : isolines)
      {
        Candidate candidate;
        if (!sides.smallerSide(scores[s].value, line, candidate) || candidate.sideArea < minimumArea)
        {
          continue;
        }
        // Unit current: score x length is the cut's mean resistance per unit length.
        candidate.score = isolineScore({ line }, gradient) * std::pow(line.length, options.lengthExponent);
        candidates.push_back(std::move(candidate));
      }
    }
    return candidates;
  }

  const Surface* Owner;
  ConsensusCutOptions Options;
  std::vector<int> Points;
  std::vector<std::vector<double>> Potentials;
  mutable std::vector<std::vector<Candidate>> Pairs;
  mutable std::vector<char> Found;
  mutable SideFinder Sides;           // scratch of the floods, shared by the pairs
  mutable std::vector<double> Sorted; // scratch of the quantiles
};

// The key of every option the candidates and their ranking read (the walk's is applied after).
std::string rankingKey(const ConsensusCutOptions& options)
{
  return "weighting=" + std::to_string(static_cast<int>(options.weighting)) +
    " points=" + std::to_string(options.maximumFeaturePoints) +
    " isovalues=" + std::to_string(options.isovaluesPerField) + " peaks=" + std::to_string(options.peaksPerField) +
    " clip=" + cacheKey(options.clipQuantile) + " same=" + cacheKey(options.sameCutTolerance) +
    " area=" + cacheKey(options.minimumSegmentArea) + " length=" + cacheKey(options.lengthExponent) +
    " areaExponent=" + cacheKey(options.areaExponent) + " vote=" + cacheKey(options.voteExponent);
}

// Step (4) for `pointCount` feature points: the candidate cuts of every pair's field, grouped and
// ranked. They depend on k only through the feature-point count, so a surface keeps them
// (Surface::derived) and the ensemble choosing its count computes them once for the counts that
// share it.
RankedCuts rankCuts(const Surface& surface, int pointCount, const ConsensusCutOptions& options)
{
  const FaceGraph& graph = faceGraph(surface);
  const FieldCandidates& found = surface.derived<FieldCandidates>(
    "consensus-cut-candidates:" + rankingKey(options), [&] { return FieldCandidates(surface, options); });
  RankedCuts ranked;
  const int points = std::min(std::max(2, pointCount), found.pointCount());
  ranked.featurePoints = points;
  // The candidates stay where they were found; fieldOf numbers the fields of this count.
  std::vector<const Candidate*> candidates;
  std::vector<int> fieldOf;
  for (int i = 0; i < points; ++i)
  {
    for (int j = i + 1; j < points; ++j)
    {
      const int fieldIndex = ranked.fields++;
      for (const Candidate& candidate : found.pair(i, j))
      {
        candidates.push_back(&candidate);
        fieldOf.push_back(fieldIndex);
      }
    }
  }
  ranked.candidates = static_cast<int>(candidates.size());

  // Group candidates that split the surface alike, best score first.
  std::vector<int> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [&](int a, int b) { return candidates[a]->score > candidates[b]->score; });
  std::vector<ConsensusCut> cuts;
  for (int c : order)
  {
    const Candidate& candidate = *candidates[c];
    ConsensusCut* home = nullptr;
    for (ConsensusCut& cut : cuts)
    {
      const Candidate& r = *candidates[cut.representative];
      const double tolerance = options.sameCutTolerance * std::min(r.sideArea, candidate.sideArea);
      if (std::abs(r.sideArea - candidate.sideArea) <= tolerance &&
        (r.centroid - candidate.centroid).norm() <= options.sameCutTolerance * std::max(r.extent, candidate.extent) &&
        symmetricDifferenceWithin(r.side, candidate.side, graph.areas(), tolerance))
      {
        home = &cut;
        break;
      }
    }
    if (!home)
    {
      cuts.push_back({ c, candidate.score, {}, 0.0 });
      home = &cuts.back();
    }
    if (std::find(home->fields.begin(), home->fields.end(), fieldOf[c]) == home->fields.end())
    {
      home->fields.push_back(fieldOf[c]);
    }
  }
  for (ConsensusCut& cut : cuts)
  {
    cut.rank = cut.bestScore * std::pow(static_cast<double>(cut.fields.size()), options.voteExponent) *
      std::pow(candidates[cut.representative]->sideArea / graph.totalArea(), options.areaExponent);
  }
  std::stable_sort(
    cuts.begin(), cuts.end(), [](const ConsensusCut& a, const ConsensusCut& b) { return a.rank > b.rank; });
  ranked.consensusCuts = static_cast<int>(cuts.size());
  for (const ConsensusCut& cut : cuts)
  {
    ranked.sides.push_back(candidates[cut.representative]->side);
  }
  return ranked;
}

const RankedCuts& rankedCuts(const Surface& surface, int pointCount, const ConsensusCutOptions& options)
{
  return surface.derived<RankedCuts>("consensus-cuts:count=" + std::to_string(pointCount) + " " + rankingKey(options),
    [&] { return rankCuts(surface, pointCount, options); });
}

ConsensusCutResult segmentConnected(const Surface& surface, int k, const ConsensusCutOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  const FaceGraph& graph = faceGraph(surface);
  const int n = graph.faceCount();
  ConsensusCutResult result;
  if (k == 1)
  {
    result.labels.assign(n, 0);
    return result;
  }
  const int pointCount = std::min(options.maximumFeaturePoints, k + options.extraFeaturePoints);
  const RankedCuts& ranked = rankedCuts(surface, pointCount, options);
  result.featurePoints = ranked.featurePoints;
  result.fields = ranked.fields;
  result.candidates = ranked.candidates;
  result.consensusCuts = ranked.consensusCuts;
  const double minimumArea = options.minimumSegmentArea * graph.totalArea();
  LaplacianWeightOptions weightOptions;
  weightOptions.weighting = options.weighting;

  // Greedy selection: each cut splits the current segments by its side; refused when a segment
  // would fall below the minimum area or the count would pass k.
  std::vector<int> labels(n, 0);
  int segments = 1;
  std::vector<int> next(n);
  std::vector<double> segmentArea;
  for (const Bits& side : ranked.sides)
  {
    if (segments >= k)
    {
      break;
    }
    std::vector<int> map(static_cast<std::size_t>(segments) * 2, -1);
    int count = 0;
    segmentArea.clear();
    for (int f = 0; f < n; ++f)
    {
      const int in = (side[static_cast<std::size_t>(f) / 64] >> (f % 64)) & 1;
      int& slot = map[static_cast<std::size_t>(labels[f]) * 2 + static_cast<std::size_t>(in)];
      if (slot < 0)
      {
        slot = count++;
        segmentArea.push_back(0.0);
      }
      next[f] = slot;
      segmentArea[slot] += graph.area(f);
    }
    if (count == segments || count > k || *std::min_element(segmentArea.begin(), segmentArea.end()) < minimumArea)
    {
      continue;
    }
    labels.swap(next);
    segments = count;
    ++result.chosenCuts;
  }
  result.labels = finalizeSegments(graph, labels, k);
  if (options.walkDepth > 0.0)
  {
    // Step (6): the segments' spines seed random walks, each face to its most probable segment.
    const SpineWalk walk = walkFromSpines(mesh, surface.laplacianWeights(weightOptions).weights,
      segmentSpines(mesh, result.labels, options.walkDepth), result.labels);
    result.walkedFaces = walk.changedFaces;
    result.labels = finalizeSegments(graph, walk.faceLabels, k);
  }
  return result;
}
} // namespace

ConsensusCutResult segmentByConsensusCuts(const Surface& surface, int k, const ConsensusCutOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkSegmentCount(k, mesh.faceCount());
  if (options.extraFeaturePoints < 0 || options.maximumFeaturePoints < 2 || options.isovaluesPerField < 1)
  {
    throw Error("consensus cuts need at least 2 feature points, no negative extra points and at least 1 isovalue");
  }
  if (!(options.clipQuantile >= 0.0 && options.clipQuantile < 0.5) ||
    !(options.sameCutTolerance >= 0.0 && options.sameCutTolerance <= 1.0) ||
    !(options.minimumSegmentArea >= 0.0 && options.minimumSegmentArea < 1.0) ||
    !(options.voteExponent >= 0.0 && std::isfinite(options.voteExponent)) ||
    !(options.walkDepth >= 0.0 && options.walkDepth <= 1.0))
  {
    throw Error("a consensus-cut option is out of range (clip quantile in [0, 0.5), tolerance in [0, 1], "
                "minimum area in [0, 1), vote exponent >= 0, walk depth in [0, 1])");
  }
  requireOrientedManifold(mesh, "consensus cut segmentation");
  ConsensusCutResult result;
  result.labels = segmentSurfaceComponents(surface, k, [&](const Surface& part, int partK) {
    const ConsensusCutResult partResult = segmentConnected(part, partK, options);
    result.featurePoints += partResult.featurePoints;
    result.fields += partResult.fields;
    result.candidates += partResult.candidates;
    result.consensusCuts += partResult.consensusCuts;
    result.chosenCuts += partResult.chosenCuts;
    result.walkedFaces += partResult.walkedFaces;
    return partResult.labels;
  });
  return result;
}

} // namespace kerf
