// Intrinsic edge flips to the Delaunay triangulation (Bobenko and Springborn 2007) and its cotangent Laplacian.
#include "Numerics/IntrinsicTriangulation.h"

#include "Error.h"
#include "Numerics/LaplacianWeights.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace kerf
{

namespace
{
// Heron's formula in Kahan's form (exact for needles): a >= b >= c after sorting.
double heronArea(double a, double b, double c)
{
  if (a < b)
  {
    std::swap(a, b);
  }
  if (a < c)
  {
    std::swap(a, c);
  }
  if (b < c)
  {
    std::swap(b, c);
  }
  const double product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return product > 0.0 ? 0.25 * std::sqrt(product) : 0.0;
}

// Cotangent of the angle opposite the side `opposite` in a triangle of area `area`.
double cotangentFromLengths(double opposite, double p, double q, double area)
{
  const double numerator = p * p + q * q - opposite * opposite;
  if (area <= 0.0)
  {
    return numerator >= 0.0 ? CotangentLimit : -CotangentLimit;
  }
  return std::clamp(numerator / (4.0 * area), -CotangentLimit, CotangentLimit);
}

// The apex of a triangle over the base from (0, 0) to (base, 0) with sides `fromOrigin` and
// `fromEnd`, above the base for side = 1 and below it for side = -1.
Eigen::Vector2d apex(double base, double fromOrigin, double fromEnd, double side)
{
  const double x = base > 0.0 ? (base * base + fromOrigin * fromOrigin - fromEnd * fromEnd) / (2.0 * base) : 0.0;
  const double y = std::sqrt(std::max(fromOrigin * fromOrigin - x * x, 0.0));
  return Eigen::Vector2d(x, side * y);
}
} // namespace

IntrinsicTriangulation::IntrinsicTriangulation(const TriangleMesh& mesh)
  : VertexCount(mesh.vertexCount())
  , Corners(mesh.triangles())
  , Lengths(mesh.faceCount())
  , Twins(mesh.faceCount())
{
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      this->Lengths[f][k] = (mesh.point(t[(k + 1) % 3]) - mesh.point(t[k])).norm();
      this->Twins[f][k] = -1;
      const int g = mesh.faceNeighbor(f, k);
      if (g < 0 || g == f)
      {
        continue;
      }
      // The neighbour must run along the edge the other way (consistent orientation).
      const Triangle& u = mesh.triangle(g);
      for (int m = 0; m < 3; ++m)
      {
        if (u[m] == t[(k + 1) % 3] && u[(m + 1) % 3] == t[k])
        {
          this->Twins[f][k] = 3 * g + m;
        }
      }
    }
  }
  // Keep twins symmetric (an inconsistent pair is unflippable on both sides).
  for (int f = 0; f < this->faceCount(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int h = this->Twins[f][k];
      if (h >= 0 && this->Twins[h / 3][h % 3] != 3 * f + k)
      {
        this->Twins[f][k] = -1;
      }
    }
  }
}

double IntrinsicTriangulation::area(int f) const
{
  const std::array<double, 3>& l = this->Lengths[f];
  return heronArea(l[0], l[1], l[2]);
}

double IntrinsicTriangulation::cotangent(int f, int k) const
{
  // The angle at corner k is opposite edge k + 1.
  const std::array<double, 3>& l = this->Lengths[f];
  return cotangentFromLengths(l[(k + 1) % 3], l[k], l[(k + 2) % 3], this->area(f));
}

std::array<Eigen::Vector2d, 3> IntrinsicTriangulation::layout(int f) const
{
  const std::array<double, 3>& l = this->Lengths[f];
  return { Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(l[0], 0.0), apex(l[0], l[2], l[1], 1.0) };
}

bool IntrinsicTriangulation::isDelaunay(int h) const
{
  const int t = this->twin(h);
  if (t < 0 || t / 3 == h / 3)
  {
    return true;
  }
  // Angles opposite the edge: at corner k + 2 of each triangle.
  const double sum = this->cotangent(h / 3, (h % 3 + 2) % 3) + this->cotangent(t / 3, (t % 3 + 2) % 3);
  return sum >= -1e-12;
}

