// Geometry seam carving's editing: weighted Laplace deformation with ring seams split or collapsed per sector on
// OpenMesh.
#include "SeamCarving/GeometrySeamCarving.h"

#include "Error.h"
#include "Mesh/OpenMeshAdapter.h"
#include "Mesh/Submesh.h"
#include "Numerics/SparseCholesky.h"
#include "SeamCarving/GeometrySeams.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>

namespace kerf
{
namespace
{

using Vec3 = OpenMesh::Vec3d;
using VH = EditableMesh::VertexHandle;
using HH = EditableMesh::HalfedgeHandle;
using EH = EditableMesh::EdgeHandle;
using FH = EditableMesh::FaceHandle;

enum Role : int
{
  FixedPoint = 0,
  FreePoint = 1,
  HandlePoint = 2
};

// Which side of a ring seam an original vertex lies on: the handle's (S) or the fixed region's (T).
enum Side : char
{
  NoSide = 0,
  HandleSide = 1,
  FixedSide = 2
};

// An inner edge of a ring (a "rung"), from its handle-side vertex s to its fixed-side vertex t.
struct Rung
{
  int s = -1, t = -1;          // submesh vertices
  int sectors[2] = { -1, -1 }; // sectors of its two ring triangles
  bool collapsible = false;    // in the ring's set of every second rung
};

struct Ring
{
  std::vector<Rung> rungs; // in order around the ring where the strip allows
  std::vector<char> side;  // per submesh vertex of the rest mesh
};

// An edge's rest vector (initialised, unlike OpenMesh's vectors, for the property's growth).
struct RestVector
{
  Vec3 value{ 0.0, 0.0, 0.0 };
};

Vector3 toVector(const Vec3& p)
{
  return Vector3(p[0], p[1], p[2]);
}

} // namespace

struct GeometrySeamCarving::Implementation
{
  SeamCarvingOptions options;
  const TriangleMesh* mesh = nullptr;
  std::vector<int> label;         // per input vertex: 0 fixed, 1 modeling, 2 handle
  std::vector<int> modelingFaces; // input triangles of the modeling region
  std::vector<char> isModelingFace;
  Submesh sub;       // the modeling region
  EditableMesh base; // its rest state, with the properties below
  OpenMesh::VPropHandleT<int> role;
  OpenMesh::VPropHandleT<int> origin; // input vertex, -1 for split points
  OpenMesh::VPropHandleT<double> stiffness;
  OpenMesh::VPropHandleT<int> rank;        // position in the rest state's elimination order, -1 before it is known
  OpenMesh::VPropHandleT<int> tie;         // creation order of split points, 0 for the others
  OpenMesh::EPropHandleT<RestVector> rest; // rest vector from halfedge 0's start to its end
  OpenMesh::EPropHandleT<double> weight;   // Laplace weight omega
  OpenMesh::FPropHandleT<int> faceRing, faceSector, faceOrigin;
  std::vector<Ring> rings;
  int sectors = 0;
  std::vector<double> sectorRestArea;
  std::vector<std::vector<double>> segmentArea; // [sector][ring]
  std::vector<std::vector<int>> order;          // per sector: rings by increasing Eq. 6 error
  int salientSegments = 0;                      // segments left out of the orders as salient

  // The current state and what was built for it.
  std::vector<int> state; // per sector, signed count
  bool built = false;
  bool ordered = false; // the base's ranks hold the rest state's elimination order
  std::vector<int> builtState;
  EditableMesh current;
  std::vector<std::array<int, 4>> corners; // per current face: its corners and its sector
  std::vector<int> freeIndex;              // per current vertex: unknown index, -1 if constrained
  int unknowns = 0;
  SparseCholesky factor;
  Eigen::SparseMatrix<double> coupling; // unknowns x current vertices: weights to constrained points
  Eigen::MatrixXd restRhs;              // unknowns x 3: sum of w r(w -> u)
  int skipped = 0;
  SeamCarvingResult result;

  Vec3 restVector(const EditableMesh& m, HH h) const
  {
    const EH e = m.edge_handle(h);
    const Vec3& r = m.property(this->rest, e).value;
    return m.halfedge_handle(e, 0) == h ? r : -r;
  }
  void setRest(EditableMesh& m, HH h, const Vec3& r, double w) const
  {
    const EH e = m.edge_handle(h);
    m.property(this->rest, e).value = m.halfedge_handle(e, 0) == h ? r : -r;
    m.property(this->weight, e) = w;
  }

