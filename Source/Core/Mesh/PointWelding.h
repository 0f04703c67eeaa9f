// Finds points with identical coordinates, so that surfaces split at seams are joined again.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// For every point, the smallest index of a point with exactly the same coordinates (itself when
/// it is unique). Readers split vertices at texture or normal seams (OBJ) or per facet (STL);
/// welding them restores the surface's connectivity. Exact comparison keeps it deterministic and
/// free of tolerances; -0.0 equals 0.0. Points with NaN coordinates are never welded.
std::vector<int> findCoincidentPoints(const std::vector<Vector3>& points);

/// Replaces every triangle corner by its representative point.
void weldTriangles(const std::vector<int>& representative, std::vector<Triangle>& triangles);

} // namespace kerf
