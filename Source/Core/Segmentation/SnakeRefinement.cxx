// Snakes on a mesh from a labelling: vertex labels and one snaxel per cut edge, slid, split and edited (Ji et al. 2006,
// section 5).
#include "Segmentation/SnakeRefinement.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshValidation.h"
#include "Segmentation/IsophoticMetric.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace kerf
{

namespace
{
constexpr double Pi = 3.14159265358979323846;
// A vertex snaxel whose angle is this close to pi is straight: no split.
constexpr double StraightAngle = Pi - 0.05;

std::string numberText(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

// The angle at `at` between the directions to `a` and to `b`, projected onto the plane of `normal`
// (unprojected where the normal is zero); pi where a direction vanishes.
double tangentAngle(const Vector3& a, const Vector3& at, const Vector3& b, const Vector3& normal)
{
  Vector3 u = a - at, w = b - at;
  u -= u.dot(normal) * normal;
  w -= w.dot(normal) * normal;
  const double scale = std::max(u.squaredNorm(), w.squaredNorm());
  if (!(u.squaredNorm() > 1e-24 * scale) || !(w.squaredNorm() > 1e-24 * scale) || scale == 0.0)
  {
    return Pi;
  }
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

// The face's corner order position of vertex v, or -1.
int cornerOf(const Triangle& t, int v)
{
  return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
}
} // namespace

struct BoundarySnake::Chain
{
  std::vector<int> edges; ///< cut edges in the order the snake passes them
  int startFace = -1;     ///< a face where three labels meet before the first snaxel, or -1
  int endFace = -1;       ///< the same after the last snaxel
  bool closed = false;
};

BoundarySnake::BoundarySnake(std::shared_ptr<const Surface> surface, const std::vector<int>& faceLabels)
  : SharedSurface(std::move(surface))
  , Mesh(SharedSurface->mesh())
  , Normals(SharedSurface->descriptors().normals)
{
  const TriangleMesh& mesh = this->Mesh;
  if (static_cast<int>(faceLabels.size()) != mesh.faceCount())
  {
    throw Error("there are " + std::to_string(faceLabels.size()) + " face labels for " +
      std::to_string(mesh.faceCount()) + " faces");
  }
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (!mesh.isManifoldEdge(e))
    {
      throw Error("edge " + std::to_string(e) + " is shared by " + std::to_string(mesh.edgeFaceCount(e)) +
        " triangles; snakes need a manifold surface");
    }
  }
  // A vertex takes the label its faces share, or the smallest of theirs: the snake then passes
  // through every vertex of the labelling's boundary.
  this->Labels.assign(static_cast<std::size_t>(mesh.vertexCount()), -1);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const IndexRange faces = mesh.vertexFaces(v);
    if (!faces.empty())
    {
      int label = faceLabels[faces[0]];
      for (int f : faces)
      {
        label = std::min(label, faceLabels[f]);
      }
      this->Labels[v] = label;
    }
  }
  // A vertex none of whose neighbours shares its label, all of them sharing another, holds no face
  // of its own (its faces' other corners outvote it): it takes its neighbours' label, so that no
  // snake loops around a single vertex.
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const IndexRange neighbors = mesh.vertexNeighbors(v);
    if (neighbors.empty() || this->Labels[v] < 0)
    {
      continue;
    }
    const int other = this->Labels[neighbors[0]];
    bool isolated = other != this->Labels[v];
    for (int w : neighbors)
    {
      isolated = isolated && this->Labels[w] == other;
    }
    if (isolated)
    {
      this->Labels[v] = other;
    }
  }
  // Each snaxel at the end of its edge that lies on the labelling's boundary: where the edge's
  // faces agree, the end whose label is not theirs.
  this->Parameters.assign(static_cast<std::size_t>(mesh.edgeCount()), 0.0);
  this->Visited.assign(static_cast<std::size_t>(mesh.edgeCount()), 0);
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (!this->isCut(e))
    {
      continue;
    }
    this->CutEdges.push_back(e);
    const auto& faces = mesh.edgeFaces(e);
    const int faceLabel = faceLabels[faces[0]];
    if (faces[1] < 0 || faceLabels[faces[1]] == faceLabel)
    {
      this->Parameters[e] = this->Labels[mesh.edgeVertices(e)[0]] != faceLabel ? 0.0 : 1.0;
    }
  }
  const SurfaceDescriptors& descriptors = this->SharedSurface->descriptors();
  const double scale = unitBoxScale(mesh);
  this->TotalCurvature.resize(static_cast<std::size_t>(mesh.vertexCount()));
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    this->TotalCurvature[v] =
      scale * (std::abs(descriptors.minimumCurvature[v]) + std::abs(descriptors.maximumCurvature[v]));
  }
  this->MeanEdgeLength = mesh.meanEdgeLength();
}

