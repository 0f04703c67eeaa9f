// The closest-point locator against a search of every face: the same face, point and distance,
// ties to the lower face index, on surfaces with several components, degenerate triangles and
// queries on, near and far from them.
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace kerf;

namespace
{
// The nearest face, the first on ties; `equal` counts the faces at its distance.
ClosestPointLocator::Hit exhaustive(const TriangleMesh& mesh, const Vector3& query, int& equal)
{
  ClosestPointLocator::Hit best;
  best.distance = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    Vector3 barycentric;
    const Vector3 p = closestPointOnTriangle(query, mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
    const double d = (p - query).squaredNorm();
    equal = d == best.distance ? equal + 1 : (d < best.distance ? 1 : equal);
    if (d < best.distance)
    {
      best.face = f;
      best.distance = d;
      best.position = p;
      best.barycentric = barycentric;
    }
  }
  best.distance = std::sqrt(best.distance);
  return best;
}

// Two tori side by side, a grid whose vertices many triangles share (equal distances above
// them), an icosphere, and a few degenerate triangles (a repeated corner, collinear corners).
TriangleMesh mixedSurface()
{
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  auto append = [&points, &triangles](const TriangleMesh& part, const Vector3& shift) {
    const int base = static_cast<int>(points.size());
    for (int v = 0; v < part.vertexCount(); ++v)
    {
      points.push_back(part.point(v) + shift);
    }
    for (int f = 0; f < part.faceCount(); ++f)
    {
      const Triangle& t = part.triangle(f);
      triangles.push_back({ { t[0] + base, t[1] + base, t[2] + base } });
    }
  };
  append(makeTorus(1.0, 0.3, 40, 16), Vector3(0, 0, 0));
  append(makeTorus(1.0, 0.3, 40, 16), Vector3(2.5, 0, 0.2));
  append(makeGrid(2.0, 2.0, 16, 16), Vector3(-1, -1, -1.5));
  append(makeIcosphere(0.5, 2), Vector3(0, 2.5, 0));
  const int base = static_cast<int>(points.size());
  points.push_back(Vector3(4, 4, 4));
  points.push_back(Vector3(5, 4, 4));
  points.push_back(Vector3(6, 4, 4));
  triangles.push_back({ { base, base + 1, base + 2 } }); // collinear
  triangles.push_back({ { base, base, base + 1 } });     // a repeated corner
  return TriangleMesh(points, triangles);
}
} // namespace

TEST(ClosestPoint, LocatorEqualsTheSearchOfEveryFace)
{
  const TriangleMesh mesh = mixedSurface();
  const ClosestPointLocator locator(mesh);
  std::mt19937 random(5);
  std::uniform_int_distribution<int> face(0, mesh.faceCount() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Vector3> queries;
  for (int i = 0; i < 400; ++i)
  {
    // On a face, near it (1e-6 to 0.3 off), and anywhere around the surfaces.
    const Triangle& t = mesh.triangle(face(random));
    double a = unit(random), b = unit(random);
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    const Vector3 on =
      mesh.point(t[0]) + a * (mesh.point(t[1]) - mesh.point(t[0])) + b * (mesh.point(t[2]) - mesh.point(t[0]));
    queries.push_back(on);
    queries.push_back(
      on + std::pow(10.0, -6.0 + 5.5 * unit(random)) * Vector3(noise(random), noise(random), noise(random)));
    queries.push_back(Vector3(-3 + 10 * unit(random), -3 + 10 * unit(random), -3 + 10 * unit(random)));
  }
  // Exactly above grid vertices and edge midpoints: up to six faces at the same distance.
  for (int i = 0; i <= 16; i += 3)
  {
    for (int j = 0; j <= 16; j += 4)
    {
      queries.push_back(Vector3(-1 + 2.0 * i / 16, -1 + 2.0 * j / 16, -1.25));
      queries.push_back(Vector3(-1 + 2.0 * (i + 0.5) / 16, -1 + 2.0 * j / 16, -1.75));
    }
  }
  int ties = 0;
  for (const Vector3& q : queries)
  {
    const ClosestPointLocator::Hit hit = locator.closest(q);
    int equal = 0;
    const ClosestPointLocator::Hit reference = exhaustive(mesh, q, equal);
    ASSERT_EQ(hit.face, reference.face) << q.transpose();
    EXPECT_EQ(hit.distance, reference.distance);
    EXPECT_EQ(hit.position, reference.position);
    EXPECT_EQ(hit.barycentric, reference.barycentric);
    ties += equal > 1 ? 1 : 0;
  }
  EXPECT_GT(ties, 20); // the tie-break was exercised

  const TriangleMesh empty;
  EXPECT_EQ(ClosestPointLocator(empty).closest(Vector3::Zero()).face, -1);
}
