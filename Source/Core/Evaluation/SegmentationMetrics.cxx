// Segmentation metrics from an area-weighted contingency table and distances to cuts.
#include "Evaluation/SegmentationMetrics.h"

#include "Error.h"
#include "Geodesic/GraphDistance.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace kerf
{

namespace
{
// Overlap of segment i of S1 and segment j of S2: area and face count, dense or sparse.
class Contingency
{
public:
  Contingency(int rows, int columns)
    : Columns(columns)
    , Dense(static_cast<long long>(rows) * columns <= (1 << 22))
  {
    if (this->Dense)
    {
      this->Area.assign(static_cast<std::size_t>(rows) * columns, 0.0);
      this->Count.assign(static_cast<std::size_t>(rows) * columns, 0);
    }
  }

  void add(int i, int j, double area)
  {
    const long long key = static_cast<long long>(i) * this->Columns + j;
    if (this->Dense)
    {
      this->Area[static_cast<std::size_t>(key)] += area;
      ++this->Count[static_cast<std::size_t>(key)];
    }
    else
    {
      Cell& cell = this->Sparse[key];
      cell.area += area;
      ++cell.count;
    }
  }

  // Calls f(i, j, area, count) for every non-empty cell, in increasing (i, j) order for the dense
  // table and in key order for the sparse one (sorted first, for deterministic sums).
  template <typename F>
  void forEach(F f) const
  {
    if (this->Dense)
    {
      for (std::size_t key = 0; key < this->Count.size(); ++key)
      {
        if (this->Count[key] > 0)
        {
          f(static_cast<int>(key / this->Columns), static_cast<int>(key % this->Columns), this->Area[key],
            this->Count[key]);
        }
      }
      return;
    }
    std::vector<long long> keys;
    keys.reserve(this->Sparse.size());
    for (const auto& entry : this->Sparse)
    {
      keys.push_back(entry.first);
    }
    std::sort(keys.begin(), keys.end());
    for (long long key : keys)
    {
      const Cell& cell = this->Sparse.at(key);
      f(static_cast<int>(key / this->Columns), static_cast<int>(key % this->Columns), cell.area, cell.count);
    }
  }

private:
  struct Cell
  {
    double area = 0.0;
    long long count = 0;
  };
  int Columns;
  bool Dense;
  std::vector<double> Area;
  std::vector<long long> Count;
  std::unordered_map<long long, Cell> Sparse;
};

double pairs(double n)
{
  return 0.5 * n * (n - 1.0);
}

// Mean over `from` of `distance`, skipping unreachable vertices (another component).
double meanDistance(const std::vector<int>& from, const std::vector<double>& distance)
{
  double sum = 0.0;
  int count = 0;
  for (int v : from)
  {
    if (std::isfinite(distance[v]))
    {
      sum += distance[v];
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}
} // namespace

SegmentationEvaluator::SegmentationEvaluator(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  this->FaceAreas.resize(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    this->FaceAreas[f] = 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
  }
  Vector3 centroid = Vector3::Zero();
  int used = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.vertexFaces(v).empty())
    {
      centroid += mesh.point(v);
      ++used;
    }
  }
  if (used > 0)
  {
    centroid /= used;
    double sum = 0.0;
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      if (!mesh.vertexFaces(v).empty())
      {
        sum += (mesh.point(v) - centroid).norm();
      }
    }
    this->AverageRadius = sum / used;
  }
}

PreparedSegmentation SegmentationEvaluator::prepare(const std::vector<int>& labels) const
{
  if (static_cast<int>(labels.size()) != this->Mesh.faceCount())
  {
    throw Error("the segmentation has " + std::to_string(labels.size()) + " labels but the mesh has " +
      std::to_string(this->Mesh.faceCount()) + " faces");
  }
  PreparedSegmentation out;
  for (int label : labels)
  {
    if (label < -1)
    {
      throw Error("segment label " + std::to_string(label) + " is negative (only -1, unlabelled, is allowed)");
    }
    if (label >= 0)
    {
      out.originalLabels.push_back(label);
    }
  }
  std::sort(out.originalLabels.begin(), out.originalLabels.end());
  out.originalLabels.erase(std::unique(out.originalLabels.begin(), out.originalLabels.end()), out.originalLabels.end());
  out.segmentCount = static_cast<int>(out.originalLabels.size());
  out.labels.resize(labels.size());
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    out.labels[f] = labels[f] < 0
      ? -1
      : static_cast<int>(std::lower_bound(out.originalLabels.begin(), out.originalLabels.end(), labels[f]) -
          out.originalLabels.begin());
  }
  std::vector<char> onCut(this->Mesh.vertexCount(), 0);
  for (int e = 0; e < this->Mesh.edgeCount(); ++e)
  {
    if (this->Mesh.edgeFaceCount(e) < 2)
    {
      continue;
    }
    const std::array<int, 2>& faces = this->Mesh.edgeFaces(e);
    const int a = out.labels[faces[0]];
    const int b = out.labels[faces[1]];
    if (a >= 0 && b >= 0 && a != b)
    {
      onCut[this->Mesh.edgeVertices(e)[0]] = 1;
      onCut[this->Mesh.edgeVertices(e)[1]] = 1;
    }
  }
  for (int v = 0; v < this->Mesh.vertexCount(); ++v)
  {
    if (onCut[v])
    {
      out.cutVertices.push_back(v);
    }
  }
  if (!out.cutVertices.empty())
  {
    out.distanceToCut = edgeGraphDistances(this->Mesh, out.cutVertices);
  }
  return out;
}

