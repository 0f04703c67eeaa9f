// Isoline extraction by chaining per-face segments through shared edges, scores, and cut sides.
#include "Harmonic/Isolines.h"

#include "Error.h"
#include "Mesh/FaceRegions.h"
#include "Mesh/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace kerf
{

namespace
{
// Crossings closer than this fraction of their edge to a vertex are placed on the vertex.
constexpr double VertexSnap = 1e-12;

// The crossing point of f = value on edge e (computed in the edge's own vertex order, so both
// faces of the edge get the same point).
Vector3 crossing(const TriangleMesh& mesh, const std::vector<double>& field, double value, int e)
{
  const std::array<int, 2>& ev = mesh.edgeVertices(e);
  const double f0 = field[ev[0]];
  const double f1 = field[ev[1]];
  // At a vertex, or within rounding of it: the vertex's own coordinates, so that every edge
  // through it gives the same point and the isoline has no vanishing segments there.
  const double t = (value - f0) / (f1 - f0);
  if (value == f0 || t <= VertexSnap)
  {
    return mesh.point(ev[0]);
  }
  if (value == f1 || t >= 1.0 - VertexSnap)
  {
    return mesh.point(ev[1]);
  }
  return mesh.point(ev[0]) + t * (mesh.point(ev[1]) - mesh.point(ev[0]));
}

// The edges where face f's corners go from below to above `value` (entry) and back (exit), in
// the face's corner order; false if the face is not crossed.
bool crossedEdges(
  const TriangleMesh& mesh, const std::vector<double>& field, double value, int f, int& entry, int& exit)
{
  const Triangle& t = mesh.triangle(f);
  const bool above[3] = { field[t[0]] >= value, field[t[1]] >= value, field[t[2]] >= value };
  if (above[0] == above[1] && above[1] == above[2])
  {
    return false;
  }
  entry = exit = -1;
  for (int k = 0; k < 3; ++k)
  {
    const bool from = above[k];
    const bool to = above[(k + 1) % 3];
    if (!from && to)
    {
      entry = mesh.faceEdge(f, k);
    }
    else if (from && !to)
    {
      exit = mesh.faceEdge(f, k);
    }
  }
  return entry >= 0 && exit >= 0;
}

// Drops zero-length segments (where the isoline passes exactly through a vertex) and measures it.
void removeRepeatedPoints(Isoline& line)
{
  const std::size_t n = line.points.size();
  if (n == 0)
  {
    return;
  }
  std::vector<Vector3> points{ line.points[0] };
  std::vector<int> faces;
  for (std::size_t i = 1; i < n; ++i)
  {
    if (line.points[i] == points.back())
    {
      continue; // segment i - 1 has zero length
    }
    faces.push_back(line.faces[i - 1]);
    points.push_back(line.points[i]);
  }
  if (line.closed)
  {
    if (points.size() > 1 && points.back() == points.front())
    {
      points.pop_back(); // the segment into it now closes the loop
    }
    else
    {
      faces.push_back(line.faces[n - 1]);
    }
  }
  line.points = std::move(points);
  line.faces = std::move(faces);
  line.length = 0.0;
  const std::size_t m = line.points.size();
  for (std::size_t i = 0; i < line.faces.size() && m > 1; ++i)
  {
    line.length += (line.points[(i + 1) % m] - line.points[i]).norm();
  }
}

double pointSegmentDistance(const Vector3& p, const Vector3& a, const Vector3& b)
{
  const Vector3 ab = b - a;
  const double lengthSquared = ab.squaredNorm();
  const double t = lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}
} // namespace

std::vector<Isoline> extractIsolines(const TriangleMesh& mesh, const std::vector<double>& field, double value)
{
  if (static_cast<int>(field.size()) != mesh.vertexCount())
  {
    throw Error("the field must have one value per vertex");
  }
  const int faces = mesh.faceCount();
  std::vector<int> entry(faces, -1), exit(faces, -1);
  std::vector<int> faceEntering(mesh.edgeCount(), -1), faceExiting(mesh.edgeCount(), -1);
  for (int f = 0; f < faces; ++f)
  {
    if (crossedEdges(mesh, field, value, f, entry[f], exit[f]))
    {
      faceEntering[entry[f]] = f;
      faceExiting[exit[f]] = f;
    }
  }
  auto next = [&](int f) { return faceEntering[exit[f]] != f ? faceEntering[exit[f]] : -1; };
  auto previous = [&](int f) { return faceExiting[entry[f]] != f ? faceExiting[entry[f]] : -1; };

  std::vector<char> visited(faces, 0);
  std::vector<Isoline> lines;
  for (int seed = 0; seed < faces; ++seed)
  {
    if (entry[seed] < 0 || visited[seed])
    {
      continue;
    }
    // Walk back to the start of an open isoline (or around a closed one).
    int start = seed;
    bool closed = false;
    for (int f = previous(seed); f >= 0; f = previous(f))
    {
      if (f == seed)
      {
        closed = true;
        break;
      }
      start = f;
    }
    if (closed)
    {
      start = seed;
    }
    Isoline line;
    line.closed = closed;
    line.points.push_back(crossing(mesh, field, value, entry[start]));
    for (int f = start; f >= 0 && !visited[f]; f = next(f))
    {
      visited[f] = 1;
      line.faces.push_back(f);
      line.points.push_back(crossing(mesh, field, value, exit[f]));
    }
    if (closed)
    {
      line.points.pop_back(); // the exit of the last face is the entry of the first
    }
    removeRepeatedPoints(line);
    if (line.points.size() >= 2 && line.length > 0.0)
    {
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

double isolineScore(const std::vector<Isoline>& isolines, const std::vector<double>& gradientMagnitudes)
{
  double weighted = 0.0, length = 0.0;
  for (const Isoline& line : isolines)
  {
    const std::size_t n = line.points.size();
    for (std::size_t i = 0; i < line.faces.size(); ++i)
    {
      const double segment = (line.points[(i + 1) % n] - line.points[i]).norm();
      weighted += segment * gradientMagnitudes[line.faces[i]];
      length += segment;
    }
  }
  return length > 0.0 ? weighted / length : 0.0;
}

std::vector<IsovalueScore> scoreIsovalues(
  const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<double>& gradientMagnitudes, int count)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.vertexFaces(v).empty())
    {
      lo = std::min(lo, field[v]);
      hi = std::max(hi, field[v]);
    }
  }
  if (count < 1 || !(hi > lo))
  {
    return {};
  }
  const double step = (hi - lo) / (count + 1);
  std::vector<IsovalueScore> scores(count);
  std::vector<double> weighted(count, 0.0);
  for (int i = 0; i < count; ++i)
  {
    scores[i].value = lo + (i + 1) * step;
  }
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const double fmin = std::min({ field[t[0]], field[t[1]], field[t[2]] });
    const double fmax = std::max({ field[t[0]], field[t[1]], field[t[2]] });
    // Face f is crossed by value_i when fmin < value_i <= fmax.
    int first = std::max(0, static_cast<int>(std::floor((fmin - lo) / step)) - 1);
    for (int i = first; i < count && scores[i].value <= fmax; ++i)
    {
      int entry, exit;
      if (!(fmin < scores[i].value) || !crossedEdges(mesh, field, scores[i].value, f, entry, exit))
      {
        continue;
      }
      const double segment =
        (crossing(mesh, field, scores[i].value, exit) - crossing(mesh, field, scores[i].value, entry)).norm();
      scores[i].length += segment;
      weighted[i] += segment * gradientMagnitudes[f];
    }
  }
  for (int i = 0; i < count; ++i)
  {
    scores[i].score = scores[i].length > 0.0 ? weighted[i] / scores[i].length : 0.0;
  }
  return scores;
}