bool BoundarySnake::isCut(int edge) const
{
  const auto& ev = this->Mesh.edgeVertices(edge);
  return this->Labels[ev[0]] != this->Labels[ev[1]];
}

int BoundarySnake::faceLabelCount(int face) const
{
  const Triangle& t = this->Mesh.triangle(face);
  const int a = this->Labels[t[0]], b = this->Labels[t[1]], c = this->Labels[t[2]];
  return 1 + (a != b ? 1 : 0) + (c != a && c != b ? 1 : 0);
}

Vector3 BoundarySnake::snaxelPosition(int edge, double t) const
{
  const auto& ev = this->Mesh.edgeVertices(edge);
  if (t == 0.0)
  {
    return this->Mesh.point(ev[0]);
  }
  if (t == 1.0)
  {
    return this->Mesh.point(ev[1]);
  }
  return (1.0 - t) * this->Mesh.point(ev[0]) + t * this->Mesh.point(ev[1]);
}

Vector3 BoundarySnake::snaxelPosition(int edge) const
{
  return this->snaxelPosition(edge, this->Parameters[edge]);
}

bool BoundarySnake::isFixedSnaxel(int edge) const
{
  const auto& faces = this->Mesh.edgeFaces(edge);
  return faces[1] < 0 || this->faceLabelCount(faces[0]) == 3 || this->faceLabelCount(faces[1]) == 3;
}

SnakePoint BoundarySnake::meetingPoint(int face) const
{
  SnakePoint point;
  point.face = face;
  for (int k = 0; k < 3; ++k)
  {
    point.position += this->snaxelPosition(this->Mesh.faceEdge(face, k)) / 3.0;
  }
  return point;
}

void BoundarySnake::noteCutCandidates(const IndexRange& edges) const
{
  this->CutCandidates.insert(this->CutCandidates.end(), edges.begin(), edges.end());
}

void BoundarySnake::updateCutEdges() const
{
  if (!this->CutCandidates.empty())
  {
    std::sort(this->CutCandidates.begin(), this->CutCandidates.end());
    std::vector<int> merged;
    merged.reserve(this->CutEdges.size() + this->CutCandidates.size());
    std::set_union(this->CutEdges.begin(), this->CutEdges.end(), this->CutCandidates.begin(), this->CutCandidates.end(),
      std::back_inserter(merged));
    this->CutEdges.swap(merged);
    this->CutCandidates.clear();
  }
  this->CutEdges.erase(
    std::remove_if(this->CutEdges.begin(), this->CutEdges.end(), [this](int e) { return !this->isCut(e); }),
    this->CutEdges.end());
}

std::vector<BoundarySnake::Chain> BoundarySnake::chains() const
{
  const TriangleMesh& mesh = this->Mesh;
  this->updateCutEdges();
  const std::vector<int>& cut = this->CutEdges;
  // The snaxel after `edge` through `face` (a face with two labels), or -1.
  auto across = [&](int edge, int face) {
    if (face < 0 || this->faceLabelCount(face) != 2)
    {
      return -1;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int other = mesh.faceEdge(face, k);
      if (other != edge && this->isCut(other))
      {
        return other;
      }
    }
    return -1;
  };
  auto otherFace = [&](int edge, int face) {
    const auto& faces = mesh.edgeFaces(edge);
    return faces[0] == face ? faces[1] : faces[0];
  };
  std::vector<char>& visited = this->Visited;
  std::vector<Chain> result;
  for (int first : cut)
  {
    if (visited[first])
    {
      continue;
    }
    Chain chain;
    visited[first] = 1;
    // Backwards through the first face, then forwards through the second.
    std::vector<int> backward;
    int edge = first, face = mesh.edgeFaces(first)[0];
    while (true)
    {
      const int next = across(edge, face);
      if (next < 0)
      {
        chain.startFace = face >= 0 && this->faceLabelCount(face) == 3 ? face : -1;
        break;
      }
      if (next == first)
      {
        chain.closed = true;
        break;
      }
      visited[next] = 1;
      backward.push_back(next);
      face = otherFace(next, face);
      edge = next;
    }
    chain.edges.assign(backward.rbegin(), backward.rend());
    chain.edges.push_back(first);
    if (!chain.closed)
    {
      edge = first;
      face = mesh.edgeFaces(first)[1];
      while (true)
      {
        const int next = across(edge, face);
        if (next < 0)
        {
          chain.endFace = face >= 0 && this->faceLabelCount(face) == 3 ? face : -1;
          break;
        }
        visited[next] = 1;
        chain.edges.push_back(next);
        face = otherFace(next, face);
        edge = next;
      }
    }
    result.push_back(std::move(chain));
  }
  for (int e : cut)
  {
    visited[e] = 0;
  }
  return result;
}

