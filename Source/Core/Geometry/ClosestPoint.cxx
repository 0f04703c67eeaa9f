// Bounding-volume hierarchy (faces in Morton order) and point-triangle distance (Ericson, RTCD 5.1.5).
#include "Geometry/ClosestPoint.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace kerf
{

Vector3 closestPointOnTriangle(
  const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c, Vector3& barycentric)
{
  const Vector3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    barycentric = Vector3(1, 0, 0);
    return a;
  }
  const Vector3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    barycentric = Vector3(0, 1, 0);
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0)
  {
    const double v = d1 / (d1 - d3);
    barycentric = Vector3(1 - v, v, 0);
    return a + v * ab;
  }
  const Vector3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    barycentric = Vector3(0, 0, 1);
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0)
  {
    const double w = d2 / (d2 - d6);
    barycentric = Vector3(1 - w, 0, w);
    return a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    barycentric = Vector3(0, 1 - w, w);
    return b + w * (c - b);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0))
  {
    // A degenerate triangle: its nearest corner.
    const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    barycentric = da <= db && da <= dc ? Vector3(1, 0, 0) : (db <= dc ? Vector3(0, 1, 0) : Vector3(0, 0, 1));
    return da <= db && da <= dc ? a : (db <= dc ? b : c);
  }
  const double v = vb / sum, w = vc / sum;
  barycentric = Vector3(1 - v - w, v, w);
  return a + ab * v + ac * w;
}

namespace
{
// The 21 low bits of v spread to every third bit.
std::uint64_t spreadBits(std::uint64_t v)
{
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

struct MortonKey
{
  std::uint64_t code;
  int face;
  bool operator<(const MortonKey& other) const
  {
    return this->code < other.code || (this->code == other.code && this->face < other.face);
  }
};
} // namespace

// The faces in the Morton (Z) order of their centroids, 21 bits per axis of the centroids' box,
// ties by face index; every node holds a contiguous range of that order, split in halves, and its
// box is its children's union. The order is one sort, where median splits along the longest axis
// select every level again (Boost's integer_sort instead of std::sort is no faster; the figures
// are in Documentation/architecture.md). Queries visit every box that can hold a
// point at least as near as the best so far and break ties by face index, so the closest point
// does not depend on the tree's shape.
ClosestPointLocator::ClosestPointLocator(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  const int faces = mesh.faceCount();
  std::vector<Vector3> centroids(faces);
  Eigen::AlignedBox3d box;
  for (int f = 0; f < faces; ++f)
  {
    const Triangle& t = mesh.triangle(f);
    centroids[f] = (mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0;
    if (centroids[f].allFinite())
    {
      box.extend(centroids[f]);
    }
  }
  std::vector<MortonKey> keys(faces);
  const double cells = static_cast<double>((1 << 21) - 1);
  for (int f = 0; f < faces; ++f)
  {
    std::uint64_t code = 0;
    if (centroids[f].allFinite())
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        const double extent = box.max()[axis] - box.min()[axis];
        const double t = extent > 0.0 ? (centroids[f][axis] - box.min()[axis]) / extent : 0.0;
        const double cell = std::min(cells, std::max(0.0, std::floor(t * cells)));
        code |= spreadBits(static_cast<std::uint64_t>(cell)) << axis;
      }
    }
    keys[f] = { code, f };
  }
  std::sort(keys.begin(), keys.end());
  this->FaceOrder.resize(faces);
  for (int i = 0; i < faces; ++i)
  {
    this->FaceOrder[i] = keys[i].face;
  }
  if (faces > 0)
  {
    // Leaves hold 2 to 4 faces (a split of 5 or more gives halves of 2 or more), so there are
    // fewer nodes than faces: one reservation, never a regrowth.
    this->Nodes.reserve(static_cast<std::size_t>(faces));
    this->build(0, faces);
  }
}

int ClosestPointLocator::build(int first, int count)
{
  const int index = static_cast<int>(this->Nodes.size());
  this->Nodes.emplace_back();
  if (count <= 4)
  {
    Eigen::AlignedBox3d box;
    for (int i = first; i < first + count; ++i)
    {
      for (int corner : this->Mesh.triangle(this->FaceOrder[i]))
      {
        box.extend(this->Mesh.point(corner));
      }
    }
    this->Nodes[index].box = box;
    this->Nodes[index].first = first;
    this->Nodes[index].count = count;
    return index;
  }
  const int half = count / 2;
  const int left = this->build(first, half);
  const int right = this->build(first + half, count - half);
  this->Nodes[index].box = this->Nodes[left].box.merged(this->Nodes[right].box);
  this->Nodes[index].first = left;
  this->Nodes[index].right = right;
  this->Nodes[index].count = 0;
  return index;
}

void ClosestPointLocator::search(int node, const Vector3& query, Hit& best) const
{
  const Node& n = this->Nodes[node];
  if (n.count > 0)
  {
    for (int i = n.first; i < n.first + n.count; ++i)
    {
      const int f = this->FaceOrder[i];
      const Triangle& t = this->Mesh.triangle(f);
      Vector3 barycentric;
      const Vector3 p = closestPointOnTriangle(
        query, this->Mesh.point(t[0]), this->Mesh.point(t[1]), this->Mesh.point(t[2]), barycentric);
      const double d = (p - query).squaredNorm();
      if (d < best.distance || (d == best.distance && f < best.face))
      {
        best.distance = d;
        best.face = f;
        best.barycentric = barycentric;
        best.position = p;
      }
    }
    return;
  }
  const int left = n.first;
  const int right = n.right;
  const double dl = this->Nodes[left].box.squaredExteriorDistance(query);
  const double dr = this->Nodes[right].box.squaredExteriorDistance(query);
  const int nearer = dl <= dr ? left : right;
  const int farther = dl <= dr ? right : left;
  const double dNear = std::min(dl, dr), dFar = std::max(dl, dr);
  if (dNear <= best.distance)
  {
    this->search(nearer, query, best);
  }
  if (dFar <= best.distance)
  {
    this->search(farther, query, best);
  }
}

ClosestPointLocator::Hit ClosestPointLocator::closest(const Vector3& query) const
{
  Hit best;
  best.distance = std::numeric_limits<double>::infinity();
  if (!this->Nodes.empty())
  {
    this->search(0, query, best);
  }
  best.distance = std::sqrt(best.distance);
  return best;
}

int snapToVertex(const TriangleMesh& mesh, const ClosestPointLocator::Hit& hit)
{
  int corner;
  hit.barycentric.maxCoeff(&corner);
  return mesh.triangle(hit.face)[corner];
}

} // namespace kerf
