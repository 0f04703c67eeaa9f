// Points and polylines in space placed on a surface: projections, coincident vertices, curves inside triangles.
#pragma once

#include "Geodesic/SurfacePoint.h"

#include <string>
#include <vector>

namespace kerf
{

class Surface;

/// The surface point nearest to `position`. Throws kerf::Error naming `what` ("click 2", "the
/// seam's target") for non-finite or huge coordinates, a mesh without triangles, and a point
/// farther than `maximumDistance` (length units; infinity for no limit) from the surface.
SurfacePoint projectOntoSurface(
  const Surface& surface, const Vector3& position, double maximumDistance, const std::string& what);

/// The vertex a surface point coincides with (one barycentric coordinate within `tolerance` of
/// 1), or -1.
int coincidentVertex(const TriangleMesh& mesh, const SurfacePoint& point, double tolerance = 1e-9);

/// The triangles a surface point lies in: its own, the one across an edge it lies on, every
/// triangle around a corner it sits on (coordinates within `tolerance` of 0 or 1). Sorted.
std::vector<int> facesHolding(const TriangleMesh& mesh, const SurfacePoint& point, double tolerance = 1e-9);

/// A polyline in space as a curve on the surface whose segments each lie in one triangle (as
/// isolines and paths are stored). Each point is projected onto the surface; two consecutive
/// points that share a triangle (inside it, on its edges or at its corners, as the points of an
/// isoline do) are joined inside it; otherwise the segment is followed across the triangles
/// between them where the plane through its ends that holds their mean normal cuts the surface,
/// crossing edges exactly (a straight stroke seen from above the segment). Repeated points are
/// dropped; with `closed` the last point is joined back to the first.
///
/// Throws kerf::Error naming `what` for fewer than two distinct points (three when closed),
/// points off the surface (projectOntoSurface), and segments that join two connected components,
/// run along the surface normal, or cannot be followed to their end (they meet the mesh's
/// boundary or a non-manifold edge first).
SurfaceCurve placeCurveOnSurface(const Surface& surface, const std::vector<Vector3>& points, bool closed,
  double maximumDistance, const std::string& what);

} // namespace kerf