  void buildBase(const SeamCarvingInput& input);
  void findRings(const SeamCarvingInput& input);
  void buildState();
  Vec3 alongRing(const EditableMesh& m, const Ring& ring, VH s, VH t, HH h) const;
  char sideOf(const Ring& ring, VH v) const;
  void split(EditableMesh& m, const Ring& ring, VH s, VH t, int ringIndex);
  bool collapse(EditableMesh& m, const Ring& ring, VH s, VH t, std::vector<int>& alias);
  void assemble();
  void solve(const Eigen::Matrix4d& transform, std::vector<Vector3>& positions) const;
  double restAreaOf(int sector) const;
};

namespace
{

void checkTransform(const Eigen::Matrix4d& m)
{
  if (!m.allFinite())
  {
    throw Error("the handle transform has a NaN or infinite entry");
  }
  if (m(3, 0) != 0.0 || m(3, 1) != 0.0 || m(3, 2) != 0.0 || m(3, 3) != 1.0)
  {
    throw Error("the handle transform is not affine (its last row must be 0 0 0 1)");
  }
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  const double scale = std::max(1.0, linear.cwiseAbs().maxCoeff());
  if (std::abs(linear.determinant()) <= 1e-9 * scale * scale * scale)
  {
    throw Error("the handle transform is singular (the determinant of its 3 x 3 part is " +
      std::to_string(linear.determinant()) + ")");
  }
}

double triangleArea(const Vector3& a, const Vector3& b, const Vector3& c)
{
  return 0.5 * (b - a).cross(c - a).norm();
}

} // namespace

void GeometrySeamCarving::Implementation::buildBase(const SeamCarvingInput& input)
{
  const TriangleMesh& m = *input.mesh;
  this->sub = extractSubmesh(m, this->modelingFaces);
  const TriangleMesh& r = this->sub.mesh;
  this->base = toEditableMesh(r);
  this->base.request_vertex_status();
  this->base.request_edge_status();
  this->base.request_halfedge_status();
  this->base.request_face_status();
  this->base.add_property(this->role);
  this->base.add_property(this->origin);
  this->base.add_property(this->stiffness);
  this->base.add_property(this->rank);
  this->base.add_property(this->tie);
  this->base.add_property(this->rest);
  this->base.add_property(this->weight);
  this->base.add_property(this->faceRing);
  this->base.add_property(this->faceSector);
  this->base.add_property(this->faceOrigin);
  for (const VH v : this->base.vertices())
  {
    const int g = this->sub.globalVertex[v.idx()];
    this->base.property(this->role, v) = this->label[g];
    this->base.property(this->origin, v) = g;
    this->base.property(this->rank, v) = -1;
    this->base.property(this->tie, v) = 0;
    // Dekkers and Kobbelt 2014, Eq. 7: stiffness(v) = s ang(v) + epsilon.
    this->base.property(this->stiffness, v) =
      this->options.stiffnessScale * input.normalConeAngle[g] + this->options.stiffnessEpsilon;
  }
  for (const EH e : this->base.edges())
  {
    const HH h = this->base.halfedge_handle(e, 0);
    this->base.property(this->rest, e).value =
      this->base.point(this->base.to_vertex_handle(h)) - this->base.point(this->base.from_vertex_handle(h));
    this->base.property(this->weight, e) = 1.0; // uniform weights: positive, as L_init must be
  }
  for (const FH f : this->base.faces())
  {
    const int g = this->sub.globalFace[f.idx()];
    this->base.property(this->faceRing, f) = input.faceRing[g];
    this->base.property(this->faceSector, f) = input.faceSector[g];
    this->base.property(this->faceOrigin, f) = g;
  }
}

// The rungs of every ring, their sides and the set of every second rung (Dekkers and Kobbelt
// 2014, 3.3.1: a collapse removes every second inner edge, a split divides every inner edge).
void GeometrySeamCarving::Implementation::findRings(const SeamCarvingInput& input)
{
  const TriangleMesh& r = this->sub.mesh;
  int ringCount = 0;
  for (int f = 0; f < r.faceCount(); ++f)
  {
    ringCount = std::max(ringCount, input.faceRing[this->sub.globalFace[f]] + 1);
  }
  this->rings.assign(static_cast<std::size_t>(ringCount), Ring());
  for (int k = 0; k < ringCount; ++k)
  {
    Ring& ring = this->rings[k];
    auto inRing = [&](int f) { return f >= 0 && input.faceRing[this->sub.globalFace[f]] == k; };
    // Sides: the region reached from the handle without crossing the ring is the handle side.
    std::vector<char> reached(r.faceCount(), 0);
    std::vector<int> stack;
    for (int f = 0; f < r.faceCount(); ++f)
    {
      if (inRing(f))
      {
        continue;
      }
      for (int v : r.triangle(f))
      {
        if (this->label[this->sub.globalVertex[v]] == HandlePoint)
        {
          reached[f] = 1;
          stack.push_back(f);
          break;
        }
      }
    }
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int c = 0; c < 3; ++c)
      {
        const int g = r.faceNeighbor(f, c);
        if (g >= 0 && !reached[g] && !inRing(g))
        {
          reached[g] = 1;
          stack.push_back(g);
        }
      }
    }
    ring.side.assign(r.vertexCount(), NoSide);
    for (int f = 0; f < r.faceCount(); ++f)
    {
      if (!inRing(f))
      {
        for (int v : r.triangle(f))
        {
          char& side = ring.side[v];
          side = reached[f] ? HandleSide : (side == HandleSide ? HandleSide : FixedSide);
        }
      }
    }
    for (int v = 0; v < r.vertexCount(); ++v)
    {
      const int l = this->label[this->sub.globalVertex[v]];
      if (l == HandlePoint)
      {
        ring.side[v] = HandleSide;
      }
      else if (l == FixedPoint)
      {
        ring.side[v] = FixedSide;
      }
    }
    // Rungs in order around the strip: from the ring's first rung, across its triangles.
    std::vector<int> rungOfEdge(r.edgeCount(), -1);
    std::vector<int> rungEdges;
    for (int e = 0; e < r.edgeCount(); ++e)
    {
      const std::array<int, 2>& faces = r.edgeFaces(e);
      if (r.edgeFaceCount(e) == 2 && inRing(faces[0]) && inRing(faces[1]))
      {
        const std::array<int, 2>& ends = r.edgeVertices(e);
        const char a = ring.side[ends[0]], b = ring.side[ends[1]];
        if (a != NoSide && b != NoSide && a != b)
        {
          rungOfEdge[e] = static_cast<int>(rungEdges.size());
          rungEdges.push_back(e);
        }
      }
    }
    std::vector<int> sequence;
    std::vector<char> visited(rungEdges.size(), 0);
    for (std::size_t first = 0; first < rungEdges.size(); ++first)
    {
      // Walk from each unvisited rung; a closed ladder is one walk.
      int rung = static_cast<int>(first);
      int cameFrom = -1;
      while (rung >= 0 && !visited[rung])
      {
        visited[rung] = 1;
        sequence.push_back(rung);
        const int e = rungEdges[rung];
        int next = -1;
        for (int f : r.edgeFaces(e))
        {
          if (f == cameFrom)
          {
            continue;
          }
          for (int c = 0; c < 3 && next < 0; ++c)
          {
            const int other = r.faceEdge(f, c);
            if (other != e && other >= 0 && rungOfEdge[other] >= 0 && !visited[rungOfEdge[other]])
            {
              next = rungOfEdge[other];
              cameFrom = f;
            }
          }
          if (next >= 0)
          {
            break;
          }
        }
        rung = next;
      }
    }
    std::vector<char> used(r.vertexCount(), 0);
    for (int index : sequence)
    {
      const int e = rungEdges[index];
      const std::array<int, 2>& ends = r.edgeVertices(e);
      Rung rungValue;
      rungValue.s = ring.side[ends[0]] == HandleSide ? ends[0] : ends[1];
      rungValue.t = rungValue.s == ends[0] ? ends[1] : ends[0];
      for (int i = 0; i < 2; ++i)
      {
        rungValue.sectors[i] = input.faceSector[this->sub.globalFace[r.edgeFaces(e)[i]]];
      }
      // Every second rung: greedily the rungs sharing no vertex with an earlier one, in order
      // around the ring (on a ladder, every second one).
      if (!used[rungValue.s] && !used[rungValue.t])
      {
        rungValue.collapsible = true;
        used[rungValue.s] = used[rungValue.t] = 1;
      }
      ring.rungs.push_back(rungValue);
    }
  }
}

