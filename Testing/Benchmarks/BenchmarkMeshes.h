// Generated benchmark surfaces whose triangle count can be chosen finely.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>

namespace kerf
{
namespace benchmarks
{

/// The surface of kerf::makeDumbbell (same parameters and profile, kerf::dumbbellRadius), built
/// from a cube whose faces are split into cells x cells squares of two triangles each, spread
/// over the sphere before the dumbbell's stretch: 12 cells^2 triangles and 6 cells^2 + 2
/// vertices, closed, outward oriented, every vertex of valence 6 but six cube corners of valence
/// 4. kerf::makeDumbbell's icosphere only gives 20 * 4^levels triangles.
TriangleMesh MakeCubeDumbbell(double halfLength, const std::array<double, 2>& lobeRadii,
  double neckHeight, double neckDepth, int cells);

} // namespace benchmarks
} // namespace kerf
