// SeamCut's export operators: curve points located on the mesh, triangles split along curves, vertices snapped to
// curves.
#include "Export/CurveExport.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/ShortestPaths.h"
#include "Mesh/UnionFind.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace kerf
{
namespace
{

std::string pointName(std::size_t curve, std::size_t point)
{
  return "point " + std::to_string(point) + " of curve " + std::to_string(curve);
}

int cornerOf(const Triangle& triangle, int v)
{
  for (int k = 0; k < 3; ++k)
  {
    if (triangle[k] == v)
    {
      return k;
    }
  }
  return -1;
}

int sideOf(const TriangleMesh& mesh, int face, int edge)
{
  for (int k = 0; k < 3; ++k)
  {
    if (mesh.faceEdge(face, k) == edge)
    {
      return k;
    }
  }
  return -1;
}

// A point of `face` by its barycentric coordinates, snapped to a corner or edge within tolerance.
CurvePointLocation classify(const TriangleMesh& mesh, int face, Vector3 b, double tolerance)
{
  // A point projected outside the triangle is taken at the triangle's border.
  b = b.cwiseMax(0.0);
  b /= b.sum();
  CurvePointLocation location;
  for (int k = 0; k < 3; ++k)
  {
    if (b[k] >= 1.0 - tolerance)
    {
      location.kind = CurvePointLocation::Vertex;
      location.index = mesh.triangle(face)[k];
      return location;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    const int opposite = (k + 1) % 3; // side `opposite` joins corners k+1 and k+2
    if (b[k] <= tolerance && mesh.faceEdge(face, opposite) >= 0)
    {
      const int a = mesh.triangle(face)[opposite];
      const int edge = mesh.faceEdge(face, opposite);
      const double fromA = b[(k + 2) % 3] / (b[(k + 1) % 3] + b[(k + 2) % 3]);
      location.kind = CurvePointLocation::Edge;
      location.index = edge;
      location.t = mesh.edgeVertices(edge)[0] == a ? fromA : 1.0 - fromA;
      return location;
    }
  }
  location.kind = CurvePointLocation::Face;
  location.index = face;
  location.barycentric = b;
  return location;
}

bool inClosure(const TriangleMesh& mesh, const CurvePointLocation& location, int face)
{
  switch (location.kind)
  {
    case CurvePointLocation::Vertex:
      return cornerOf(mesh.triangle(face), location.index) >= 0;
    case CurvePointLocation::Edge:
      return sideOf(mesh, face, location.index) >= 0;
    default:
      return location.index == face;
  }
}

// The location of a point between segments in faces f0 and f1 that disagree: what they share.
CurvePointLocation sharedLocation(
  const TriangleMesh& mesh, int f0, int f1, const Vector3& p, double tolerance, std::size_t curve, std::size_t point)
{
  for (int k = 0; k < 3; ++k)
  {
    const int edge = mesh.faceEdge(f0, k);
    if (edge >= 0 && sideOf(mesh, f1, edge) >= 0)
    {
      const auto& ends = mesh.edgeVertices(edge);
      const Vector3 a = mesh.point(ends[0]);
      const Vector3 ab = mesh.point(ends[1]) - a;
      const double length2 = ab.squaredNorm();
      const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
      CurvePointLocation location;
      if (t <= tolerance || t >= 1.0 - tolerance)
      {
        location.kind = CurvePointLocation::Vertex;
        location.index = ends[t <= tolerance ? 0 : 1];
      }
      else
      {
        location.kind = CurvePointLocation::Edge;
        location.index = edge;
        location.t = t;
      }
      return location;
    }
  }
  for (int v : mesh.triangle(f0))
  {
    if (cornerOf(mesh.triangle(f1), v) >= 0)
    {
      CurvePointLocation location;
      location.kind = CurvePointLocation::Vertex;
      location.index = v;
      return location;
    }
  }
  throw Error(pointName(curve, point) + " joins segments in triangles " + std::to_string(f0) + " and " +
    std::to_string(f1) + ", which do not touch");
}

Vector3 locationPosition(const TriangleMesh& mesh, const CurvePointLocation& location)
{
  switch (location.kind)
  {
    case CurvePointLocation::Vertex:
      return mesh.point(location.index);
    case CurvePointLocation::Edge:
    {
      const auto& ends = mesh.edgeVertices(location.index);
      return (1.0 - location.t) * mesh.point(ends[0]) + location.t * mesh.point(ends[1]);
    }
    default:
      return surfacePosition(mesh, SurfacePoint{ location.index, location.barycentric });
  }
}

bool isZeroArea(const TriangleMesh& mesh, int face)
{
  const Triangle& t = mesh.triangle(face);
  const Vector3 e0 = mesh.point(t[1]) - mesh.point(t[0]);
  const Vector3 e1 = mesh.point(t[2]) - mesh.point(t[1]);
  const Vector3 e2 = mesh.point(t[0]) - mesh.point(t[2]);
  const double longest = std::max({ e0.squaredNorm(), e1.squaredNorm(), e2.squaredNorm() });
  return e0.cross(-e2).norm() <= ZeroAreaTolerance * longest;
}

// ---------------------------------------------------------------------------------------------
// Scissor: per touched triangle, its points in the reference triangle (0,0), (1,0), (0,1) and
// the curve segments as constraints, triangulated by greedy insertion of non-crossing edges.

struct LocalPoint
{
  int id = -1;             // output vertex
  double x = 0.0, y = 0.0; // (b1, b2)
  int side = -1;           // the side it lies on (-1: inside), corners: -2
  int corner = -1;         // corner index for corners
  double along = 0.0;      // parameter along `side` from its first corner
};

struct FaceWork
{
  std::vector<LocalPoint> points;
  std::vector<std::pair<int, int>> constraints; // local indices
};

double orient(const LocalPoint& a, const LocalPoint& b, const LocalPoint& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Does local point p lie on side k of the reference triangle?
bool onSide(const LocalPoint& p, int k)
{
  if (p.corner >= 0)
  {
    return p.corner == k || p.corner == (k + 1) % 3;
  }
  return p.side == k;
}

// Parameter of p along side k (0 at corner k, 1 at corner k+1).
double alongSide(const LocalPoint& p, int k)
{
  if (p.corner >= 0)
  {
    return p.corner == k ? 0.0 : 1.0;
  }
  return p.along;
}

int commonSide(const LocalPoint& a, const LocalPoint& b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (onSide(a, k) && onSide(b, k))
    {
      return k;
    }
  }
  return -1;
}

bool properlyCross(const LocalPoint& a, const LocalPoint& b, const LocalPoint& c, const LocalPoint& d)
{
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Is local point p strictly inside segment (a, b)?
bool strictlyInside(const std::vector<LocalPoint>& pts, int a, int b, int p)
{
  const int side = commonSide(pts[a], pts[b]);
  if (side >= 0)
  {
    if (!onSide(pts[p], side))
    {
      return false;
    }
    const double s = alongSide(pts[p], side), sa = alongSide(pts[a], side), sb = alongSide(pts[b], side);
    return s > std::min(sa, sb) && s < std::max(sa, sb);
  }
  if (orient(pts[a], pts[b], pts[p]) != 0.0)
  {
    return false;
  }
  const double dot = (pts[p].x - pts[a].x) * (pts[b].x - pts[a].x) + (pts[p].y - pts[a].y) * (pts[b].y - pts[a].y);
  const double length2 = (pts[b].x - pts[a].x) * (pts[b].x - pts[a].x) + (pts[b].y - pts[a].y) * (pts[b].y - pts[a].y);
  return dot > 0.0 && dot < length2;
}

class Scissor
{
public:
  // `newVertices`: how many vertices to make room for (the curve points, say).
  Scissor(const TriangleMesh& mesh, double tolerance, std::size_t newVertices)
    : Mesh(mesh)
    , Tolerance(tolerance)
    , FirstOnEdge(static_cast<std::size_t>(mesh.edgeCount()), -1)
    , WorkOfFace(static_cast<std::size_t>(mesh.faceCount()), -1)
  {
    const std::size_t n = static_cast<std::size_t>(mesh.vertexCount());
    this->Points.reserve(n + newVertices);
    this->Points.assign(mesh.points().begin(), mesh.points().end());
    this->Origins.reserve(n + newVertices);
    this->OriginalIds.reserve(n + newVertices);
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      // vertexSurfacePoint: the vertex in its first triangle.
      SurfacePoint origin{ -1, Vector3::Zero() };
      const IndexRange faces = mesh.vertexFaces(v);
      if (!faces.empty())
      {
        const Triangle& t = mesh.triangle(faces[0]);
        origin = SurfacePoint{ faces[0], Vector3(t[0] == v ? 1.0 : 0.0, t[1] == v ? 1.0 : 0.0, t[2] == v ? 1.0 : 0.0) };
      }
      this->Origins.push_back(origin);
      this->OriginalIds.push_back(v);
    }
  }

  // The output vertex of a located point (new vertices shared by equal locations).
  int vertexOf(const CurvePointLocation& location)
  {
    switch (location.kind)
    {
      case CurvePointLocation::Vertex:
        return location.index;
      case CurvePointLocation::Edge:
      {
        int* last = &this->FirstOnEdge[static_cast<std::size_t>(location.index)];
        for (; *last >= 0; last = &this->OnEdges[static_cast<std::size_t>(*last)].next)
        {
          const EdgePoint& entry = this->OnEdges[static_cast<std::size_t>(*last)];
          if (std::abs(entry.t - location.t) <= this->Tolerance)
          {
            return entry.id;
          }
        }
        const auto& ends = this->Mesh.edgeVertices(location.index);
        const int face = this->Mesh.edgeFaces(location.index)[0];
        Vector3 b = Vector3::Zero();
        b[cornerOf(this->Mesh.triangle(face), ends[0])] = 1.0 - location.t;
        b[cornerOf(this->Mesh.triangle(face), ends[1])] = location.t;
        const int id = this->addVertex(locationPosition(this->Mesh, location), SurfacePoint{ face, b });
        if (last == &this->FirstOnEdge[static_cast<std::size_t>(location.index)])
        {
          this->SplitEdges.push_back(location.index);
        }
        *last = static_cast<int>(this->OnEdges.size());
        this->OnEdges.push_back(EdgePoint{ location.t, id, -1 });
        return id;
      }
      default:
      {
        FaceWork& work = this->work(location.index);
        for (const LocalPoint& p : work.points)
        {
          if (p.side == -1 && p.corner < 0 && std::abs(p.x - location.barycentric[1]) <= this->Tolerance &&
            std::abs(p.y - location.barycentric[2]) <= this->Tolerance)
          {
            return p.id;
          }
        }
        const int id =
          this->addVertex(locationPosition(this->Mesh, location), SurfacePoint{ location.index, location.barycentric });
        work.points.push_back(LocalPoint{ id, location.barycentric[1], location.barycentric[2], -1, -1, 0.0 });
        return id;
      }
    }
  }

  // The segment of `curve` from its point `point` to the next, in `face`, between output vertices a and b.
  void addSegment(int face, int a, int b, std::size_t curve, std::size_t point)
  {
    if (a == b)
    {
      return;
    }
    if (isZeroArea(this->Mesh, face))
    {
      throw Error(pointName(curve, point) + " is on triangle " + std::to_string(face) +
        ", which has zero area; remove degenerate triangles before cutting");
    }
    FaceWork& work = this->work(face);
    work.constraints.emplace_back(this->localIndex(face, a), this->localIndex(face, b));
  }

  CurveExportResult finish()
  {
    const TriangleMesh& mesh = this->Mesh;
    // Triangles beside edges that received points are split too, so the mesh stays conforming.
    std::sort(this->SplitEdges.begin(), this->SplitEdges.end());
    for (int e : this->SplitEdges)
    {
      if (!mesh.isManifoldEdge(e))
      {
        throw Error("a curve crosses edge " + std::to_string(e) + ", which is shared by more than two triangles");
      }
      for (int face : mesh.edgeFaces(e))
      {
        if (face < 0)
        {
          continue;
        }
        if (isZeroArea(mesh, face))
        {
          throw Error("a curve crosses an edge of triangle " + std::to_string(face) +
            ", which has zero area; "
            "remove degenerate triangles before cutting");
        }
        this->work(face);
      }
    }
    std::vector<Triangle> triangles;
    std::vector<int> originalFaces;
    triangles.reserve(static_cast<std::size_t>(mesh.faceCount()) + 4 * this->Works.size());
    originalFaces.reserve(triangles.capacity());
    std::vector<std::pair<int, int>> cuts;
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const int w = this->WorkOfFace[static_cast<std::size_t>(f)];
      if (w < 0)
      {
        triangles.push_back(mesh.triangle(f));
        originalFaces.push_back(f);
        continue;
      }
      FaceWork& work = this->Works[static_cast<std::size_t>(w)];
      for (int k = 0; k < 3; ++k)
      {
        const int edge = mesh.faceEdge(f, k);
        for (int i = edge >= 0 ? this->FirstOnEdge[static_cast<std::size_t>(edge)] : -1; i >= 0;
             i = this->OnEdges[static_cast<std::size_t>(i)].next)
        {
          this->localIndex(f, this->OnEdges[static_cast<std::size_t>(i)].id);
        }
      }
      this->triangulate(f, work, triangles, originalFaces, cuts);
    }

    // The per-triangle work is done: its memory goes back before the split mesh's is taken.
    std::vector<FaceWork>().swap(this->Works);
    std::vector<int>().swap(this->WorkOfFace);
    std::vector<int>().swap(this->FirstOnEdge);
    std::vector<EdgePoint>().swap(this->OnEdges);

    // Only the adjacency around the split triangles is built again.
    CurveExportResult result;
    result.mesh = mesh.refined(std::move(this->Points), std::move(triangles), originalFaces);
    result.originalFaces = std::move(originalFaces);
    result.originalPointIds = std::move(this->OriginalIds);
    result.pointOrigins = std::move(this->Origins);
    result.cutEdges.assign(static_cast<std::size_t>(result.mesh.edgeCount()), 0);
    for (const auto& cut : cuts)
    {
      result.cutEdges[static_cast<std::size_t>(edgeBetween(result.mesh, cut.first, cut.second))] = 1;
    }
    return result;
  }

private:
  static int edgeBetween(const TriangleMesh& mesh, int a, int b)
  {
    const IndexRange neighbors = mesh.vertexNeighbors(a);
    for (std::size_t i = 0; i < neighbors.size(); ++i)
    {
      if (neighbors[i] == b)
      {
        return mesh.vertexEdges(a)[i];
      }
    }
    throw Error("the cut edge between vertices " + std::to_string(a) + " and " + std::to_string(b) +
      " is missing from the split mesh");
  }

  int addVertex(const Vector3& position, const SurfacePoint& origin)
  {
    this->Points.push_back(position);
    this->Origins.push_back(origin);
    this->OriginalIds.push_back(-1);
    return static_cast<int>(this->Points.size()) - 1;
  }

  FaceWork& work(int face)
  {
    int& w = this->WorkOfFace[static_cast<std::size_t>(face)];
    if (w < 0)
    {
      w = static_cast<int>(this->Works.size());
      this->Works.emplace_back();
      FaceWork& created = this->Works.back();
      created.points.reserve(6); // the corners and, mostly, two points on sides
      for (int k = 0; k < 3; ++k)
      {
        LocalPoint corner{ this->Mesh.triangle(face)[k], k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0, -2, k, 0.0 };
        created.points.push_back(corner);
      }
    }
    return this->Works[static_cast<std::size_t>(w)];
  }

  // The local index of output vertex `id` in triangle `face` (added when it lies on an edge).
  int localIndex(int face, int id)
  {
    FaceWork& work = this->work(face);
    for (std::size_t i = 0; i < work.points.size(); ++i)
    {
      if (work.points[i].id == id)
      {
        return static_cast<int>(i);
      }
    }
    const SurfacePoint& origin = this->Origins[static_cast<std::size_t>(id)];
    int a = -1, b = -1, nonZero = 0;
    for (int k = 0; k < 3; ++k)
    {
      if (origin.barycentric[k] != 0.0)
      {
        (a < 0 ? a : b) = k;
        ++nonZero;
      }
    }
    // Only a new vertex on an edge can be missing from a triangle it belongs to.
    if (this->OriginalIds[static_cast<std::size_t>(id)] >= 0 || nonZero != 2)
    {
      throw Error("a curve joins a point that is not on triangle " + std::to_string(face) + " through it");
    }
    const Triangle& other = this->Mesh.triangle(origin.face);
    const int va = other[a], vb = other[b];
    const Triangle& triangle = this->Mesh.triangle(face);
    const int ca = cornerOf(triangle, va), cb = cornerOf(triangle, vb);
    if (ca < 0 || cb < 0)
    {
      throw Error("a curve joins a point that is not on triangle " + std::to_string(face) + " through it");
    }
    Vector3 bary = Vector3::Zero();
    bary[ca] = origin.barycentric[a];
    bary[cb] = origin.barycentric[b];
    const int side = (cb == (ca + 1) % 3) ? ca : cb;
    const double along = bary[(side + 1) % 3];
    work.points.push_back(LocalPoint{ id, bary[1], bary[2], side, -1, along });
    return static_cast<int>(work.points.size()) - 1;
  }

  // The common cases without the general triangulation: one point on a side and no curve
  // segment (the triangle beside a crossed edge), or one segment between two sides (a curve
  // crossing the triangle): the corner cut off, and the quadrilateral left split along its
  // shorter diagonal.
  bool splitSimply(int face, const FaceWork& work, std::vector<Triangle>& triangles, std::vector<int>& originalFaces,
    std::vector<std::pair<int, int>>& cuts) const
  {
    const std::vector<LocalPoint>& pts = work.points;
    const Triangle& corner = this->Mesh.triangle(face);
    if (pts.size() == 4 && work.constraints.empty() && pts[3].side >= 0)
    {
      const int k = pts[3].side, p = pts[3].id;
      triangles.push_back(Triangle{ corner[k], p, corner[(k + 2) % 3] });
      triangles.push_back(Triangle{ p, corner[(k + 1) % 3], corner[(k + 2) % 3] });
      originalFaces.insert(originalFaces.end(), 2, face);
      return true;
    }
    if (pts.size() != 5 || work.constraints.size() != 1)
    {
      return false;
    }
    int a = work.constraints[0].first, b = work.constraints[0].second;
    if (pts[a].side < 0 || pts[b].side < 0 || pts[a].side == pts[b].side)
    {
      return false;
    }
    if (pts[b].side != (pts[a].side + 1) % 3)
    {
      std::swap(a, b);
    }
    // a on side i (corners i, i+1), b on side i+1 (corners i+1, i+2): corner i+1 is cut off.
    const int i = pts[a].side, pa = pts[a].id, pb = pts[b].id;
    const int ci = corner[i], cj = corner[(i + 1) % 3], ck = corner[(i + 2) % 3];
    triangles.push_back(Triangle{ pa, cj, pb });
    if ((this->Points[ci] - this->Points[pb]).squaredNorm() <= (this->Points[pa] - this->Points[ck]).squaredNorm())
    {
      triangles.push_back(Triangle{ ci, pa, pb });
      triangles.push_back(Triangle{ ci, pb, ck });
    }
    else
    {
      triangles.push_back(Triangle{ pa, pb, ck });
      triangles.push_back(Triangle{ pa, ck, ci });
    }
    originalFaces.insert(originalFaces.end(), 3, face);
    cuts.emplace_back(pa, pb);
    return true;
  }

  void triangulate(int face, FaceWork& work, std::vector<Triangle>& triangles, std::vector<int>& originalFaces,
    std::vector<std::pair<int, int>>& cuts)
  {
    std::vector<LocalPoint>& pts = work.points;
    if (this->splitSimply(face, work, triangles, originalFaces, cuts))
    {
      return;
    }
    // Constraints split at the points they pass through, then at their crossings.
    std::vector<std::pair<int, int>> constraints;
    std::vector<std::pair<int, int>> pending = work.constraints;
    while (!pending.empty())
    {
      const auto c = pending.back();
      pending.pop_back();
      bool split = false;
      for (int p = 0; p < static_cast<int>(pts.size()) && !split; ++p)
      {
        if (p != c.first && p != c.second && strictlyInside(pts, c.first, c.second, p))
        {
          if (pts[p].side == -1 && pts[p].corner < 0 && commonSide(pts[c.first], pts[c.second]) < 0)
          {
            throw Error("a curve segment passes exactly through a point of another curve inside triangle " +
              std::to_string(face));
          }
          pending.emplace_back(c.first, p);
          pending.emplace_back(p, c.second);
          split = true;
        }
      }
      if (!split)
      {
        constraints.push_back(c);
      }
    }
    // Crossing constraints meet at a new vertex; repeated until none crosses another.
    for (bool crossed = true; crossed;)
    {
      crossed = false;
      for (std::size_t i = 0; i < constraints.size() && !crossed; ++i)
      {
        for (std::size_t j = i + 1; j < constraints.size() && !crossed; ++j)
        {
          const auto [a, b] = constraints[i];
          const auto [c, d] = constraints[j];
          if (a == c || a == d || b == c || b == d || !properlyCross(pts[a], pts[b], pts[c], pts[d]))
          {
            continue;
          }
          const double oa = orient(pts[c], pts[d], pts[a]), ob = orient(pts[c], pts[d], pts[b]);
          const double s = oa / (oa - ob);
          const double x = pts[a].x + s * (pts[b].x - pts[a].x);
          const double y = pts[a].y + s * (pts[b].y - pts[a].y);
          const Vector3 bary(1.0 - x - y, x, y);
          const int id =
            this->addVertex(surfacePosition(this->Mesh, SurfacePoint{ face, bary }), SurfacePoint{ face, bary });
          pts.push_back(LocalPoint{ id, x, y, -1, -1, 0.0 });
          const int p = static_cast<int>(pts.size()) - 1;
          constraints[i] = { a, p };
          constraints[j] = { c, p };
          constraints.emplace_back(p, b);
          constraints.emplace_back(p, d);
          crossed = true;
        }
      }
    }

    // Greedy triangulation: constraints first, then the shortest edges that cross nothing.
    const int n = static_cast<int>(pts.size());
    std::vector<char> adjacent(static_cast<std::size_t>(n * n), 0);
    std::vector<std::pair<int, int>> accepted;
    auto tryEdge = [&](int a, int b) {
      if (a == b || adjacent[static_cast<std::size_t>(a * n + b)])
      {
        return;
      }
      for (int p = 0; p < n; ++p)
      {
        if (p != a && p != b && strictlyInside(pts, a, b, p))
        {
          return;
        }
      }
      const bool alongSide = commonSide(pts[a], pts[b]) >= 0;
      if (!alongSide)
      {
        for (const auto& e : accepted)
        {
          if (e.first != a && e.first != b && e.second != a && e.second != b &&
            properlyCross(pts[a], pts[b], pts[e.first], pts[e.second]))
          {
            return;
          }
        }
      }
      accepted.emplace_back(a, b);
      adjacent[static_cast<std::size_t>(a * n + b)] = adjacent[static_cast<std::size_t>(b * n + a)] = 1;
    };
    for (const auto& c : constraints)
    {
      tryEdge(c.first, c.second);
      if (!adjacent[static_cast<std::size_t>(c.first * n + c.second)])
      {
        throw Error("the curves inside triangle " + std::to_string(face) + " overlap");
      }
      cuts.emplace_back(pts[c.first].id, pts[c.second].id);
    }
    std::vector<std::pair<double, std::pair<int, int>>> candidates;
    for (int a = 0; a < n; ++a)
    {
      for (int b = a + 1; b < n; ++b)
      {
        const double length2 = (this->Points[pts[a].id] - this->Points[pts[b].id]).squaredNorm();
        candidates.push_back({ length2, { a, b } });
      }
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& candidate : candidates)
    {
      tryEdge(candidate.second.first, candidate.second.second);
    }

    // Triangles: consecutive neighbours in counter-clockwise order that are joined.
    std::vector<std::vector<int>> around(static_cast<std::size_t>(n));
    for (const auto& e : accepted)
    {
      around[static_cast<std::size_t>(e.first)].push_back(e.second);
      around[static_cast<std::size_t>(e.second)].push_back(e.first);
    }
    for (int a = 0; a < n; ++a)
    {
      auto& list = around[static_cast<std::size_t>(a)];
      // A pseudo-angle: increases with the angle like atan2, without its cost.
      auto angle = [&](int b) {
        const double dx = pts[b].x - pts[a].x, dy = pts[b].y - pts[a].y;
        const double p = dx / (std::abs(dx) + std::abs(dy));
        return dy < 0.0 ? p - 1.0 : 1.0 - p;
      };
      std::sort(list.begin(), list.end(), [&](int p, int q) { return angle(p) < angle(q); });
      for (std::size_t i = 0; i < list.size(); ++i)
      {
        const int b = list[i], c = list[(i + 1) % list.size()];
        if (b == c || a > b || a > c || !adjacent[static_cast<std::size_t>(b * n + c)] ||
          orient(pts[a], pts[b], pts[c]) <= 0.0)
        {
          continue;
        }
        triangles.push_back(Triangle{ pts[a].id, pts[b].id, pts[c].id });
        originalFaces.push_back(face);
      }
    }
  }

  const TriangleMesh& Mesh;
  double Tolerance;
  std::vector<Vector3> Points;
  std::vector<SurfacePoint> Origins;
  std::vector<int> OriginalIds;
  struct EdgePoint
  {
    double t = 0.0; // along the edge, as CurvePointLocation::t
    int id = -1;    // output vertex
    int next = -1;  // the edge's next point in OnEdges, in order of creation
  };
  std::vector<int> FirstOnEdge; // per input edge: its first point in OnEdges, -1 for none
  std::vector<EdgePoint> OnEdges;
  std::vector<int> SplitEdges; // the input edges with points
  std::vector<int> WorkOfFace;
  std::vector<FaceWork> Works;
};

// ---------------------------------------------------------------------------------------------
// Snap: nearest corners joined by shortest edge paths.

// Shortest edge path from `source` to `target` (Dijkstra by edge length, stopped at the target;
// ties by vertex index). Buffers are reset through the list of touched vertices, so a path costs
// the region it explores, not the mesh's size.
class EdgePathFinder
{
public:
  explicit EdgePathFinder(const TriangleMesh& mesh)
    : Mesh(mesh)
    , Distance(static_cast<std::size_t>(mesh.vertexCount()), std::numeric_limits<double>::infinity())
    , Previous(static_cast<std::size_t>(mesh.vertexCount()), -1)
  {
  }

  // Appends the path's vertices after `source` to `chain`; throws if the target is unreachable.
  // The path ends at point `point` of curve `curve` (named in the error).
  void appendPath(int source, int target, std::vector<int>& chain, std::size_t curve, std::size_t point)
  {
    DistanceQueue queue;
    this->Distance[static_cast<std::size_t>(source)] = 0.0;
    this->Touched.push_back(source);
    queue.emplace(0.0, source);
    const double infinity = std::numeric_limits<double>::infinity();
    const bool reached = searchShortestPaths(
      queue, [&](int v) -> double& { return this->Distance[static_cast<std::size_t>(v)]; },
      [&](int v, double d, const auto& lower) {
        for (int w : this->Mesh.vertexNeighbors(v))
        {
          const bool fresh = this->Distance[static_cast<std::size_t>(w)] == infinity;
          if (lower(w, d + (this->Mesh.point(w) - this->Mesh.point(v)).norm()))
          {
            if (fresh)
            {
              this->Touched.push_back(w);
            }
            this->Previous[static_cast<std::size_t>(w)] = v;
          }
        }
      },
      [target](int v, double) { return v == target; });
    if (!reached)
    {
      this->reset();
      throw Error(pointName(curve, point) + " cannot be joined to the previous point along mesh edges");
    }
    const std::size_t start = chain.size();
    for (int v = target; v != source; v = this->Previous[static_cast<std::size_t>(v)])
    {
      chain.push_back(v);
    }
    std::reverse(chain.begin() + static_cast<std::ptrdiff_t>(start), chain.end());
    this->reset();
  }

private:
  void reset()
  {
    for (int v : this->Touched)
    {
      this->Distance[static_cast<std::size_t>(v)] = std::numeric_limits<double>::infinity();
      this->Previous[static_cast<std::size_t>(v)] = -1;
    }
    this->Touched.clear();
  }

  const TriangleMesh& Mesh;
  std::vector<double> Distance;
  std::vector<int> Previous;
  std::vector<int> Touched;
};

int nearestVertex(const TriangleMesh& mesh, const CurvePointLocation& location, const Vector3& p)
{
  switch (location.kind)
  {
    case CurvePointLocation::Vertex:
      return location.index;
    case CurvePointLocation::Edge:
    {
      const auto& ends = mesh.edgeVertices(location.index);
      return (mesh.point(ends[1]) - p).squaredNorm() < (mesh.point(ends[0]) - p).squaredNorm() ? ends[1] : ends[0];
    }
    default:
    {
      const Triangle& t = mesh.triangle(location.index);
      int best = t[0];
      for (int k = 1; k < 3; ++k)
      {
        const double d = (mesh.point(t[k]) - p).squaredNorm(), bestDistance = (mesh.point(best) - p).squaredNorm();
        if (d < bestDistance || (d == bestDistance && t[k] < best))
        {
          best = t[k];
        }
      }
      return best;
    }
  }
}

Vector3 faceNormal(const std::vector<Vector3>& points, const Triangle& t)
{
  return (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
}

} // namespace

std::vector<std::vector<CurvePointLocation>> locateCurvePoints(
  const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, double tolerance)
{
  if (!(tolerance >= 0.0 && tolerance < 0.5))
  {
    throw Error("the location tolerance must lie in [0, 0.5)");
  }
  std::vector<std::vector<CurvePointLocation>> locations(curves.size());
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    const SurfaceCurve& curve = curves[c];
    const std::size_t count = curve.points.size();
    if (count == 0)
    {
      continue;
    }
    if (static_cast<int>(curve.faces.size()) != segmentCount(curve) || (count < 2 && !curve.faces.empty()))
    {
      throw Error("curve " + std::to_string(c) + " has " + std::to_string(curve.faces.size()) + " segment faces for " +
        std::to_string(count) + " points");
    }
    for (int face : curve.faces)
    {
      if (face < 0 || face >= mesh.faceCount())
      {
        throw Error(
          "curve " + std::to_string(c) + " names triangle " + std::to_string(face) + ", which does not exist");
      }
    }
    if (curve.faces.empty())
    {
      throw Error("curve " + std::to_string(c) + " has a single point and no segment");
    }
    for (std::size_t i = 0; i < count; ++i)
    {
      if (!curve.points[i].allFinite())
      {
        throw Error(pointName(c, i) + " has a NaN or infinite coordinate");
      }
      const bool hasBefore = i > 0 || curve.closed;
      const bool hasAfter = i + 1 < count || curve.closed;
      const int before = hasBefore ? curve.faces[(i + curve.faces.size() - 1) % curve.faces.size()] : -1;
      const int after = hasAfter ? curve.faces[i % curve.faces.size()] : -1;
      const int first = before >= 0 ? before : after;
      const int second = after >= 0 ? after : before;
      CurvePointLocation location = classify(mesh, first, barycentricInFace(mesh, first, curve.points[i]), tolerance);
      if (second != first && !inClosure(mesh, location, second))
      {
        location = sharedLocation(mesh, first, second, curve.points[i], tolerance, c, i);
      }
      locations[c].push_back(location);
    }
  }
  return locations;
}

int labelCharts(const TriangleMesh& mesh, const std::vector<char>& cutEdges, std::vector<int>& charts)
{
  // Union-find in face order instead of labelFaceRegions' depth-first walk: the same labels (an
  // edge is cut for both its triangles alike, and the smaller root wins, so a chart's root is its
  // lowest face), with the faces read in order rather than in a walk's scattered order (the
  // benchmark's scissor output, Documentation/filters/CurveExport.md). Parents always point to lower faces,
  // so one array holds the parents and then, in increasing order, the labels.
  const int faces = mesh.faceCount();
  charts.resize(static_cast<std::size_t>(faces));
  int* parent = charts.data();
  for (int f = 0; f < faces; ++f)
  {
    parent[f] = f;
    for (int k = 0; k < 3; ++k)
    {
      const int g = mesh.faceNeighbor(f, k);
      if (g >= 0 && g < f && !cutEdges[static_cast<std::size_t>(mesh.faceEdge(f, k))])
      {
        joinRoots(parent, f, g);
      }
    }
  }
  int count = 0;
  for (int f = 0; f < faces; ++f)
  {
    charts[static_cast<std::size_t>(f)] = parent[f] == f ? count++ : charts[static_cast<std::size_t>(parent[f])];
  }
  return count;
}

CurveExportResult exportCurves(
  const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, const CurveExportOptions& options)
{
  if (mesh.empty())
  {
    throw Error("the mesh has no triangle");
  }
  const auto locations = locateCurvePoints(mesh, curves, options.locationTolerance);
  CurveExportResult result;
  result.curveVertices.resize(curves.size());

  if (options.mode == CurveExportMode::Scissor)
  {
    std::size_t curvePoints = 0;
    for (const SurfaceCurve& curve : curves)
    {
      curvePoints += curve.points.size();
    }
    Scissor scissor(mesh, options.locationTolerance, curvePoints);
    std::vector<std::vector<int>> ids(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c)
    {
      for (const CurvePointLocation& location : locations[c])
      {
        ids[c].push_back(scissor.vertexOf(location));
      }
    }
    for (std::size_t c = 0; c < curves.size(); ++c)
    {
      for (std::size_t i = 0; i < curves[c].faces.size(); ++i)
      {
        scissor.addSegment(curves[c].faces[i], ids[c][i], ids[c][(i + 1) % ids[c].size()], c, i);
      }
      for (int id : ids[c])
      {
        if (result.curveVertices[c].empty() || result.curveVertices[c].back() != id)
        {
          result.curveVertices[c].push_back(id);
        }
      }
    }
    CurveExportResult split = scissor.finish();
    split.curveVertices = std::move(result.curveVertices);
    result = std::move(split);
  }
  else
  {
    // Nearest vertex of each point; with several points on one vertex the nearest point wins
    // (ties: the first). The candidates sorted by vertex, stably, rather than kept in a std::map.
    struct Candidate
    {
      int vertex;
      double distance;
      Vector3 point;
    };
    std::vector<std::vector<int>> nearest(curves.size());
    std::vector<Candidate> candidates;
    for (std::size_t c = 0; c < curves.size(); ++c)
    {
      for (std::size_t i = 0; i < locations[c].size(); ++i)
      {
        const Vector3& p = curves[c].points[i];
        const int v = nearestVertex(mesh, locations[c][i], p);
        nearest[c].push_back(v);
        candidates.push_back(Candidate{ v, (mesh.point(v) - p).norm(), p });
      }
    }
    std::stable_sort(
      candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.vertex < b.vertex; });
    std::vector<Candidate> winners; // by increasing vertex
    for (const Candidate& candidate : candidates)
    {
      if (winners.empty() || winners.back().vertex != candidate.vertex)
      {
        winners.push_back(candidate);
      }
      else if (candidate.distance < winners.back().distance)
      {
        winners.back() = candidate;
      }
    }
    result.droppedPoints = static_cast<int>(candidates.size() - winners.size());
    std::vector<Vector3> points;
    if (options.mode == CurveExportMode::InverseSnap)
    {
      points = mesh.points();
      for (const Candidate& winner : winners)
      {
        const int v = winner.vertex;
        const Vector3 previous = points[static_cast<std::size_t>(v)];
        points[static_cast<std::size_t>(v)] = winner.point;
        bool flips = false;
        for (int f : mesh.vertexFaces(v))
        {
          if (faceNormal(points, mesh.triangle(f)).dot(faceNormal(mesh.points(), mesh.triangle(f))) <= 0.0)
          {
            flips = true;
            break;
          }
        }
        if (flips)
        {
          points[static_cast<std::size_t>(v)] = previous;
          ++result.refusedFlips;
        }
        else if (winner.point != previous)
        {
          ++result.movedVertices;
        }
      }
    }
    if (options.mode == CurveExportMode::InverseSnap)
    {
      result.mesh = mesh.withPoints(std::move(points));
    }
    const TriangleMesh& output = exportedMesh(result, mesh);
    EdgePathFinder paths(output);
    result.cutEdges.assign(static_cast<std::size_t>(mesh.edgeCount()), 0);
    for (std::size_t c = 0; c < curves.size(); ++c)
    {
      std::vector<int>& chain = result.curveVertices[c];
      for (std::size_t i = 0; i < nearest[c].size(); ++i)
      {
        const int v = nearest[c][i];
        if (chain.empty())
        {
          chain.push_back(v);
        }
        else if (chain.back() != v)
        {
          paths.appendPath(chain.back(), v, chain, c, i);
        }
      }
      if (curves[c].closed && chain.size() > 1 && chain.back() != chain.front())
      {
        paths.appendPath(chain.back(), chain.front(), chain, c, 0);
      }
      if (curves[c].closed && chain.size() > 1 && chain.back() == chain.front())
      {
        chain.pop_back();
      }
      const std::size_t segments = curves[c].closed && chain.size() > 2 ? chain.size() : chain.size() - 1;
      for (std::size_t i = 0; i < segments && !chain.empty(); ++i)
      {
        const int a = chain[i], b = chain[(i + 1) % chain.size()];
        const IndexRange neighbors = output.vertexNeighbors(a);
        for (std::size_t k = 0; k < neighbors.size(); ++k)
        {
          if (neighbors[k] == b)
          {
            result.cutEdges[static_cast<std::size_t>(output.vertexEdges(a)[k])] = 1;
          }
        }
      }
    }
  }
  result.chartCount = labelCharts(exportedMesh(result, mesh), result.cutEdges, result.charts);
  return result;
}

} // namespace kerf