// The part of rung (s, t)'s rest vector along the ring (tau), from the ring's boundary edges in
// the rung's two triangles. Splits and collapses insert or remove only the rest: the strip's
// height, not a shift along the ring (which would twist the surface).
Vec3 GeometrySeamCarving::Implementation::alongRing(const EditableMesh& m, const Ring& ring, VH s, VH t, HH h) const
{
  const Vec3 rung = this->restVector(m, h);
  Vec3 tangent(0.0, 0.0, 0.0);
  for (const HH side : { h, m.opposite_halfedge_handle(h) })
  {
    if (m.is_boundary(side))
    {
      continue;
    }
    const VH l = m.to_vertex_handle(m.next_halfedge_handle(side));
    const char where = this->sideOf(ring, l);
    Vec3 edge(0.0, 0.0, 0.0);
    if (where == HandleSide)
    {
      edge = this->restVector(m, m.find_halfedge(s, l));
    }
    else if (where == FixedSide)
    {
      edge = this->restVector(m, m.find_halfedge(t, l));
    }
    if (OpenMesh::dot(edge, tangent) < 0.0)
    {
      edge = -edge;
    }
    tangent += edge;
  }
  const double length = tangent.norm();
  return length > 0.0 ? Vec3(OpenMesh::dot(rung, tangent) / (length * length) * tangent) : Vec3(0.0, 0.0, 0.0);
}

char GeometrySeamCarving::Implementation::sideOf(const Ring& ring, VH v) const
{
  return v.idx() < static_cast<int>(ring.side.size()) ? ring.side[v.idx()] : static_cast<char>(NoSide);
}

// Eq. 9 of Dekkers and Kobbelt 2014 with rest lengths: omega' = |r'| / |r| omega.
double scaledWeight(double weight, const Vec3& before, const Vec3& after)
{
  return weight * after.norm() / std::max(before.norm(), 1e-300);
}