SegmentationScores SegmentationEvaluator::compare(const PreparedSegmentation& s1, const PreparedSegmentation& s2) const
{
  if (s1.labels.size() != this->FaceAreas.size() || s2.labels.size() != this->FaceAreas.size())
  {
    throw Error("both segmentations must be prepared for this mesh");
  }
  SegmentationScores scores;
  scores.segments1 = s1.segmentCount;
  scores.segments2 = s2.segmentCount;

  // Cut discrepancy, normalised by the average radius.
  if (!s1.cutVertices.empty() && !s2.cutVertices.empty() && this->AverageRadius > 0.0)
  {
    scores.cutsCompared = true;
    scores.directionalCutDiscrepancy12 = meanDistance(s1.cutVertices, s2.distanceToCut) / this->AverageRadius;
    scores.directionalCutDiscrepancy21 = meanDistance(s2.cutVertices, s1.distanceToCut) / this->AverageRadius;
    scores.cutDiscrepancy = scores.directionalCutDiscrepancy12 + scores.directionalCutDiscrepancy21;
  }

  // Contingency table over faces labelled in both.
  const int k1 = std::max(s1.segmentCount, 1);
  const int k2 = std::max(s2.segmentCount, 1);
  Contingency table(k1, k2);
  std::vector<double> area1(k1, 0.0), area2(k2, 0.0);
  std::vector<double> count1(k1, 0.0), count2(k2, 0.0);
  double totalArea = 0.0;
  long long faces = 0;
  for (std::size_t f = 0; f < s1.labels.size(); ++f)
  {
    const int i = s1.labels[f];
    const int j = s2.labels[f];
    if (i < 0 || j < 0)
    {
      continue;
    }
    const double a = this->FaceAreas[f];
    table.add(i, j, a);
    area1[i] += a;
    area2[j] += a;
    count1[i] += 1.0;
    count2[j] += 1.0;
    totalArea += a;
    ++faces;
  }
  scores.comparedFaces = static_cast<int>(faces);
  if (faces == 0)
  {
    return scores;
  }

  // Hamming distance: each segment's best match in the other segmentation.
  std::vector<double> best1(k1, 0.0), best2(k2, 0.0);
  double samePairs = 0.0;
  double global12 = 0.0, global21 = 0.0, local = 0.0;
  table.forEach([&](int i, int j, double a, long long n) {
    best1[i] = std::max(best1[i], a);
    best2[j] = std::max(best2[j], a);
    samePairs += pairs(static_cast<double>(n));
    // Local refinement errors of a face in (i, j): |R1 \ R2| / |R1| and |R2 \ R1| / |R2|.
    const double e12 = area1[i] > 0.0 ? (area1[i] - a) / area1[i] : 0.0;
    const double e21 = area2[j] > 0.0 ? (area2[j] - a) / area2[j] : 0.0;
    global12 += a * e12;
    global21 += a * e21;
    local += a * std::min(e12, e21);
  });
  if (totalArea > 0.0)
  {
    double missing = 0.0, falseAlarm = 0.0;
    for (int j = 0; j < k2; ++j)
    {
      missing += area2[j] - best2[j];
    }
    for (int i = 0; i < k1; ++i)
    {
      falseAlarm += area1[i] - best1[i];
    }
    scores.missingRate = missing / totalArea;
    scores.falseAlarmRate = falseAlarm / totalArea;
    scores.hammingDistance = 0.5 * (scores.missingRate + scores.falseAlarmRate);
    scores.globalConsistencyError = std::min(global12, global21) / totalArea;
    scores.localConsistencyError = local / totalArea;
  }

  // Rand index from the contingency counts: pairs split in one segmentation but not the other.
  if (faces >= 2)
  {
    double rowPairs = 0.0, columnPairs = 0.0;
    for (double n : count1)
    {
      rowPairs += pairs(n);
    }
    for (double n : count2)
    {
      columnPairs += pairs(n);
    }
    scores.randIndexError = (rowPairs + columnPairs - 2.0 * samePairs) / pairs(static_cast<double>(faces));
  }
  return scores;
}

std::vector<int> matchLabels(const std::vector<int>& labels, const std::vector<int>& reference)
{
  if (labels.size() != reference.size())
  {
    throw Error("the two segmentations have different lengths");
  }
  std::map<int, std::map<int, int>> overlap;
  std::map<int, int> size;
  int fresh = 0;
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    ++overlap[labels[f]][reference[f]];
    ++size[labels[f]];
    fresh = std::max(fresh, reference[f] + 1);
  }
  std::vector<std::pair<int, int>> bySize; // (-size, label): largest first, ties by label
  for (const auto& entry : size)
  {
    bySize.emplace_back(-entry.second, entry.first);
  }
  std::sort(bySize.begin(), bySize.end());
  std::map<int, int> renumber;
  std::set<int> taken;
  for (const auto& entry : bySize)
  {
    const int label = entry.second;
    int best = -1, bestCount = 0;
    for (const auto& candidate : overlap[label])
    {
      if (candidate.first >= 0 && !taken.count(candidate.first) && candidate.second > bestCount)
      {
        best = candidate.first;
        bestCount = candidate.second;
      }
    }
    renumber[label] = label < 0 ? label : (best >= 0 ? best : fresh++);
    taken.insert(renumber[label]);
  }
  std::vector<int> out(labels.size());
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    out[f] = renumber[labels[f]];
  }
  return out;
}

SegmentationScores compareSegmentations(
  const TriangleMesh& mesh, const std::vector<int>& evaluated, const std::vector<int>& reference)
{
  const SegmentationEvaluator evaluator(mesh);
  return evaluator.compare(evaluator.prepare(evaluated), evaluator.prepare(reference));
}

} // namespace kerf