double BoundarySnake::snaxelEnergy(
  const Vector3& previous, const Vector3& position, const Vector3& next, int edge, double t) const
{
  const auto& ev = this->Mesh.edgeVertices(edge);
  Vector3 normal = (1.0 - t) * this->Normals[ev[0]] + t * this->Normals[ev[1]];
  const double length = normal.norm();
  normal = length > 0.0 ? Vector3(normal / length) : Vector3::Zero();
  const double external = (1.0 - t) * this->TotalCurvature[ev[0]] + t * this->TotalCurvature[ev[1]];
  return tangentAngle(previous, position, next, normal) * (external + this->CurvatureOffset);
}

bool BoundarySnake::canSplit(int vertex) const
{
  const TriangleMesh& mesh = this->Mesh;
  if (mesh.isBoundaryVertex(vertex) || mesh.vertexComponent(vertex) < 0)
  {
    return false;
  }
  // Two labels in the one-ring, each in one run: exactly two faces with differently labelled far corners.
  const int own = this->Labels[vertex];
  int other = -1, changes = 0, same = 0;
  for (int w : mesh.vertexNeighbors(vertex))
  {
    const int label = this->Labels[w];
    if (label == own)
    {
      ++same;
    }
    else if (other < 0 || label == other)
    {
      other = label;
    }
    else
    {
      return false;
    }
  }
  for (int f : mesh.vertexFaces(vertex))
  {
    const Triangle& t = mesh.triangle(f);
    const int k = cornerOf(t, vertex);
    changes += this->Labels[t[(k + 1) % 3]] != this->Labels[t[(k + 2) % 3]] ? 1 : 0;
  }
  return other >= 0 && same > 0 && changes == 2;
}

