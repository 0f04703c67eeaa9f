// Generated benchmark surfaces whose triangle count can be chosen finely, and strokes on the dumbbell.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>
#include <vector>

namespace kerf
{
namespace benchmarks
{

/// The surface of kerf::makeDumbbell (same parameters and profile, kerf::dumbbellRadius), built
/// from a cube whose faces are split into cells x cells squares of two triangles each, spread
/// over the sphere before the dumbbell's stretch: 12 cells^2 triangles and 6 cells^2 + 2
/// vertices, closed, outward oriented, every vertex of valence 6 but six cube corners of valence
/// 4. kerf::makeDumbbell's icosphere only gives 20 * 4^levels triangles.
TriangleMesh MakeCubeDumbbell(
  double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth, int cells);

/// The dumbbell of kerf's tests and benchmarks (TestConcavityCut, the harmonic-cut benchmarks).
constexpr double DumbbellHalfLength = 2.2;
constexpr std::array<double, 2> DumbbellLobeRadii = { { 1.0, 0.8 } };
constexpr double DumbbellNeckCentre = 0.3;
constexpr double DumbbellNeckDepth = 0.65;

/// The dumbbell's surface with `cells` x `cells` squares per cube face (MakeCubeDumbbell).
TriangleMesh MakeBenchmarkDumbbell(int cells);

/// Height of the narrowest circle of the dumbbell's profile (the pinch's centre moved by the
/// lobes' blend).
double DumbbellNeckHeight();

/// `count` points on the dumbbell's smooth surface at angles firstAngle..lastAngle about z, at
/// height height + tilt cos(angle); a full turn repeats its first point at the end (a closed
/// stroke).
std::vector<Vector3> DumbbellStroke(double height, double tilt, double firstAngle, double lastAngle, int count);

/// The benchmarks' strokes, of 9 points each.
struct DumbbellStrokes
{
  /// Closed strokes around the neck: level at the narrowest circle, and 0.04 higher, tilted by
  /// 0.03 and turned by pi / 8.
  std::array<std::vector<Vector3>, 2> around;
  /// Half loops 0.03 below and above the narrowest circle, on opposite sides.
  std::array<std::vector<Vector3>, 2> refinement;
};
DumbbellStrokes MakeDumbbellStrokes();

} // namespace benchmarks
} // namespace kerf
