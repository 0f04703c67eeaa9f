// A generated shape with known parts for the automatic segmentation tests: a body with three fingers.
#pragma once

#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace kerf
{
namespace test
{

// makeProtrusions' fingers: a sphere of radius 1 with three fingers of length 1 and angular
// width 0.35 in the xy plane (5,120 triangles).
constexpr int FingerCount = 3;
constexpr double FingerLength = 1.0, FingerWidth = 0.35;
constexpr double Pi = 3.14159265358979323846;

struct Fingers
{
  std::shared_ptr<Surface> surface =
    std::make_shared<Surface>(makeProtrusions(FingerCount, FingerLength, FingerWidth, 4));
  /// The construction's parts: a face belongs to the finger whose axis is nearest to its
  /// centroid's direction when that angle is below the crease's, else to the body.
  std::vector<int> parts;
  /// The crease: the angle from a finger's axis where the profile 1 + L exp(-(a / w)^4) bends
  /// most concavely (largest second derivative), 1.24 w.
  double creaseAngle = 0.0;

  Fingers()
  {
    const auto profile = [](double a) { return 1.0 + FingerLength * std::exp(-std::pow(a / FingerWidth, 4)); };
    double bend = -1e300;
    for (double a = FingerWidth; a < 2.0 * FingerWidth; a += 1e-4)
    {
      const double second = (profile(a + 1e-4) - 2.0 * profile(a) + profile(a - 1e-4)) / 1e-8;
      if (second > bend)
      {
        bend = second;
        this->creaseAngle = a;
      }
    }
    const TriangleMesh& mesh = this->surface->mesh();
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const Triangle& t = mesh.triangle(f);
      const Vector3 c = ((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0).normalized();
      int part = 0;
      for (int i = 0; i < FingerCount; ++i)
      {
        const Vector3 axis(std::cos(2 * Pi * i / FingerCount), std::sin(2 * Pi * i / FingerCount), 0.0);
        if (std::acos(std::max(-1.0, std::min(1.0, c.dot(axis)))) < this->creaseAngle)
        {
          part = i + 1;
        }
      }
      this->parts.push_back(part);
    }
  }
};

/// A mesh and a copy of it moved by `offset`, as one mesh of two components (the copy's vertices and
/// faces after the original's).
inline TriangleMesh withMovedCopy(const TriangleMesh& one, const Vector3& offset)
{
  std::vector<Vector3> points = one.points();
  std::vector<Triangle> triangles = one.triangles();
  for (const Vector3& p : one.points())
  {
    points.push_back(p + offset);
  }
  const int first = one.vertexCount();
  for (const Triangle& t : one.triangles())
  {
    triangles.push_back({ { t[0] + first, t[1] + first, t[2] + first } });
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

inline const Fingers& fingers()
{
  static const Fingers shape;
  return shape;
}

} // namespace test
} // namespace kerf