SnakeStatistics BoundarySnake::refine(const SnakeOptions& options)
{
  if (options.iterations < 0 || !(options.convergence >= 0.0) || !std::isfinite(options.convergence) ||
    !(options.curvatureOffset >= 0.0) || !std::isfinite(options.curvatureOffset) || options.slideSamples < 1 ||
    options.slideSamples > 1000)
  {
    throw Error("the snake needs iterations >= 0, a finite convergence threshold >= 0, a finite curvature offset "
                ">= 0 and 1 to 1000 slide samples");
  }
  this->CurvatureOffset = options.curvatureOffset;
  const TriangleMesh& mesh = this->Mesh;
  const double coincident = 1e-9 * this->MeanEdgeLength;
  SnakeStatistics statistics;
  for (int sweep = 0; sweep < options.iterations; ++sweep)
  {
    ++statistics.sweeps;
    double largestMove = 0.0;
    int splits = 0;
    for (const Chain& chain : this->chains())
    {
      const int n = static_cast<int>(chain.edges.size());
      std::vector<Vector3> points(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i)
      {
        points[i] = this->snaxelPosition(chain.edges[i]);
      }
      const bool hasStart = chain.startFace >= 0, hasEnd = chain.endFace >= 0;
      const Vector3 start = hasStart ? this->meetingPoint(chain.startFace).position : Vector3::Zero();
      const Vector3 end = hasEnd ? this->meetingPoint(chain.endFace).position : Vector3::Zero();
      // The nearest point before (step -1) or after (+1) snaxel i that is not at `at`; false if none.
      auto neighbour = [&](int i, int step, const Vector3& at, Vector3& found) {
        for (int k = 1; k < n; ++k)
        {
          int j = i + step * k;
          if (chain.closed)
          {
            j = ((j % n) + n) % n;
          }
          else if (j < 0 || j >= n)
          {
            const Vector3& meeting = j < 0 ? start : end;
            if ((j < 0 ? hasStart : hasEnd) && (meeting - at).norm() > coincident)
            {
              found = meeting;
              return true;
            }
            return false;
          }
          if ((points[j] - at).norm() > coincident)
          {
            found = points[j];
            return true;
          }
        }
        return false;
      };
      auto energyAt = [&](int i, double t) {
        const Vector3 at = this->snaxelPosition(chain.edges[i], t);
        Vector3 previous, next;
        if (!neighbour(i, -1, at, previous) || !neighbour(i, +1, at, next))
        {
          return 0.0;
        }
        return this->snaxelEnergy(previous, at, next, chain.edges[i], t);
      };

      // Slides.
      for (int i = 0; i < n; ++i)
      {
        const int e = chain.edges[i];
        if (this->isFixedSnaxel(e))
        {
          continue;
        }
        const double current = this->Parameters[e];
        double bestT = current, bestEnergy = energyAt(i, current);
        auto consider = [&](double t) {
          const double energy = energyAt(i, t);
          if (energy > bestEnergy * (1.0 + 1e-12) + 1e-300)
          {
            bestEnergy = energy;
            bestT = t;
          }
        };
        for (int k = 0; k <= options.slideSamples; ++k)
        {
          consider(static_cast<double>(k) / options.slideSamples);
        }
        // The position on the edge in line with the neighbours, seen along the normal.
        Vector3 previous, next;
        const auto& ev = mesh.edgeVertices(e);
        if (neighbour(i, -1, points[i], previous) && neighbour(i, +1, points[i], next))
        {
          const std::vector<Vector3>& normals = this->Normals;
          const Vector3 cutNormal = (next - previous).cross(normals[ev[0]] + normals[ev[1]]);
          const Vector3 along = mesh.point(ev[1]) - mesh.point(ev[0]);
          const double denominator = along.dot(cutNormal);
          if (denominator != 0.0)
          {
            const double t = (previous - mesh.point(ev[0])).dot(cutNormal) / denominator;
            if (t > 0.0 && t < 1.0)
            {
              consider(t);
            }
          }
        }
        if (bestT != current)
        {
          this->Parameters[e] = bestT;
          const Vector3 moved = this->snaxelPosition(e);
          largestMove = std::max(largestMove, (moved - points[i]).norm());
          points[i] = moved;
          ++statistics.slides;
        }
      }

      // Splits: runs of snaxels at one vertex that hold every snaxel of that vertex.
      auto vertexAt = [&](int i) {
        const double t = this->Parameters[chain.edges[i]];
        const auto& ev = mesh.edgeVertices(chain.edges[i]);
        return t == 0.0 ? ev[0] : t == 1.0 ? ev[1] : -1;
      };
      int first = 0;
      if (chain.closed)
      {
        // Start at a run's beginning.
        while (first < n && vertexAt(first) >= 0 && vertexAt(first) == vertexAt((first + n - 1) % n))
        {
          ++first;
        }
        if (first == n)
        {
          continue; // the whole loop sits at one vertex
        }
      }
      std::vector<int> touched; // split vertices and their neighbours: this chain changed there
      for (int i = first; i < first + n;)
      {
        const int vertex = vertexAt(i % n);
        int length = 1;
        while (vertex >= 0 && length < n && i + length < first + n && vertexAt((i + length) % n) == vertex)
        {
          ++length;
        }
        const int runStart = i;
        i += length;
        if (vertex < 0 || std::find(touched.begin(), touched.end(), vertex) != touched.end() || !this->canSplit(vertex))
        {
          continue;
        }
        int cutEdges = 0;
        for (int e : mesh.vertexEdges(vertex))
        {
          cutEdges += this->isCut(e) ? 1 : 0;
        }
        const Vector3& at = mesh.point(vertex);
        Vector3 previous, next;
        if (length != cutEdges || !neighbour(runStart % n, -1, at, previous) ||
          !neighbour((runStart + length - 1) % n, +1, at, next))
        {
          continue;
        }
        const Vector3& normal = this->Normals[vertex];
        if (tangentAngle(previous, at, next, normal) > StraightAngle)
        {
          continue;
        }
        // Straightening moves the vertex towards the middle of its neighbours: split if the edge
        // pointing most that way leads into its own label.
        Vector3 towards = 0.5 * (previous + next) - at;
        towards -= towards.dot(normal) * normal;
        int bestNeighbour = -1;
        double bestCosine = -2.0;
        for (int w : mesh.vertexNeighbors(vertex))
        {
          Vector3 direction = mesh.point(w) - at;
          direction -= direction.dot(normal) * normal;
          const double cosine = direction.dot(towards) / (direction.norm() * towards.norm());
          if (cosine > bestCosine)
          {
            bestCosine = cosine;
            bestNeighbour = w;
          }
        }
        if (bestNeighbour < 0 || this->Labels[bestNeighbour] != this->Labels[vertex])
        {
          continue;
        }
        int other = -1;
        for (int w : mesh.vertexNeighbors(vertex))
        {
          other = this->Labels[w] != this->Labels[vertex] ? this->Labels[w] : other;
        }
        const IndexRange edges = mesh.vertexEdges(vertex);
        const IndexRange neighbors = mesh.vertexNeighbors(vertex);
        for (std::size_t k = 0; k < edges.size(); ++k)
        {
          // The edges to its own label get snaxels at the vertex; the others lose theirs.
          if (this->Labels[neighbors[k]] == this->Labels[vertex])
          {
            this->Parameters[edges[k]] = mesh.edgeVertices(edges[k])[0] == vertex ? 0.0 : 1.0;
          }
        }
        this->Labels[vertex] = other;
        this->noteCutCandidates(edges);
        touched.push_back(vertex);
        touched.insert(touched.end(), neighbors.begin(), neighbors.end());
        statistics.removals += cutEdges;
        ++splits;
      }
    }
    statistics.splits += splits;
    if (largestMove <= options.convergence * this->MeanEdgeLength && splits == 0)
    {
      statistics.converged = true;
      break;
    }
  }
  return statistics;
}