void IntrinsicTriangulation::flip(int h)
{
  const int t = this->twin(h);
  const int A = h / 3, kA = h % 3, B = t / 3, kB = t % 3;
  // A = (a, b, c) with h from a to b; B = (b, a, d) with t from b to a.
  const int a = this->Corners[A][kA], b = this->Corners[A][(kA + 1) % 3], c = this->Corners[A][(kA + 2) % 3];
  const int d = this->Corners[B][(kB + 2) % 3];
  const double lab = this->Lengths[A][kA], lbc = this->Lengths[A][(kA + 1) % 3], lca = this->Lengths[A][(kA + 2) % 3];
  const double lad = this->Lengths[B][(kB + 1) % 3], ldb = this->Lengths[B][(kB + 2) % 3];
  // The new edge's length from the quadrilateral laid out in the plane.
  const double lcd = (apex(lab, lca, lbc, 1.0) - apex(lab, lad, ldb, -1.0)).norm();

  const int hBC = 3 * A + (kA + 1) % 3, hCA = 3 * A + (kA + 2) % 3;
  const int hAD = 3 * B + (kB + 1) % 3, hDB = 3 * B + (kB + 2) % 3;
  // Old halfedge -> new halfedge for the four outer edges: A becomes (c, a, d), B becomes (d, b, c).
  const std::pair<int, int> moves[4] = { { hCA, 3 * A + 0 }, { hAD, 3 * A + 1 }, { hDB, 3 * B + 0 },
    { hBC, 3 * B + 1 } };
  int outerTwins[4];
  for (int i = 0; i < 4; ++i)
  {
    int twin = this->twin(moves[i].first);
    for (const auto& move : moves)
    {
      if (twin == move.first)
      {
        twin = move.second;
        break;
      }
    }
    outerTwins[i] = twin;
  }
  this->Corners[A] = { c, a, d };
  this->Corners[B] = { d, b, c };
  this->Lengths[A] = { lca, lad, lcd };
  this->Lengths[B] = { ldb, lbc, lcd };
  for (int i = 0; i < 4; ++i)
  {
    const int n = moves[i].second;
    this->Twins[n / 3][n % 3] = outerTwins[i];
    if (outerTwins[i] >= 0)
    {
      this->Twins[outerTwins[i] / 3][outerTwins[i] % 3] = n;
    }
  }
  this->Twins[A][2] = 3 * B + 2;
  this->Twins[B][2] = 3 * A + 2;
}

int IntrinsicTriangulation::flipToDelaunay()
{
  const int halfedges = 3 * this->faceCount();
  std::vector<int> stack;
  std::vector<char> queued(halfedges, 0);
  for (int h = halfedges - 1; h >= 0; --h)
  {
    const int t = this->twin(h);
    if (t > h)
    {
      stack.push_back(h);
      queued[h] = 1;
    }
  }
  int flips = 0;
  const long long limit = 50LL * halfedges + 100;
  while (!stack.empty())
  {
    const int h = stack.back();
    stack.pop_back();
    queued[h] = 0;
    if (this->isDelaunay(h))
    {
      continue;
    }
    if (flips >= limit)
    {
      throw Error("the intrinsic Delaunay flips did not terminate; the mesh's edge lengths are degenerate");
    }
    this->flip(h);
    ++flips;
    const int A = h / 3, B = this->twin(h) / 3;
    for (int e : { 3 * A + 0, 3 * A + 1, 3 * B + 0, 3 * B + 1 })
    {
      const int t = this->twin(e);
      if (t < 0)
      {
        continue;
      }
      const int representative = std::min(e, t);
      if (!queued[representative])
      {
        queued[representative] = 1;
        stack.push_back(representative);
      }
    }
  }
  return flips;
}

std::vector<IntrinsicTriangulation::PairWeight> IntrinsicTriangulation::cotangentWeights() const
{
  std::vector<PairWeight> entries;
  entries.reserve(3 * this->Corners.size());
  for (int f = 0; f < this->faceCount(); ++f)
  {
    const Triangle& t = this->Corners[f];
    for (int k = 0; k < 3; ++k)
    {
      const int i = t[k], j = t[(k + 1) % 3];
      if (i == j)
      {
        continue;
      }
      entries.push_back({ std::min(i, j), std::max(i, j), 0.5 * this->cotangent(f, (k + 2) % 3) });
    }
  }
  std::sort(entries.begin(), entries.end(),
    [](const PairWeight& x, const PairWeight& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });
  std::vector<PairWeight> merged;
  for (const PairWeight& entry : entries)
  {
    if (!merged.empty() && merged.back().i == entry.i && merged.back().j == entry.j)
    {
      merged.back().weight += entry.weight;
    }
    else
    {
      merged.push_back(entry);
    }
  }
  for (PairWeight& entry : merged)
  {
    entry.weight = std::max(entry.weight, 0.0);
  }
  return merged;
}

std::vector<double> IntrinsicTriangulation::vertexAreas() const
{
  std::vector<double> areas(this->VertexCount, 0.0);
  for (int f = 0; f < this->faceCount(); ++f)
  {
    const double third = this->area(f) / 3.0;
    for (int v : this->Corners[f])
    {
      areas[v] += third;
    }
  }
  return areas;
}

IntrinsicDelaunayLaplacian intrinsicDelaunayLaplacian(const TriangleMesh& mesh)
{
  IntrinsicTriangulation triangulation(mesh);
  IntrinsicDelaunayLaplacian laplacian;
  laplacian.flips = triangulation.flipToDelaunay();
  laplacian.mesh = TriangleMesh(mesh.points(), triangulation.triangles());
  laplacian.weights.assign(laplacian.mesh.edgeCount(), 0.0);
  for (const IntrinsicTriangulation::PairWeight& pair : triangulation.cotangentWeights())
  {
    const IndexRange neighbors = laplacian.mesh.vertexNeighbors(pair.i);
    for (std::size_t n = 0; n < neighbors.size(); ++n)
    {
      if (neighbors[n] == pair.j)
      {
        laplacian.weights[laplacian.mesh.vertexEdges(pair.i)[n]] = pair.weight;
      }
    }
  }
  return laplacian;
}

} // namespace kerf