// A split of rung (s, t) at its midpoint m (Dekkers and Kobbelt 2014, 3.3.2, Fig. 5b). The rest
// geometry gains the strip's height n = r - tau: towards the handle side m stands at
// mid + n / 2, towards the fixed side at mid - n / 2, so that the sector's rest area grows by the
// segment's. Weights follow Eq. 9 with rest lengths; the wing edges average the two they replace.
void GeometrySeamCarving::Implementation::split(EditableMesh& m, const Ring& ring, VH s, VH t, int ringIndex)
{
  const HH h = m.find_halfedge(s, t);
  if (!h.is_valid())
  {
    ++this->skipped;
    return;
  }
  const Vec3 rung = this->restVector(m, h);
  const Vec3 tau = this->alongRing(m, ring, s, t, h);
  const Vec3 half = 0.5 * tau + (rung - tau); // s -> m and m -> t
  const double rungWeight = scaledWeight(m.property(this->weight, m.edge_handle(h)), rung, half);
  struct Wing
  {
    VH v;
    Vec3 rest; // from the wing to m
    double weight;
  };
  std::vector<Wing> wings;
  for (const HH side : { h, m.opposite_halfedge_handle(h) })
  {
    if (m.is_boundary(side))
    {
      continue;
    }
    const VH l = m.to_vertex_handle(m.next_halfedge_handle(side));
    const HH ls = m.find_halfedge(l, s), lt = m.find_halfedge(l, t);
    const Vec3 toS = this->restVector(m, ls), toT = this->restVector(m, lt);
    const double ws = m.property(this->weight, m.edge_handle(ls)), wt = m.property(this->weight, m.edge_handle(lt));
    const char where = this->sideOf(ring, l);
    const Vec3 rest = where == HandleSide ? Vec3(toS + half)
      : where == FixedSide                ? Vec3(toT - half)
                                          : Vec3(0.5 * (toS + toT));
    // Dekkers and Kobbelt 2014, 3.3.2: omega'_{l,new} = 1/2 (|l - new| / |l - s| omega_{l,s} + |l - new| / |l - t|
    // omega_{l,t}).
    wings.push_back({ l, rest, 0.5 * (scaledWeight(ws, toS, rest) + scaledWeight(wt, toT, rest)) });
  }
  const VH mid = m.add_vertex(0.5 * (m.point(s) + m.point(t)));
  m.property(this->role, mid) = FreePoint;
  m.property(this->origin, mid) = -1;
  m.property(this->stiffness, mid) = 0.5 * (m.property(this->stiffness, s) + m.property(this->stiffness, t));
  // Eliminated right after the later of its rung's ends, so that the rest state's ordering serves.
  m.property(this->rank, mid) = std::max(m.property(this->rank, s), m.property(this->rank, t));
  m.property(this->tie, mid) = static_cast<int>(mid.idx());
  m.split_copy(m.edge_handle(h), mid);
  for (const FH f : m.vf_range(mid))
  {
    m.property(this->faceRing, f) = ringIndex;
  }
  this->setRest(m, m.find_halfedge(s, mid), half, rungWeight);
  this->setRest(m, m.find_halfedge(mid, t), half, rungWeight);
  for (const Wing& wing : wings)
  {
    this->setRest(m, m.find_halfedge(wing.v, mid), wing.rest, wing.weight);
  }
}

// A collapse of rung (s, t) into one vertex v (Dekkers and Kobbelt 2014, 3.3.2, Fig. 5a): the
// rest geometry loses the strip's height n = r - tau; v stands at s + tau / 2 towards the handle
// side and at t - tau / 2 towards the fixed side, so the sector's rest area shrinks by the
// segment's. The kept vertex is a free one (constrained points stay where they are).
bool GeometrySeamCarving::Implementation::collapse(
  EditableMesh& m, const Ring& ring, VH s, VH t, std::vector<int>& alias)
{
  const bool sFree = m.property(this->role, s) == FreePoint, tFree = m.property(this->role, t) == FreePoint;
  if (!sFree && !tFree)
  {
    return false;
  }
  const VH removed = tFree ? t : s, kept = tFree ? s : t;
  const HH h = m.find_halfedge(removed, kept);
  if (!h.is_valid() || !m.is_collapse_ok(h))
  {
    return false;
  }
  const HH st = m.find_halfedge(s, t);
  const Vec3 tau = this->alongRing(m, ring, s, t, st);
  // Every neighbour's new rest vector from v and weight, from its edges to s and t.
  struct Neighbor
  {
    VH v;
    Vec3 rest;
    double weight;
  };
  std::map<int, std::pair<Vec3, double>> fromS, fromT;
  for (const HH out : m.voh_range(s))
  {
    fromS[m.to_vertex_handle(out).idx()] = { this->restVector(m, out), m.property(this->weight, m.edge_handle(out)) };
  }
  for (const HH out : m.voh_range(t))
  {
    fromT[m.to_vertex_handle(out).idx()] = { this->restVector(m, out), m.property(this->weight, m.edge_handle(out)) };
  }
  std::vector<Neighbor> neighbors;
  for (const auto& [index, viaS] : fromS)
  {
    if (index == t.idx())
    {
      continue;
    }
    const auto viaT = fromT.find(index);
    const Vec3 shiftedS = viaS.first - 0.5 * tau;
    if (viaT == fromT.end())
    {
      neighbors.push_back({ VH(index), shiftedS, scaledWeight(viaS.second, viaS.first, shiftedS) });
      continue;
    }
    // A wing: its edges to s and t become one.
    const Vec3 shiftedT = viaT->second.first + 0.5 * tau;
    const char where = this->sideOf(ring, VH(index));
    const Vec3 rest = where == HandleSide ? shiftedS
      : where == FixedSide                ? shiftedT
                                          : Vec3(0.5 * (viaS.first + viaT->second.first));
    neighbors.push_back({ VH(index), rest,
      0.5 *
        (scaledWeight(viaS.second, viaS.first, rest) + scaledWeight(viaT->second.second, viaT->second.first, rest)) });
  }
  for (const auto& [index, viaT] : fromT)
  {
    if (index != s.idx() && fromS.find(index) == fromS.end())
    {
      const Vec3 shiftedT = viaT.first + 0.5 * tau;
      neighbors.push_back({ VH(index), shiftedT, scaledWeight(viaT.second, viaT.first, shiftedT) });
    }
  }
  m.collapse(h);
  alias[removed.idx()] = kept.idx();
  for (const Neighbor& neighbor : neighbors)
  {
    const HH e = m.find_halfedge(kept, neighbor.v);
    if (e.is_valid())
    {
      this->setRest(m, e, neighbor.rest, neighbor.weight);
    }
  }
  return true;
}