int nearestIsoline(const std::vector<Isoline>& isolines, const std::vector<Vector3>& points)
{
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < isolines.size(); ++c)
  {
    const Isoline& line = isolines[c];
    double sum = 0.0;
    for (const Vector3& p : points)
    {
      double nearest = std::numeric_limits<double>::infinity();
      const std::size_t n = line.points.size();
      const std::size_t segments = line.closed ? n : n - 1;
      for (std::size_t i = 0; i < segments; ++i)
      {
        nearest = std::min(nearest, pointSegmentDistance(p, line.points[i], line.points[(i + 1) % n]));
      }
      sum += nearest;
    }
    const double mean = points.empty() ? 0.0 : sum / static_cast<double>(points.size());
    if (best < 0 || mean < bestDistance)
    {
      bestDistance = mean;
      best = static_cast<int>(c);
    }
  }
  return best;
}

namespace
{
// A region made only of faces a cut runs through is a sliver along the cut, not a segment: where
// the cut ends on a hole, a crossed face whose uncrossed edge is on the boundary is cut off from
// both sides. Each sliver joins the neighbouring region it shares the most edges with (the lower
// label on ties), regions with faces off the cut first; then regions are numbered again in order
// of their first face.
template <typename OnCut>
std::vector<int> mergeSlivers(const TriangleMesh& mesh, std::vector<int> labels, int regions, OnCut onCut)
{
  std::vector<char> sliver(regions, 1);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (!onCut(f))
    {
      sliver[labels[f]] = 0;
    }
  }
  if (std::find(sliver.begin(), sliver.end(), 0) == sliver.end())
  {
    return labels; // everything is on the cut: nothing to join
  }
  // Shared edge counts of each sliver with its neighbours; slivers joined repeatedly until each
  // reaches a region off the cut (a chain of slivers is resolved one link per pass).
  std::vector<int> target(regions);
  std::iota(target.begin(), target.end(), 0);
  for (bool changed = true; changed;)
  {
    changed = false;
    std::vector<std::map<int, int>> shared(regions);
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const int a = target[labels[f]];
      if (!sliver[a])
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && target[labels[g]] != a)
        {
          ++shared[a][target[labels[g]]];
        }
      }
    }
    for (int r = 0; r < regions; ++r)
    {
      if (target[r] != r || !sliver[r] || shared[r].empty())
      {
        continue;
      }
      int best = -1, bestCount = 0;
      for (const auto& [neighbour, count] : shared[r])
      {
        const bool better =
          best < 0 || (sliver[best] && !sliver[neighbour]) || (sliver[best] == sliver[neighbour] && count > bestCount);
        if (better)
        {
          best = neighbour;
          bestCount = count;
        }
      }
      while (target[best] != best)
      {
        best = target[best]; // merged earlier in this pass
      }
      if (best == r)
      {
        continue;
      }
      for (int& t : target)
      {
        t = t == r ? best : t;
      }
      changed = true;
    }
  }
  std::vector<int> renumber(regions, -1);
  int next = 0;
  for (int& label : labels)
  {
    int& number = renumber[target[label]];
    number = number < 0 ? next++ : number;
    label = number;
  }
  return labels;
}
} // namespace