std::vector<int> BoundarySnake::faceLabels() const
{
  const TriangleMesh& mesh = this->Mesh;
  std::vector<int> labels(static_cast<std::size_t>(mesh.faceCount()));
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const int count = this->faceLabelCount(f);
    if (count == 1)
    {
      labels[f] = this->Labels[t[0]];
      continue;
    }
    // The area of each corner's part, as a fraction of the face.
    std::map<int, double> area;
    if (count == 2)
    {
      int lone = 0;
      for (int k = 0; k < 3; ++k)
      {
        if (this->Labels[t[k]] != this->Labels[t[(k + 1) % 3]] && this->Labels[t[k]] != this->Labels[t[(k + 2) % 3]])
        {
          lone = k;
        }
      }
      // The corner's part is a triangle spanning fractions a and b of its two edges.
      auto fractionFrom = [&](int corner, int edge) {
        const double t = this->Parameters[edge];
        return mesh.edgeVertices(edge)[0] == corner ? t : 1.0 - t;
      };
      const int v = t[lone];
      const double part = fractionFrom(v, mesh.faceEdge(f, lone)) * fractionFrom(v, mesh.faceEdge(f, (lone + 2) % 3));
      area[this->Labels[v]] += part;
      area[this->Labels[t[(lone + 1) % 3]]] += 1.0 - part;
    }
    else
    {
      const Vector3 meeting = this->meetingPoint(f).position;
      const double whole = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
      for (int k = 0; k < 3; ++k)
      {
        const Vector3& corner = mesh.point(t[k]);
        const Vector3 after = this->snaxelPosition(mesh.faceEdge(f, k));
        const Vector3 before = this->snaxelPosition(mesh.faceEdge(f, (k + 2) % 3));
        const double part =
          (after - corner).cross(meeting - corner).norm() + (meeting - corner).cross(before - corner).norm();
        area[this->Labels[t[k]]] += whole > 0.0 ? part / whole : 1.0 / 3.0;
      }
    }
    int best = -1;
    double bestArea = -1.0;
    for (const auto& [label, part] : area)
    {
      if (part > bestArea)
      {
        bestArea = part;
        best = label;
      }
    }
    labels[f] = best;
  }
  return labels;
}