double GeometrySeamCarving::Implementation::restAreaOf(int sector) const
{
  double area = this->sectorRestArea[sector];
  const int count = this->state[sector];
  for (int i = 0; i < std::abs(count); ++i)
  {
    area += (count > 0 ? 1.0 : -1.0) * this->segmentArea[sector][this->order[sector][i]];
  }
  return area;
}

// The mesh of the current state, rebuilt from the rest state: every executed ring, in ring order.
void GeometrySeamCarving::Implementation::buildState()
{
  this->current = this->base;
  this->skipped = 0;
  EditableMesh& m = this->current;
  // What each sector does with each ring.
  const int ringCount = static_cast<int>(this->rings.size());
  std::vector<std::vector<int>> operation(static_cast<std::size_t>(ringCount), std::vector<int>(this->sectors, 0));
  for (int j = 0; j < this->sectors; ++j)
  {
    for (int i = 0; i < std::abs(this->state[j]); ++i)
    {
      operation[this->order[j][i]][j] = this->state[j] > 0 ? 1 : -1;
    }
  }
  std::vector<int> alias(this->base.n_vertices(), -1);
  auto resolve = [&](int v) {
    while (v < static_cast<int>(alias.size()) && alias[v] >= 0)
    {
      v = alias[v];
    }
    return VH(v);
  };
  for (int k = 0; k < ringCount; ++k)
  {
    const Ring& ring = this->rings[k];
    for (const Rung& rung : ring.rungs)
    {
      // A rung between two sectors follows them when they agree or one of them is idle.
      int wanted = 0;
      bool conflict = false;
      for (int sector : rung.sectors)
      {
        const int op = sector >= 0 ? operation[k][sector] : 0;
        if (op != 0)
        {
          conflict |= wanted != 0 && wanted != op;
          wanted = op;
        }
      }
      if (conflict || wanted == 0)
      {
        continue;
      }
      const VH s = resolve(rung.s), t = resolve(rung.t);
      if (wanted > 0)
      {
        this->split(m, ring, s, t, k);
        alias.resize(m.n_vertices(), -1);
      }
      else if (rung.collapsible && !this->collapse(m, ring, s, t, alias))
      {
        ++this->skipped;
      }
    }
  }
  this->corners.clear();
  this->corners.reserve(m.n_faces());
  for (const FH f : m.faces())
  {
    std::array<int, 4> c{};
    int k = 0;
    for (const VH v : m.fv_range(f))
    {
      c[k++] = v.idx();
    }
    c[3] = m.property(this->faceSector, f);
    this->corners.push_back(c);
  }
  this->builtState = this->state;
  this->built = true;
  this->assemble();
}

// The linear system of the weighted Laplace editing on the current mesh: with edge springs,
// sum_e w_e |x_j - x_i - r_ij|^2 is minimised, so that L_M x' = div r on the free points, the
// form of ||L_M x' - L_init x||^2 (Dekkers and Kobbelt 2014, Eq. 8) whose rows are the free points.
// w_e is omega_e times the mean of the end points' stiffness (Eq. 7): scaling the rows of a square
// system would not change its solution, scaling the springs does.
void GeometrySeamCarving::Implementation::assemble()
{
  const EditableMesh& m = this->current;
  this->freeIndex.assign(m.n_vertices(), -1);
  this->unknowns = 0;
  for (const VH v : m.vertices())
  {
    if (m.property(this->role, v) == FreePoint)
    {
      this->freeIndex[v.idx()] = this->unknowns++;
    }
  }
  // Column by column, the free points in index order, the lower triangle only (SparseCholesky
  // reads no more): one pass over each point's edges, without triplets to sort.
  Eigen::SparseMatrix<double> matrix(this->unknowns, this->unknowns);
  matrix.reserve(static_cast<Eigen::Index>(m.n_edges()) + this->unknowns);
  std::vector<Eigen::Triplet<double>> c;
  this->restRhs.setZero(this->unknowns, 3);
  std::vector<std::pair<int, double>> below;
  for (const VH v : m.vertices())
  {
    const int fi = this->freeIndex[v.idx()];
    if (fi < 0)
    {
      continue;
    }
    matrix.startVec(fi);
    const double stiffness = m.property(this->stiffness, v);
    double diagonal = 0.0;
    Vec3 rhs(0.0, 0.0, 0.0);
    below.clear();
    for (const HH h : m.voh_range(v))
    {
      const VH u = m.to_vertex_handle(h);
      const double w = m.property(this->weight, m.edge_handle(h)) * 0.5 * (stiffness + m.property(this->stiffness, u));
      diagonal += w;
      rhs -= w * this->restVector(m, h); // the rest vector from v to u
      const int fj = this->freeIndex[u.idx()];
      if (fj > fi)
      {
        below.emplace_back(fj, -w);
      }
      else if (fj < 0)
      {
        c.emplace_back(fi, u.idx(), w);
      }
    }
    std::sort(below.begin(), below.end());
    matrix.insertBack(fi, fi) = diagonal;
    for (const std::pair<int, double>& entry : below)
    {
      matrix.insertBack(entry.first, fi) = entry.second;
    }
    this->restRhs.row(fi) = Eigen::RowVector3d(rhs[0], rhs[1], rhs[2]);
  }
  matrix.finalize();
  this->coupling.resize(this->unknowns, static_cast<Eigen::Index>(m.n_vertices()));
  this->coupling.setFromTriplets(c.begin(), c.end());
  // The rest state is ordered by AMD; every other state reuses that order, extended by the split
  // points, which skips the ordering (a third of a factorization at 100k triangles).
  bool factored = false;
  if (this->ordered)
  {
    std::vector<int> order(static_cast<std::size_t>(this->unknowns));
    std::vector<std::pair<std::uint64_t, int>> keys; // rank, then tie
    keys.reserve(order.size());
    for (const VH v : m.vertices())
    {
      const int i = this->freeIndex[v.idx()];
      if (i >= 0)
      {
        const std::uint64_t key = static_cast<std::uint64_t>(m.property(this->rank, v)) << 32 |
          static_cast<std::uint32_t>(m.property(this->tie, v));
        keys.push_back({ key, i });
      }
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t k = 0; k < keys.size(); ++k)
    {
      order[k] = keys[k].second;
    }
    factored = this->factor.factor(matrix, order);
  }
  else
  {
    factored = this->factor.factor(matrix);
    const std::vector<int> order = this->factor.permutation();
    if (!order.empty())
    {
      std::vector<int> vertexOf(static_cast<std::size_t>(this->unknowns));
      for (const VH v : m.vertices())
      {
        if (this->freeIndex[v.idx()] >= 0)
        {
          vertexOf[this->freeIndex[v.idx()]] = v.idx();
        }
      }
      for (std::size_t k = 0; k < order.size(); ++k)
      {
        this->base.property(this->rank, VH(vertexOf[order[k]])) = static_cast<int>(k);
      }
      this->ordered = true;
    }
  }
  if (!factored)
  {
    throw Error("the Laplace editing system of the modeling region is not positive definite");
  }
}