std::vector<int> labelCuts(const TriangleMesh& mesh, const std::vector<FieldCut>& cuts)
{
  const int faces = mesh.faceCount();
  // Per cut: which side each face is on, and which faces hold a segment of the cut.
  std::vector<std::vector<char>> upper(cuts.size(), std::vector<char>(faces));
  std::vector<std::vector<char>> onCut(cuts.size(), std::vector<char>(faces, 0));
  for (std::size_t c = 0; c < cuts.size(); ++c)
  {
    const std::vector<double>& field = *cuts[c].field;
    for (int f = 0; f < faces; ++f)
    {
      const Triangle& t = mesh.triangle(f);
      upper[c][f] = (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0 >= cuts[c].value ? 1 : 0;
    }
    for (const Isoline* line : cuts[c].components)
    {
      for (int f : line->faces)
      {
        onCut[c][f] = 1;
      }
    }
  }
  auto separated = [&](int f, int g) {
    for (std::size_t c = 0; c < cuts.size(); ++c)
    {
      if (upper[c][f] != upper[c][g] && (onCut[c][f] || onCut[c][g]))
      {
        return true;
      }
    }
    return false;
  };
  std::vector<int> labels;
  labelFaceRegions(
    mesh, [&](int f, int k) { return !separated(f, mesh.faceNeighbor(f, k)); }, labels);
  return labels;
}

namespace
{
double distanceToPolyline(const Vector3& p, const std::vector<Vector3>& polyline)
{
  double nearest = std::numeric_limits<double>::infinity();
  if (polyline.size() == 1)
  {
    return (p - polyline[0]).norm();
  }
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
  {
    nearest = std::min(nearest, pointSegmentDistance(p, polyline[i], polyline[i + 1]));
  }
  return nearest;
}
} // namespace

std::vector<int> labelStrokeCuts(
  const TriangleMesh& mesh, const std::vector<CutWithStroke>& cuts, double supportDistance)
{
  std::vector<FieldCut> fieldCuts;
  for (const CutWithStroke& cut : cuts)
  {
    fieldCuts.push_back(cut.cut);
  }
  const std::vector<int> regions = labelCuts(mesh, fieldCuts);
  const int faces = mesh.faceCount();
  const int regionCount = faces == 0 ? 0 : *std::max_element(regions.begin(), regions.end()) + 1;

  // Per cut: the side of each face, and where its isoline runs near its stroke.
  std::vector<std::vector<char>> upper(cuts.size(), std::vector<char>(faces));
  std::vector<std::vector<signed char>> near(cuts.size(), std::vector<signed char>(faces, -1)); // -1: off the cut
  for (std::size_t c = 0; c < cuts.size(); ++c)
  {
    const FieldCut& cut = cuts[c].cut;
    const std::vector<double>& field = *cut.field;
    for (int f = 0; f < faces; ++f)
    {
      const Triangle& t = mesh.triangle(f);
      upper[c][f] = (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0 >= cut.value ? 1 : 0;
    }
    for (const Isoline* line : cut.components)
    {
      const std::size_t n = line->points.size();
      for (std::size_t i = 0; i < line->faces.size(); ++i)
      {
        const Vector3 middle = 0.5 * (line->points[i] + line->points[(i + 1) % n]);
        near[c][line->faces[i]] = distanceToPolyline(middle, cuts[c].stroke) <= supportDistance ? 1 : 0;
      }
    }
  }

  // The boundaries between regions: their length and the length a stroke supports.
  std::map<std::pair<int, int>, std::pair<double, double>> boundaries;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (mesh.edgeFaceCount(e) != 2)
    {
      continue;
    }
    const int f = mesh.edgeFaces(e)[0];
    const int g = mesh.edgeFaces(e)[1];
    if (regions[f] == regions[g])
    {
      continue;
    }
    const double length = (mesh.point(mesh.edgeVertices(e)[0]) - mesh.point(mesh.edgeVertices(e)[1])).norm();
    bool supported = false;
    for (std::size_t c = 0; c < cuts.size() && !supported; ++c)
    {
      supported = upper[c][f] != upper[c][g] && (near[c][f] == 1 || near[c][g] == 1);
    }
    auto& entry = boundaries[{ std::min(regions[f], regions[g]), std::max(regions[f], regions[g]) }];
    entry.first += length;
    entry.second += supported ? length : 0.0;
  }

  // A stroke speaks only where its cut follows it: when most of the stroke lies within
  // supportDistance of its isoline.
  std::vector<char> followed(cuts.size(), 0);
  for (std::size_t c = 0; c < cuts.size(); ++c)
  {
    int close = 0;
    for (const Vector3& p : cuts[c].stroke)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Isoline* line : cuts[c].cut.components)
      {
        const std::size_t n = line->points.size();
        for (std::size_t i = 0; i + 1 < n + (line->closed ? 1 : 0); ++i)
        {
          nearest = std::min(nearest, pointSegmentDistance(p, line->points[i], line->points[(i + 1) % n]));
        }
      }
      close += nearest <= supportDistance ? 1 : 0;
    }
    followed[c] = 2 * close > static_cast<int>(cuts[c].stroke.size()) ? 1 : 0;
  }

  // The two sides of every stroke must stay apart.
  std::vector<std::vector<int>> apart(static_cast<std::size_t>(regionCount));
  for (std::size_t c = 0; c < cuts.size(); ++c)
  {
    if (!followed[c])
    {
      continue;
    }
    const CutWithStroke& cut = cuts[c];
    for (std::size_t i = 0; i + 1 < cut.sideFaces.size(); i += 2)
    {
      // A pair counts where the cut puts its two points on different sides.
      const int a = cut.sideFaces[i], b = cut.sideFaces[i + 1];
      if (a >= 0 && b >= 0 && a < faces && b < faces && regions[a] != regions[b] && upper[c][a] != upper[c][b])
      {
        apart[regions[a]].push_back(regions[b]);
        apart[regions[b]].push_back(regions[a]);
      }
    }
  }

  struct Candidate
  {
    double support;
    double length;
    int a, b;
  };
  std::vector<Candidate> order;
  for (const auto& entry : boundaries)
  {
    order.push_back(
      { entry.second.second / entry.second.first, entry.second.first, entry.first.first, entry.first.second });
  }
  std::sort(order.begin(), order.end(), [](const Candidate& x, const Candidate& y) {
    return x.support != y.support ? x.support < y.support
      : x.length != y.length      ? x.length < y.length
                                  : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  std::vector<int> parent(static_cast<std::size_t>(regionCount));
  for (int r = 0; r < regionCount; ++r)
  {
    parent[r] = r;
  }
  for (const Candidate& candidate : order)
  {
    const int a = findRoot(parent, candidate.a);
    const int b = findRoot(parent, candidate.b);
    if (a == b)
    {
      continue;
    }
    bool forbidden = false;
    for (int other : apart[a])
    {
      forbidden = forbidden || findRoot(parent, other) == b;
    }
    if (forbidden)
    {
      continue;
    }
    const int root = std::min(a, b), child = std::max(a, b);
    parent[child] = root;
    apart[root].insert(apart[root].end(), apart[child].begin(), apart[child].end());
    apart[child].clear();
  }

  // Each side of each stroke has a home: the merged region holding most of its constraint points.
  // Small pieces between cuts that cross near a junction can hold a few points of two strokes and
  // so stay apart from both neighbours; a region that is no side's home joins the neighbour it
  // shares the longest boundary with (smallest first).
  std::vector<char> home(static_cast<std::size_t>(regionCount), 0);
  for (std::size_t c = 0; c < cuts.size(); ++c)
  {
    const CutWithStroke& cut = cuts[c];
    for (std::size_t side = 0; side < 2 && followed[c]; ++side)
    {
      std::map<int, int> count;
      for (std::size_t i = side; i < cut.sideFaces.size(); i += 2)
      {
        const int f = cut.sideFaces[i];
        if (f >= 0 && f < faces)
        {
          ++count[findRoot(parent, regions[f])];
        }
      }
      int best = -1;
      for (const auto& entry : count)
      {
        best = best < 0 || entry.second > count[best] ? entry.first : best;
      }
      if (best >= 0)
      {
        home[best] = 1;
      }
    }
  }
  std::vector<double> area(static_cast<std::size_t>(regionCount), 0.0);
  for (int f = 0; f < faces; ++f)
  {
    const Triangle& t = mesh.triangle(f);
    area[findRoot(parent, regions[f])] +=
      (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
  }
  std::vector<int> homeless;
  for (int r = 0; r < regionCount; ++r)
  {
    if (findRoot(parent, r) == r && !home[r])
    {
      homeless.push_back(r);
    }
  }
  std::stable_sort(homeless.begin(), homeless.end(), [&area](int x, int y) { return area[x] < area[y]; });
  for (int r : homeless)
  {
    std::map<int, double> neighbours;
    const int root = findRoot(parent, r);
    for (const auto& entry : boundaries)
    {
      const int a = findRoot(parent, entry.first.first);
      const int b = findRoot(parent, entry.first.second);
      if (a != b && (a == root || b == root))
      {
        neighbours[a == root ? b : a] += entry.second.first;
      }
    }
    int best = -1;
    for (const auto& neighbour : neighbours)
    {
      best = best < 0 || neighbour.second > neighbours[best] ? neighbour.first : best;
    }
    if (best >= 0)
    {
      parent[root] = best;
    }
  }

  // Merged regions, numbered in order of their first face.
  std::vector<int> number(static_cast<std::size_t>(regionCount), -1);
  std::vector<int> labels(static_cast<std::size_t>(faces));
  int next = 0;
  for (int f = 0; f < faces; ++f)
  {
    const int root = findRoot(parent, regions[f]);
    if (number[root] < 0)
    {
      number[root] = next++;
    }
    labels[f] = number[root];
  }
  return labels;
}

std::vector<int> labelCutSides(
  const TriangleMesh& mesh, const std::vector<double>& field, double value, const std::vector<const Isoline*>& cut)
{
  std::vector<int> labels = labelCuts(mesh, { FieldCut{ &field, value, cut } });
  std::vector<char> onCut(static_cast<std::size_t>(mesh.faceCount()), 0);
  for (const Isoline* line : cut)
  {
    for (int f : line->faces)
    {
      onCut[f] = 1;
    }
  }
  const int regions = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  return mergeSlivers(mesh, std::move(labels), regions, [&](int f) { return onCut[f] != 0; });
}

} // namespace kerf