std::vector<SnakeCurve> BoundarySnake::curves() const
{
  const TriangleMesh& mesh = this->Mesh;
  std::vector<SnakeCurve> result;
  for (const Chain& chain : this->chains())
  {
    SnakeCurve curve;
    curve.closed = chain.closed;
    auto add = [&curve](const SnakePoint& point) {
      if (curve.points.empty() || curve.points.back().position != point.position)
      {
        curve.points.push_back(point);
      }
    };
    if (chain.startFace >= 0)
    {
      add(this->meetingPoint(chain.startFace));
    }
    for (int e : chain.edges)
    {
      SnakePoint point;
      point.edge = e;
      point.t = this->Parameters[e];
      point.position = this->snaxelPosition(e);
      add(point);
    }
    if (chain.endFace >= 0)
    {
      add(this->meetingPoint(chain.endFace));
    }
    if (chain.closed && curve.points.size() > 1 && curve.points.front().position == curve.points.back().position)
    {
      curve.points.pop_back();
    }
    // Left and right: the face the first snaxel leads into has the edge from p to q in its own
    // orientation; the snake enters it across that edge, so p's label is on the left.
    const int e = chain.edges[0];
    const auto& faces = mesh.edgeFaces(e);
    int face = chain.edges.size() > 1 ? -1 : (chain.endFace >= 0 ? chain.endFace : chain.startFace);
    if (chain.edges.size() > 1)
    {
      const int second = chain.edges[1];
      for (int f : faces)
      {
        for (int k = 0; f >= 0 && k < 3; ++k)
        {
          face = mesh.faceEdge(f, k) == second ? f : face;
        }
      }
    }
    if (face < 0)
    {
      face = faces[0];
    }
    const Triangle& t = mesh.triangle(face);
    const auto& ev = mesh.edgeVertices(e);
    const int k = cornerOf(t, ev[0]);
    const bool forward = t[(k + 1) % 3] == ev[1];
    curve.leftLabel = this->Labels[forward ? ev[0] : ev[1]];
    curve.rightLabel = this->Labels[forward ? ev[1] : ev[0]];
    if (curve.leftLabel > curve.rightLabel)
    {
      std::swap(curve.leftLabel, curve.rightLabel);
      std::reverse(curve.points.begin(), curve.points.end());
    }
    result.push_back(std::move(curve));
  }
  return result;
}

