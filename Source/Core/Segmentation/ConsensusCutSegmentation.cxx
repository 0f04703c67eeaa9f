// Consensus cuts: feature points, unit-current harmonic fields, isoline candidates, grouping and greedy selection.
#include "Segmentation/ConsensusCutSegmentation.h"

#include "Error.h"
#include "Geodesic/GraphDistance.h"
#include "Harmonic/FieldGradient.h"
#include "Harmonic/Isolines.h"
#include "Harmonic/SparseCholesky.h"
#include "Mesh/MeshValidation.h"
#include "Session/Surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

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
  double score = 0.0;
  int field = -1;
};

// A group of candidates that split the surface the same way.
struct ConsensusCut
{
  int representative = -1; // the best-scoring candidate
  double bestScore = 0.0;
  std::vector<int> fields; // distinct fields that found it
  double rank = 0.0;
};

double symmetricDifferenceArea(const Bits& a, const Bits& b, const std::vector<double>& area)
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
  }
  return sum;
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
    const std::vector<double> d = edgeGraphDistances(mesh, { next });
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      distance[v] = std::min(distance[v], d[v]);
    }
  }
  return points;
}

// The potential of a unit source at each feature point, with the sink at a ground vertex
// (L_rr G = e_i on the other vertices; the ground and unused vertices hold 0).
std::vector<std::vector<double>> unitPotentials(const TriangleMesh& mesh, const std::vector<double>& weights,
  const std::vector<int>& sources)
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
  std::sort(sorted.begin(), sorted.end());
  const std::size_t last = sorted.size() - 1;
  const double lo = sorted[static_cast<std::size_t>(std::floor(quantile * last))];
  const double hi = sorted[static_cast<std::size_t>(std::ceil((1.0 - quantile) * last))];
  for (double& value : field)
  {
    value = std::clamp(value, lo, hi);
  }
  return field;
}