void GeometrySeamCarving::Implementation::solve(const Eigen::Matrix4d& transform, std::vector<Vector3>& positions) const
{
  const EditableMesh& m = this->current;
  positions.assign(m.n_vertices(), Vector3::Zero());
  Eigen::MatrixXd constrained = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m.n_vertices()), 3);
  for (const VH v : m.vertices())
  {
    const int r = m.property(this->role, v);
    if (r == FreePoint)
    {
      continue;
    }
    const Vector3 p = toVector(m.point(v));
    const Vector3 q = r == HandlePoint ? Vector3((transform * p.homogeneous()).head<3>()) : p;
    positions[v.idx()] = q;
    constrained.row(v.idx()) = q.transpose();
  }
  const Eigen::MatrixXd rhs = this->restRhs + this->coupling * constrained;
  const Eigen::MatrixXd x = this->factor.solveBlock(rhs);
  for (const VH v : m.vertices())
  {
    const int i = this->freeIndex[v.idx()];
    if (i >= 0)
    {
      positions[v.idx()] = x.row(i).transpose();
    }
  }
}

GeometrySeamCarving::GeometrySeamCarving(const SeamCarvingInput& input, const SeamCarvingOptions& options)
  : Impl(new Implementation)
{
  Implementation& d = *this->Impl;
  if (!input.mesh)
  {
    throw Error("no surface was given");
  }
  const TriangleMesh& mesh = *input.mesh;
  const std::size_t faces = static_cast<std::size_t>(mesh.faceCount());
  const std::size_t points = static_cast<std::size_t>(mesh.vertexCount());
  if (input.faceRing.size() != faces || input.faceSector.size() != faces || input.faceCost.size() != faces)
  {
    throw Error("the ring, sector and cost arrays need one value per triangle (" + std::to_string(faces) + ")");
  }
  if (input.region.size() != points || input.normalConeAngle.size() != points)
  {
    throw Error("the region and normal-cone arrays need one value per point (" + std::to_string(points) + ")");
  }
  if (!std::isfinite(options.stiffnessScale) || options.stiffnessScale < 0.0 ||
    !std::isfinite(options.stiffnessEpsilon) || options.stiffnessEpsilon <= 0.0)
  {
    throw Error("the stiffness scale must be finite and non-negative and the stiffness epsilon positive");
  }
  if (!(options.salientThreshold >= 0.0 && options.salientThreshold <= 1.0))
  {
    throw Error("the salient threshold must lie in [0, 1] (1 executes every segment)");
  }
  d.options = options;
  d.mesh = &mesh;
  d.modelingFaces = checkSeamRegions(mesh, input.region);
  d.label.resize(points);
  for (std::size_t v = 0; v < points; ++v)
  {
    d.label[v] = static_cast<int>(input.region[v]);
  }
  d.isModelingFace.assign(faces, 0);
  for (int f : d.modelingFaces)
  {
    d.isModelingFace[f] = 1;
    if (input.faceSector[f] < 0)
    {
      throw Error("modeling triangle " + std::to_string(f) +
        " has no sector; use the output of Geometry Seams computed on the same regions");
    }
    d.sectors = std::max(d.sectors, input.faceSector[f] + 1);
  }
  for (std::size_t f = 0; f < faces; ++f)
  {
    if (!d.isModelingFace[f] && input.faceRing[f] >= 0)
    {
      throw Error("triangle " + std::to_string(f) +
        " lies in a ring seam but outside the modeling region; use the output of Geometry Seams computed on the same "
        "regions");
    }
  }
  for (double angle : input.normalConeAngle)
  {
    if (!std::isfinite(angle))
    {
      throw Error("the normal-cone angles hold a NaN or infinite value");
    }
  }
  d.buildBase(input);
  d.findRings(input);

  // ang(v) scaled linearly to [0, 1] over the modeling region's points, as Eq. 3's saliency term.
  double lowAngle = std::numeric_limits<double>::infinity(), highAngle = -lowAngle;
  for (int f : d.modelingFaces)
  {
    for (int v : mesh.triangle(f))
    {
      lowAngle = std::min(lowAngle, input.normalConeAngle[v]);
      highAngle = std::max(highAngle, input.normalConeAngle[v]);
    }
  }
  // Angles that differ by less than 1e-3 rad over the whole region (a plain tube's, up to rounding)
  // hold no feature: scaled, their rounding noise would fill [0, 1].
  auto salient = [&](const Triangle& t) {
    const double threshold = lowAngle + options.salientThreshold * (highAngle - lowAngle);
    return options.salientThreshold < 1.0 && highAngle - lowAngle > 1e-3 &&
      std::max({ input.normalConeAngle[t[0]], input.normalConeAngle[t[1]], input.normalConeAngle[t[2]] }) > threshold;
  };

  // Per sector: rest area, each ring segment's area, its Eq. 6 error and whether it is salient,
  // the execution order.
  const int ringCount = static_cast<int>(d.rings.size());
  d.sectorRestArea.assign(d.sectors, 0.0);
  d.segmentArea.assign(d.sectors, std::vector<double>(ringCount, 0.0));
  std::vector<std::vector<double>> error(d.sectors, std::vector<double>(ringCount, 0.0));
  std::vector<std::vector<char>> isSalient(d.sectors, std::vector<char>(ringCount, 0));
  for (int f : d.modelingFaces)
  {
    const Triangle& t = mesh.triangle(f);
    const double area = triangleArea(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]));
    const int j = input.faceSector[f];
    d.sectorRestArea[j] += area;
    const int k = input.faceRing[f];
    if (k >= 0)
    {
      d.segmentArea[j][k] += area;
      // Dekkers and Kobbelt 2014, Eq. 6, with each triangle's mean edge cost standing for its edges'.
      error[j][k] += std::max(0.0, input.faceCost[f]);
      isSalient[j][k] |= salient(t) ? 1 : 0;
    }
  }
  d.order.assign(d.sectors, std::vector<int>());
  for (int j = 0; j < d.sectors; ++j)
  {
    for (int k = 0; k < ringCount; ++k)
    {
      if (d.segmentArea[j][k] > 0.0 && isSalient[j][k])
      {
        ++d.salientSegments;
      }
      else if (d.segmentArea[j][k] > 0.0)
      {
        d.order[j].push_back(k);
      }
    }
    std::stable_sort(d.order[j].begin(), d.order[j].end(), [&](int a, int b) { return error[j][a] < error[j][b]; });
  }
  d.state.assign(d.sectors, 0);
}

