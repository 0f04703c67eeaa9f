// Builds the cube-based dumbbell (a subdivided cube, spread over the sphere, stretched like kerf::makeDumbbell) and
// strokes on it.
#include "BenchmarkMeshes.h"

#include "Error.h"
#include "Mesh/MeshGenerators.h"

#include <cmath>
#include <vector>

namespace kerf
{
namespace benchmarks
{

TriangleMesh MakeCubeDumbbell(
  double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth, int cells)
{
  if (cells < 1)
  {
    throw Error("a cube dumbbell needs at least one cell per cube edge");
  }
  const int side = cells + 1;
  // Lattice point (i, j, k) of the cube -> vertex, filled as the faces reach it.
  std::vector<int> vertexOfLattice(static_cast<std::size_t>(side) * side * side, -1);
  std::vector<Vector3> points;
  points.reserve(6 * static_cast<std::size_t>(cells) * cells + 2);
  auto vertex = [&](const std::array<int, 3>& lattice) {
    int& id = vertexOfLattice[(static_cast<std::size_t>(lattice[0]) * side + lattice[1]) * side + lattice[2]];
    if (id < 0)
    {
      id = static_cast<int>(points.size());
      const double x = 2.0 * lattice[0] / cells - 1.0;
      const double y = 2.0 * lattice[1] / cells - 1.0;
      const double z = 2.0 * lattice[2] / cells - 1.0;
      // A cube-to-sphere map that keeps the triangles' areas on the sphere within a factor of
      // 1.4 of each other (a plain normalisation: a factor of 5).
      const Vector3 p(x * std::sqrt(1.0 - y * y / 2.0 - z * z / 2.0 + y * y * z * z / 3.0),
        y * std::sqrt(1.0 - z * z / 2.0 - x * x / 2.0 + z * z * x * x / 3.0),
        z * std::sqrt(1.0 - x * x / 2.0 - y * y / 2.0 + x * x * y * y / 3.0));
      // As kerf::makeDumbbell does with its icosphere: stretch along z, radius from the profile.
      const double height = halfLength * p.z();
      const double around = std::hypot(p.x(), p.y());
      const double radius = dumbbellRadius(height, halfLength, lobeRadii, neckHeight, neckDepth);
      const double scale = around > 0.0 ? radius / around : 0.0;
      points.emplace_back(p.x() * scale, p.y() * scale, height);
    }
    return id;
  };

  std::vector<Triangle> triangles;
  triangles.reserve(12 * static_cast<std::size_t>(cells) * cells);
  for (int axis = 0; axis < 3; ++axis)
  {
    // (u, v, axis) is a right-handed frame, so (u, v) squares are counter-clockwise seen from +axis.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (const bool upper : { false, true })
    {
      for (int i = 0; i < cells; ++i)
      {
        for (int j = 0; j < cells; ++j)
        {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> lattice;
            lattice[axis] = upper ? cells : 0;
            lattice[u] = i + di;
            lattice[v] = j + dj;
            return vertex(lattice);
          };
          const int a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          if (upper)
          {
            triangles.push_back({ a, b, c });
            triangles.push_back({ a, c, d });
          }
          else
          {
            triangles.push_back({ a, c, b });
            triangles.push_back({ a, d, c });
          }
        }
      }
    }
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TriangleMesh MakeBenchmarkDumbbell(int cells)
{
  return MakeCubeDumbbell(DumbbellHalfLength, DumbbellLobeRadii, DumbbellNeckCentre, DumbbellNeckDepth, cells);
}

double DumbbellNeckHeight()
{
  double best = DumbbellNeckCentre, smallest = HUGE_VAL;
  for (double z = -0.5 * DumbbellHalfLength; z <= 0.5 * DumbbellHalfLength; z += 1e-4)
  {
    const double r = dumbbellRadius(z, DumbbellHalfLength, DumbbellLobeRadii, DumbbellNeckCentre, DumbbellNeckDepth);
    if (r < smallest)
    {
      smallest = r;
      best = z;
    }
  }
  return best;
}

std::vector<Vector3> DumbbellStroke(double height, double tilt, double firstAngle, double lastAngle, int count)
{
  std::vector<Vector3> points;
  for (int k = 0; k < count; ++k)
  {
    const double angle = firstAngle + (lastAngle - firstAngle) * k / (count - 1);
    const double z = height + tilt * std::cos(angle);
    const double r = dumbbellRadius(z, DumbbellHalfLength, DumbbellLobeRadii, DumbbellNeckCentre, DumbbellNeckDepth);
    points.emplace_back(r * std::cos(angle), r * std::sin(angle), z);
  }
  return points;
}

DumbbellStrokes MakeDumbbellStrokes()
{
  constexpr double Pi = 3.14159265358979323846;
  const double neck = DumbbellNeckHeight();
  DumbbellStrokes strokes;
  strokes.around[0] = DumbbellStroke(neck, 0.0, 0.0, 2.0 * Pi, 9);
  strokes.around[1] = DumbbellStroke(neck + 0.04, 0.03, Pi / 8.0, Pi / 8.0 + 2.0 * Pi, 9);
  strokes.refinement[0] = DumbbellStroke(neck - 0.03, 0.0, 0.5 * Pi, 1.5 * Pi, 9);
  strokes.refinement[1] = DumbbellStroke(neck + 0.03, 0.0, -0.5 * Pi, 0.5 * Pi, 9);
  return strokes;
}

} // namespace benchmarks
} // namespace kerf