void BoundarySnake::overrideWithStroke(const std::vector<Vector3>& stroke, double radius, double maximumDistance)
{
  const TriangleMesh& mesh = this->Mesh;
  if (stroke.size() < 2)
  {
    throw Error("an override stroke needs at least two points, this one has " + std::to_string(stroke.size()));
  }
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    throw Error("the override radius must be a positive length, not " + numberText(radius));
  }
  const ClosestPointLocator& locator = this->SharedSurface->locator();
  const std::vector<Vector3>& normals = this->Normals;
  // The stroke on the surface, with the interpolated normal at each point.
  std::vector<Vector3> path, pathNormals;
  for (std::size_t i = 0; i < stroke.size(); ++i)
  {
    if (!stroke[i].allFinite() || stroke[i].cwiseAbs().maxCoeff() > CoordinateLimit)
    {
      throw Error(
        "point " + std::to_string(i) + " of the override stroke has a NaN, infinite or huge coordinate (beyond 1e50)");
    }
    const ClosestPointLocator::Hit hit = locator.closest(stroke[i]);
    if (maximumDistance > 0.0 && hit.distance > maximumDistance)
    {
      throw Error("point " + std::to_string(i) + " of the override stroke is " + numberText(hit.distance) +
        " away from the surface, farther than the allowed " + numberText(maximumDistance));
    }
    const Triangle& t = mesh.triangle(hit.face);
    Vector3 normal = Vector3::Zero();
    for (int k = 0; k < 3; ++k)
    {
      normal += hit.barycentric[k] * normals[t[k]];
    }
    if (path.empty() || (hit.position - path.back()).norm() > 0.0)
    {
      path.push_back(hit.position);
      pathNormals.push_back(normal.normalized());
    }
  }
  if (path.size() < 2)
  {
    throw Error("the override stroke has fewer than two distinct points on the surface");
  }
  // Signed distance to the stroke of a point beside it (its nearest stroke point is not an end):
  // positive on the left of the stroke seen from outside.
  auto sideDistance = [&](const Vector3& x, double& signedDistance) {
    double best = std::numeric_limits<double>::infinity();
    bool beside = false;
    for (std::size_t s = 0; s + 1 < path.size(); ++s)
    {
      const Vector3 d = path[s + 1] - path[s];
      const double u = std::clamp((x - path[s]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const Vector3 nearest = path[s] + u * d;
      const double distance = (x - nearest).norm();
      if (distance < best)
      {
        best = distance;
        beside = !((s == 0 && u == 0.0) || (s + 2 == path.size() && u == 1.0));
        const Vector3 normal = ((1.0 - u) * pathNormals[s] + u * pathNormals[s + 1]).normalized();
        signedDistance = (x - nearest).dot(normal.cross(d).normalized());
      }
    }
    return beside && best <= radius;
  };
  // The band: vertices beside the stroke within the radius, grown from the vertices under it.
  std::map<int, double> band;
  std::vector<int> front;
  std::vector<char> seen(static_cast<std::size_t>(mesh.vertexCount()), 0);
  for (std::size_t s = 0; s + 1 < path.size(); ++s)
  {
    const int samples =
      1 + static_cast<int>(std::min(1e4, (path[s + 1] - path[s]).norm() / (0.5 * this->MeanEdgeLength)));
    for (int k = 0; k <= samples; ++k)
    {
      const int v = snapToVertex(mesh, locator.closest(path[s] + (path[s + 1] - path[s]) * (double(k) / samples)));
      if (!seen[v])
      {
        seen[v] = 1;
        front.push_back(v);
      }
    }
  }
  for (std::size_t i = 0; i < front.size(); ++i)
  {
    const int v = front[i];
    double signedDistance = 0.0;
    if (!sideDistance(mesh.point(v), signedDistance))
    {
      continue;
    }
    band[v] = signedDistance;
    for (int w : mesh.vertexNeighbors(v))
    {
      if (!seen[w])
      {
        seen[w] = 1;
        front.push_back(w);
      }
    }
  }
  // The two labels of the band, and which side each belongs to.
  std::map<int, std::array<int, 2>> counts; // label -> vertices on the left, on the right
  std::array<int, 2> sideTotals{ 0, 0 };
  for (const auto& [v, signedDistance] : band)
  {
    const int side = signedDistance >= 0.0 ? 0 : 1;
    ++counts[this->Labels[v]][side];
    ++sideTotals[side];
  }
  if (counts.size() < 2 || sideTotals[0] == 0 || sideTotals[1] == 0)
  {
    throw Error("the override stroke is not near a boundary: the " + std::to_string(band.size()) + " vertices within " +
      numberText(radius) + " beside it " +
      (counts.empty() ? std::string("are none") : "have the single label " + std::to_string(counts.begin()->first)));
  }
  std::vector<std::pair<int, int>> byCount; // (-count, label): most frequent first
  for (const auto& [label, sides] : counts)
  {
    byCount.emplace_back(-(sides[0] + sides[1]), label);
  }
  std::sort(byCount.begin(), byCount.end());
  const int a = byCount[0].second, b = byCount[1].second;
  const double leftShareOfA = double(counts[a][0]) / sideTotals[0],
               rightShareOfA = double(counts[a][1]) / sideTotals[1];
  const int leftLabel = leftShareOfA >= rightShareOfA ? a : b;
  const int rightLabel = leftLabel == a ? b : a;
  std::vector<double> previousParameters = this->Parameters;
  std::vector<int> previousLabels = this->Labels;
  for (const auto& [v, signedDistance] : band)
  {
    this->Labels[v] = signedDistance >= 0.0 ? leftLabel : rightLabel;
    this->noteCutCandidates(mesh.vertexEdges(v));
  }
  // Snaxels where the stroke crosses edges inside the band; elsewhere kept, or mid-edge if new.
  for (const auto& [v, signedDistance] : band)
  {
    for (int e : mesh.vertexEdges(v))
    {
      if (!this->isCut(e))
      {
        continue;
      }
      const auto& ev = mesh.edgeVertices(e);
      const auto first = band.find(ev[0]), second = band.find(ev[1]);
      if (first != band.end() && second != band.end() && (first->second >= 0.0) != (second->second >= 0.0))
      {
        this->Parameters[e] = first->second / (first->second - second->second);
      }
      else if (previousLabels[ev[0]] != previousLabels[ev[1]])
      {
        this->Parameters[e] = previousParameters[e];
      }
      else
      {
        this->Parameters[e] = 0.5;
      }
    }
  }
}

} // namespace kerf