GeometrySeamCarving::~GeometrySeamCarving() = default;

int GeometrySeamCarving::sectorCount() const
{
  return this->Impl->sectors;
}

int GeometrySeamCarving::ringCount() const
{
  return static_cast<int>(this->Impl->rings.size());
}

const std::vector<std::vector<int>>& GeometrySeamCarving::executionOrder() const
{
  return this->Impl->order;
}

int GeometrySeamCarving::salientSegmentCount() const
{
  return this->Impl->salientSegments;
}

const SeamCarvingResult& GeometrySeamCarving::deform(const Eigen::Matrix4d& handleTransform)
{
  checkTransform(handleTransform);
  Implementation& d = *this->Impl;
  SeamCarvingResult& out = d.result;
  out.solves = 0;
  out.factorizations = 0;
  std::vector<Vector3> positions;
  std::vector<double> distortion(d.sectors, 0.0);
  // Each pass executes or undoes at most one segment per sector (Dekkers and Kobbelt 2014,
  // 3.3.1); a segment is executed when |d(A_j)| exceeds half its area and undone when the sign
  // reverses by more than half the last one's area, which keeps a state stable once reached.
  // Within one call a sector moves one way only (executing, or undoing), so that a segment whose
  // execution overshoots is kept until the next call rather than done and undone in turn.
  const int passes = 2 * static_cast<int>(d.rings.size()) + 2;
  std::vector<int> direction(d.sectors, 0);
  for (int pass = 0; pass <= passes; ++pass)
  {
    if (!d.built || d.builtState != d.state)
    {
      d.buildState();
      ++out.factorizations;
    }
    d.solve(handleTransform, positions);
    ++out.solves;
    std::fill(distortion.begin(), distortion.end(), 0.0);
    for (std::size_t f = 0; f < d.corners.size(); ++f)
    {
      const std::array<int, 4>& c = d.corners[f];
      distortion[c[3]] += triangleArea(positions[c[0]], positions[c[1]], positions[c[2]]);
    }
    bool changed = false;
    for (int j = 0; j < d.sectors; ++j)
    {
      distortion[j] -= d.restAreaOf(j); // Dekkers and Kobbelt 2014, Eq. 5
      if (!d.options.plastic || pass == passes)
      {
        continue;
      }
      const int count = d.state[j];
      const int executed = std::abs(count);
      const std::vector<int>& order = d.order[j];
      const double last = executed > 0 ? d.segmentArea[j][order[executed - 1]] : 0.0;
      const double next = executed < static_cast<int>(order.size()) ? d.segmentArea[j][order[executed]] : 0.0;
      if (distortion[j] > 0.0)
      {
        if (count < 0 && distortion[j] > 0.5 * last)
        {
          d.state[j] += 1; // undo the last collapse
        }
        else if (count >= 0 && next > 0.0 && distortion[j] > 0.5 * next)
        {
          d.state[j] += 1; // split the next ring
        }
      }
      else if (distortion[j] < 0.0)
      {
        if (count > 0 && -distortion[j] > 0.5 * last)
        {
          d.state[j] -= 1; // undo the last split
        }
        else if (count <= 0 && next > 0.0 && -distortion[j] > 0.5 * next)
        {
          d.state[j] -= 1; // collapse the next ring
        }
      }
      const int step = d.state[j] - count;
      if (step != 0 && direction[j] != 0 && step != direction[j])
      {
        d.state[j] = count;
      }
      else if (step != 0)
      {
        direction[j] = step;
        changed = true;
      }
    }
    if (!changed)
    {
      break;
    }
  }

  // The whole surface: surviving input points in order, then the points splits made; the input
  // triangles in order, each followed by the triangles split from it.
  const TriangleMesh& mesh = *d.mesh;
  const EditableMesh& m = d.current;
  std::vector<int> subOfGlobal(mesh.vertexCount(), -1);
  for (std::size_t v = 0; v < d.sub.globalVertex.size(); ++v)
  {
    subOfGlobal[d.sub.globalVertex[v]] = static_cast<int>(v);
  }
  out.points.clear();
  out.pointOrigin.clear();
  std::vector<int> globalIndex(mesh.vertexCount(), -1), subIndex(m.n_vertices(), -1);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const int local = subOfGlobal[v];
    if (local >= 0 && m.status(VH(local)).deleted())
    {
      continue;
    }
    globalIndex[v] = static_cast<int>(out.points.size());
    if (local >= 0)
    {
      subIndex[local] = globalIndex[v];
      out.points.push_back(positions[local]);
    }
    else
    {
      const Vector3& p = mesh.point(v);
      out.points.push_back(d.label[v] == HandlePoint ? Vector3((handleTransform * p.homogeneous()).head<3>()) : p);
    }
    out.pointOrigin.push_back(v);
  }
  for (const VH v : m.vertices())
  {
    if (v.idx() >= static_cast<int>(d.sub.globalVertex.size()))
    {
      subIndex[v.idx()] = static_cast<int>(out.points.size());
      out.points.push_back(positions[v.idx()]);
      out.pointOrigin.push_back(-1);
    }
  }
  // The current faces grouped by the input triangle they came from (a counting sort: handles stay
  // in increasing order within each group).
  std::vector<int> childStart(mesh.faceCount() + 1, 0);
  for (const FH f : m.faces())
  {
    ++childStart[m.property(d.faceOrigin, f) + 1];
  }
  std::partial_sum(childStart.begin(), childStart.end(), childStart.begin());
  std::vector<FH> children(static_cast<std::size_t>(childStart.back()));
  {
    std::vector<int> next(childStart.begin(), childStart.end() - 1);
    for (const FH f : m.faces())
    {
      children[next[m.property(d.faceOrigin, f)]++] = f;
    }
  }
  out.triangles.clear();
  out.faceRing.clear();
  out.faceSector.clear();
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (!d.isModelingFace[f])
    {
      const Triangle& t = mesh.triangle(f);
      out.triangles.push_back({ globalIndex[t[0]], globalIndex[t[1]], globalIndex[t[2]] });
      out.faceRing.push_back(-1);
      out.faceSector.push_back(-1);
      continue;
    }
    for (int c = childStart[f]; c < childStart[f + 1]; ++c)
    {
      const FH child = children[c];
      Triangle t{};
      int k = 0;
      for (const VH v : m.fv_range(child))
      {
        t[k++] = subIndex[v.idx()];
      }
      // An untouched triangle keeps the input's first corner.
      const Triangle& in = mesh.triangle(f);
      for (int turn = 0; turn < 3 && t[0] != globalIndex[in[0]]; ++turn)
      {
        std::rotate(t.begin(), t.begin() + 1, t.end());
      }
      out.triangles.push_back(t);
      out.faceRing.push_back(m.property(d.faceRing, child));
      out.faceSector.push_back(m.property(d.faceSector, child));
    }
  }
  out.sectorState = d.state;
  out.sectorDistortion = distortion;
  out.splitSegments = 0;
  out.collapsedSegments = 0;
  for (int count : d.state)
  {
    (count > 0 ? out.splitSegments : out.collapsedSegments) += std::abs(count);
  }
  out.skippedOperations = d.skipped;
  return out;
}

} // namespace kerf
