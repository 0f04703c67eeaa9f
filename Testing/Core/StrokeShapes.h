// Generated shapes with labelled strokes for the region-growing and snake tests.
#pragma once

#include "Mesh/MeshGenerators.h"
#include "Segmentation/RegionGrowing.h"

#include <array>
#include <cmath>
#include <vector>

namespace kerf
{
namespace test
{

/// kerf::makeDumbbell with lobes of radii 1 and 0.8 and the neck pinched to a third off centre,
/// the height of its narrowest ring, and one short stroke on each lobe (label 1 below, 2 above).
struct DumbbellWithStrokes
{
  static constexpr double HalfLength = 2.2, NeckHeight = 0.3, Depth = 0.65;
  static constexpr std::array<double, 2> Radii{ { 1.0, 0.8 } };
  TriangleMesh mesh;
  double neckZ = 0.0;
  std::vector<LabelledStroke> strokes;

  explicit DumbbellWithStrokes(int levels)
    : mesh(makeDumbbell(HalfLength, Radii, NeckHeight, Depth, levels))
  {
    double narrowest = 1e300;
    for (double z = -0.5 * HalfLength; z <= 0.5 * HalfLength; z += 1e-4)
    {
      const double r = dumbbellRadius(z, HalfLength, Radii, NeckHeight, Depth);
      if (r < narrowest)
      {
        narrowest = r;
        this->neckZ = z;
      }
    }
    for (const auto& [label, heights] :
      { std::pair<int, std::array<double, 3>>{ 1, { -1.6, -1.5, -1.4 } }, { 2, { 1.4, 1.5, 1.6 } } })
    {
      LabelledStroke stroke;
      stroke.label = label;
      for (double z : heights)
      {
        stroke.points.emplace_back(dumbbellRadius(z, HalfLength, Radii, NeckHeight, Depth), 0.0, z);
      }
      this->strokes.push_back(stroke);
    }
  }
};

/// kerf::makeProtrusions with three fingers (length 1, width 0.35 rad) and four strokes: label 0
/// on the sphere's top (+z), labels 1 to 3 along fingers 0 to 2 near their tips.
struct ProtrusionsWithStrokes
{
  static constexpr int Count = 3;
  static constexpr double Length = 1.0, Width = 0.35;
  TriangleMesh mesh;
  std::vector<LabelledStroke> strokes;

  explicit ProtrusionsWithStrokes(int levels)
    : mesh(makeProtrusions(Count, Length, Width, levels))
  {
    LabelledStroke body;
    body.label = 0;
    body.points = { Vector3(0.1, 0.0, 0.995), Vector3(-0.1, 0.0, 0.995) };
    this->strokes.push_back(body);
    for (int i = 0; i < Count; ++i)
    {
      const double angle = 2.0 * 3.14159265358979323846 * i / Count;
      const Vector3 axis(std::cos(angle), std::sin(angle), 0.0);
      LabelledStroke finger;
      finger.label = i + 1;
      finger.points = { 1.9 * axis + Vector3(0, 0, 0.05), 1.9 * axis - Vector3(0, 0, 0.05) };
      this->strokes.push_back(finger);
    }
  }

  /// The finger (0 to Count - 1) whose axis is nearest to p's direction, and the angle to it.
  static int nearestFinger(const Vector3& p, double& angle)
  {
    int best = 0;
    angle = 10.0;
    for (int i = 0; i < Count; ++i)
    {
      const double a = 2.0 * 3.14159265358979323846 * i / Count;
      const double alpha =
        std::acos(std::max(-1.0, std::min(1.0, p.normalized().dot(Vector3(std::cos(a), std::sin(a), 0.0)))));
      if (alpha < angle)
      {
        angle = alpha;
        best = i;
      }
    }
    return best;
  }
};

} // namespace test
} // namespace kerf