ConsensusCutResult segmentConnected(const Surface& surface, int k, const ConsensusCutOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  const FaceGraph graph(mesh);
  const int n = graph.faceCount();
  ConsensusCutResult result;
  if (k == 1)
  {
    result.labels.assign(n, 0);
    return result;
  }
  const int pointCount = std::min(options.maximumFeaturePoints, k + options.extraFeaturePoints);
  const std::vector<int> points = farthestPoints(mesh, std::max(2, pointCount));
  result.featurePoints = static_cast<int>(points.size());
  LaplacianWeightOptions weightOptions;
  weightOptions.weighting = options.weighting;
  const std::vector<std::vector<double>> potentials =
    unitPotentials(mesh, surface.laplacianWeights(weightOptions).weights, points);

  const std::size_t words = (static_cast<std::size_t>(n) + 63) / 64;
  const double minimumArea = options.minimumSegmentArea * graph.totalArea();
  std::vector<Candidate> candidates;
  std::vector<double> sorted;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    for (std::size_t j = i + 1; j < points.size(); ++j)
    {
      const int fieldIndex = result.fields++;
      const std::vector<double> field = clippedField(mesh, potentials[i], potentials[j], options.clipQuantile, sorted);
      const std::vector<double> gradient = faceGradientMagnitudes(mesh, field);
      const std::vector<IsovalueScore> scores = scoreIsovalues(mesh, field, gradient, options.isovaluesPerField);
      for (std::size_t s = 0; s < scores.size(); ++s)
      {
        // Peaks of the score along the isovalues.
        const double left = s > 0 ? scores[s - 1].score : 0.0;
        const double right = s + 1 < scores.size() ? scores[s + 1].score : 0.0;
        if (!(scores[s].score > left && scores[s].score >= right))
        {
          continue;
        }
        const std::vector<Isoline> isolines = extractIsolines(mesh, field, scores[s].value);
        for (const Isoline& line : isolines)
        {
          const std::vector<int> sides = labelCutSides(mesh, field, scores[s].value, { &line });
          const int regions = *std::max_element(sides.begin(), sides.end()) + 1;
          if (regions != 2)
          {
            continue; // a loop that does not split the surface (around a handle)
          }
          double area0 = 0.0;
          for (int f = 0; f < n; ++f)
          {
            area0 += sides[f] == 0 ? graph.area(f) : 0.0;
          }
          const int smaller = area0 <= 0.5 * graph.totalArea() ? 0 : 1;
          Candidate candidate;
          candidate.sideArea = smaller == 0 ? area0 : graph.totalArea() - area0;
          if (candidate.sideArea < minimumArea)
          {
            continue;
          }
          candidate.side.assign(words, 0);
          for (int f = 0; f < n; ++f)
          {
            if (sides[f] == smaller)
            {
              candidate.side[static_cast<std::size_t>(f) / 64] |= std::uint64_t(1) << (f % 64);
            }
          }
          candidate.score = isolineScore({ line }, gradient);
          candidate.field = fieldIndex;
          candidates.push_back(std::move(candidate));
        }
      }
    }
  }
  result.candidates = static_cast<int>(candidates.size());

  // Group candidates that split the surface alike, best score first.
  std::vector<int> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return candidates[a].score > candidates[b].score; });
  std::vector<ConsensusCut> cuts;
  for (int c : order)
  {
    const Candidate& candidate = candidates[c];
    ConsensusCut* home = nullptr;
    for (ConsensusCut& cut : cuts)
    {
      const Candidate& r = candidates[cut.representative];
      const double tolerance = options.sameCutTolerance * std::min(r.sideArea, candidate.sideArea);
      if (std::abs(r.sideArea - candidate.sideArea) <= tolerance &&
        symmetricDifferenceArea(r.side, candidate.side, graph.areas()) <= tolerance)
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
    if (std::find(home->fields.begin(), home->fields.end(), candidate.field) == home->fields.end())
    {
      home->fields.push_back(candidate.field);
    }
  }
  for (ConsensusCut& cut : cuts)
  {
    cut.rank = cut.bestScore * std::pow(static_cast<double>(cut.fields.size()), options.voteExponent);
  }
  std::stable_sort(cuts.begin(), cuts.end(), [](const ConsensusCut& a, const ConsensusCut& b) { return a.rank > b.rank; });
  result.consensusCuts = static_cast<int>(cuts.size());

  // Greedy selection: each cut splits the current segments by its side; refused when a segment
  // would fall below the minimum area or the count would pass k.
  std::vector<int> labels(n, 0);
  int segments = 1;
  std::vector<int> next(n);
  std::vector<double> segmentArea;
  for (const ConsensusCut& cut : cuts)
  {
    if (segments >= k)
    {
      break;
    }
    const Bits& side = candidates[cut.representative].side;
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
    if (count == segments || count > k ||
      *std::min_element(segmentArea.begin(), segmentArea.end()) < minimumArea)
    {
      continue;
    }
    labels.swap(next);
    segments = count;
    ++result.chosenCuts;
  }
  result.labels = finalizeSegments(graph, labels, k);
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
    !(options.voteExponent >= 0.0 && std::isfinite(options.voteExponent)))
  {
    throw Error("a consensus-cut option is out of range (clip quantile in [0, 0.5), tolerance in [0, 1], "
                "minimum area in [0, 1), vote exponent >= 0)");
  }
  const MeshReport report = inspectMesh(mesh);
  if (report.nonManifoldEdges > 0 || report.inconsistentEdges > 0)
  {
    throw Error("consensus cuts need an edge-manifold, consistently oriented surface (" +
      std::to_string(report.nonManifoldEdges) + " non-manifold and " + std::to_string(report.inconsistentEdges) +
      " inconsistently oriented edges)");
  }
  const FaceGraph graph(mesh);
  if (graph.componentCount() == 1)
  {
    return segmentConnected(surface, k, options);
  }
  ConsensusCutResult result;
  result.labels = segmentComponents(graph, k, [&](const TriangleMesh& part, int partK) {
    const Surface partSurface(part);
    const ConsensusCutResult partResult = segmentConnected(partSurface, partK, options);
    result.featurePoints += partResult.featurePoints;
    result.fields += partResult.fields;
    result.candidates += partResult.candidates;
    result.consensusCuts += partResult.consensusCuts;
    result.chosenCuts += partResult.chosenCuts;
    return partResult.labels;
  });
  return result;
}

} // namespace kerf
