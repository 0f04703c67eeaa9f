// Generated analytic surfaces for tests and benchmarks.
#include "Mesh/MeshGenerators.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace kerf
{

namespace
{
constexpr double Pi = 3.14159265358979323846;
}

TriangleMesh makeIcosphere(double radius, int levels)
{
  if (levels < 0 || levels > 9)
  {
    throw Error("icosphere subdivision level must be in [0, 9]");
  }
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vector3> points = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<Triangle> triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 },
    { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (Vector3& p : points)
  {
    p.normalize();
  }
  for (int level = 0; level < levels; ++level)
  {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      points.push_back((points[a] + points[b]).normalized());
      const int index = static_cast<int>(points.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(triangles.size() * 4);
    for (const Triangle& tri : triangles)
    {
      const int ab = midpoint(tri[0], tri[1]);
      const int bc = midpoint(tri[1], tri[2]);
      const int ca = midpoint(tri[2], tri[0]);
      finer.push_back({ tri[0], ab, ca });
      finer.push_back({ tri[1], bc, ab });
      finer.push_back({ tri[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    triangles = std::move(finer);
  }
  for (Vector3& p : points)
  {
    p *= radius;
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TriangleMesh makeTorus(double majorRadius, double minorRadius, int around, int tube)
{
  if (around < 3 || tube < 3)
  {
    throw Error("a torus needs at least 3 vertices around and across the tube");
  }
  std::vector<Vector3> points;
  points.reserve(static_cast<std::size_t>(around) * tube);
  for (int i = 0; i < around; ++i)
  {
    const double u = 2.0 * Pi * i / around;
    for (int j = 0; j < tube; ++j)
    {
      const double v = 2.0 * Pi * j / tube;
      const double r = majorRadius + minorRadius * std::cos(v);
      points.emplace_back(r * std::cos(u), r * std::sin(u), minorRadius * std::sin(v));
    }
  }
  std::vector<Triangle> triangles;
  triangles.reserve(2 * static_cast<std::size_t>(around) * tube);
  for (int i = 0; i < around; ++i)
  {
    const int i1 = (i + 1) % around;
    for (int j = 0; j < tube; ++j)
    {
      const int j1 = (j + 1) % tube;
      const int a = i * tube + j, b = i1 * tube + j, c = i1 * tube + j1, d = i * tube + j1;
      triangles.push_back({ a, b, c });
      triangles.push_back({ a, c, d });
    }
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TriangleMesh makeCylinder(double radius, double height, int around, int rings)
{
  if (around < 3 || rings < 2)
  {
    throw Error("a cylinder needs at least 3 vertices around and 2 rings");
  }
  std::vector<Vector3> points;
  for (int j = 0; j < rings; ++j)
  {
    const double z = height * j / (rings - 1);
    for (int i = 0; i < around; ++i)
    {
      const double u = 2.0 * Pi * i / around;
      points.emplace_back(radius * std::cos(u), radius * std::sin(u), z);
    }
  }
  std::vector<Triangle> triangles;
  for (int j = 0; j + 1 < rings; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const int i1 = (i + 1) % around;
      const int a = j * around + i, b = j * around + i1, c = (j + 1) * around + i1, d = (j + 1) * around + i;
      triangles.push_back({ a, b, c });
      triangles.push_back({ a, c, d });
    }
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TriangleMesh makeBumpyCylinder(
  double radius, double height, int around, int rings, int bumps, double bumpHeight, double bumpRadius, double bumpSize)
{
  if (bumps < 0 || !(bumpRadius > 0.0))
  {
    throw Error("a bumpy cylinder needs a bump count >= 0 and a positive bump radius");
  }
  return makeReliefCylinder(radius, height, around, rings, [&](double u, double z) {
    double offset = 0.0;
    for (int b = 0; b < bumps; ++b)
    {
      const double du = std::remainder(u - 2.0 * Pi * b / bumps, 2.0 * Pi);
      const double d2 = (radius * du) * (radius * du) + (z - bumpHeight) * (z - bumpHeight);
      const double s = 1.0 - d2 / (bumpRadius * bumpRadius);
      offset = std::max(offset, s > 0.0 ? bumpSize * s * s : 0.0);
    }
    return offset;
  });
}

TriangleMesh makeReliefCylinder(
  double radius, double height, int around, int rings, const std::function<double(double u, double z)>& offset)
{
  const TriangleMesh cylinder = makeCylinder(radius, height, around, rings);
  std::vector<Vector3> points = cylinder.points();
  for (Vector3& p : points)
  {
    const double scale = (radius + offset(std::atan2(p.y(), p.x()), p.z())) / radius;
    p.x() *= scale;
    p.y() *= scale;
  }
  return TriangleMesh(std::move(points), cylinder.triangles());
}

TriangleMesh makeFeatureTube(TubeFeature feature, int around, int rings)
{
  auto square = [](double x) { return x * x; };
  // 1 - (d / r)^2 for the distance d from (u0, z0) on the unrolled tube, clamped at 0.
  auto falloff = [&](double u, double z, double u0, double z0, double r) {
    return std::max(0.0, 1.0 - (square(std::remainder(u - u0, 2.0 * Pi)) + square(z - z0)) / square(r));
  };
  std::function<double(double, double)> offset;
  switch (feature)
  {
    case TubeFeature::Knob:
      offset = [&](double u, double z) { return 0.35 * square(falloff(u, z, 0.0, 2.0, 0.45)); };
      break;
    case TubeFeature::Groove:
      offset = [&](double, double z) { return -0.15 * square(std::max(0.0, 1.0 - square((z - 2.5) / 0.2))); };
      break;
    case TubeFeature::Crease:
      offset = [](double, double z) { return 0.08 * std::max(0.0, 1.0 - std::abs(z - 2.2) / 0.1); };
      break;
    case TubeFeature::Cups:
      offset = [&](double u, double z) {
        double height = 0.0;
        for (double z0 : { 1.5, 2.3, 3.1 })
        {
          const double s = falloff(u, z, 0.0, z0, 0.3);
          height = std::max(height, s > 0.0 ? 0.48 * s * (1.0 - s) : 0.0);
        }
        return height;
      };
      break;
    case TubeFeature::Ridge:
      offset = [&](double u, double) { return 0.2 * square(std::max(0.0, 1.0 - square(u / 0.25))); };
      break;
  }
  return makeReliefCylinder(1.0, 5.0, around, rings, offset);
}

std::vector<int> featureTubePoints(const TriangleMesh& mesh)
{
  std::vector<int> points;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const Vector3& p = mesh.point(v);
    if (std::abs(p.head<2>().norm() - 1.0) > 1e-3 && p.z() > 0.8 && p.z() < 4.2)
    {
      points.push_back(v);
    }
  }
  return points;
}

std::vector<double> heightBandRegions(const TriangleMesh& mesh, double handleTop, double fixedBottom)
{
  std::vector<double> region;
  for (const Vector3& p : mesh.points())
  {
    region.push_back(p.z() <= handleTop ? 2.0 : p.z() >= fixedBottom ? 0.0 : 1.0);
  }
  return region;
}

TriangleMesh makeGrid(double width, double height, int columns, int rows)
{
  if (columns < 1 || rows < 1)
  {
    throw Error("a grid needs at least one column and one row");
  }
  std::vector<Vector3> points;
  for (int j = 0; j <= rows; ++j)
  {
    for (int i = 0; i <= columns; ++i)
    {
      points.emplace_back(width * i / columns, height * j / rows, 0.0);
    }
  }
  std::vector<Triangle> triangles;
  const int stride = columns + 1;
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const int a = j * stride + i, b = a + 1, c = a + stride + 1, d = a + stride;
      triangles.push_back({ a, b, c });
      triangles.push_back({ a, c, d });
    }
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TriangleMesh makeSlitCylinder(double radius, double height, int around, int rings)
{
  const TriangleMesh grid = makeGrid(2.0 * M_PI * radius, height, around, rings);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    const double angle = p.x() / radius;
    p = Vector3(radius * std::cos(angle), radius * std::sin(angle), p.y());
  }
  return TriangleMesh(std::move(points), grid.triangles());
}

TriangleMesh makeConeSector(
  double halfAngle, double innerDistance, double outerDistance, double angle, int columns, int rows)
{
  const TriangleMesh grid = makeGrid(outerDistance - innerDistance, angle, columns, rows);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    const double distance = innerDistance + p.x();
    const double around = p.y();
    p = distance *
      Vector3(std::sin(halfAngle) * std::cos(around), std::sin(halfAngle) * std::sin(around), std::cos(halfAngle));
  }
  return TriangleMesh(std::move(points), grid.triangles());
}

std::vector<int> octantLabels(const TriangleMesh& mesh)
{
  std::vector<int> labels;
  labels.reserve(static_cast<std::size_t>(mesh.faceCount()));
  for (const Triangle& t : mesh.triangles())
  {
    const Vector3 c = mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2]);
    labels.push_back((c.x() > 0 ? 1 : 0) + (c.y() > 0 ? 2 : 0) + (c.z() > 0 ? 4 : 0));
  }
  return labels;
}

TriangleMesh makeJitteredGrid(int cells, double jitter, unsigned seed)
{
  const TriangleMesh grid = makeGrid(cells, cells, cells, cells);
  std::vector<Vector3> points = grid.points();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  for (int v = 0; v < grid.vertexCount(); ++v)
  {
    if (!grid.isBoundaryVertex(v))
    {
      points[v].x() += offset(random);
      points[v].y() += offset(random);
    }
  }
  return TriangleMesh(points, grid.triangles());
}

double dumbbellRadius(
  double z, double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth)
{
  const double s = std::clamp(z / halfLength, -1.0, 1.0);
  const double neck = neckHeight / halfLength;
  // Smooth step between the two lobe radii across the neck.
  const double blend = 0.5 * (1.0 + std::tanh((s - neck) / 0.15));
  const double lobe = (1.0 - blend) * lobeRadii[0] + blend * lobeRadii[1];
  const double pinch = 1.0 - neckDepth * std::exp(-((s - neck) / 0.2) * ((s - neck) / 0.2));
  return std::sqrt(std::max(0.0, 1.0 - s * s)) * lobe * pinch;
}

TriangleMesh makeDumbbell(
  double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth, int levels)
{
  const TriangleMesh sphere = makeIcosphere(1.0, levels);
  std::vector<Vector3> points = sphere.points();
  for (Vector3& p : points)
  {
    const double z = halfLength * p.z();
    const double around = std::hypot(p.x(), p.y());
    const double r = dumbbellRadius(z, halfLength, lobeRadii, neckHeight, neckDepth);
    const double scale = around > 0.0 ? r / around : 0.0;
    p = Vector3(p.x() * scale, p.y() * scale, z);
  }
  return TriangleMesh(std::move(points), sphere.triangles());
}

TriangleMesh makeProtrusions(int count, double length, double width, int levels)
{
  if (count < 1 || !(length >= 0.0) || !(width > 0.0))
  {
    throw Error("protrusions need a count of at least 1, a non-negative length and a positive width");
  }
  const TriangleMesh sphere = makeIcosphere(1.0, levels);
  std::vector<Vector3> points = sphere.points();
  for (Vector3& p : points)
  {
    double alpha = Pi;
    for (int i = 0; i < count; ++i)
    {
      const double angle = 2.0 * Pi * i / count;
      const Vector3 axis(std::cos(angle), std::sin(angle), 0.0);
      alpha = std::min(alpha, std::acos(std::clamp(p.dot(axis), -1.0, 1.0)));
    }
    p *= 1.0 + length * std::exp(-std::pow(alpha / width, 4.0));
  }
  return TriangleMesh(std::move(points), sphere.triangles());
}

} // namespace kerf
