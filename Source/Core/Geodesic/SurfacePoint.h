// Points and curves on a triangle mesh, and the sources of geodesic distance fields.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A point inside triangle `face`, by its barycentric coordinates w.r.t. the corners 0, 1, 2.
struct SurfacePoint
{
  int face = -1;
  Vector3 barycentric = Vector3::Zero();
};

/// A polyline on the surface whose segments each lie in one triangle: faces[i] holds the segment
/// from points[i] to points[i + 1] (for a closed curve the last face holds the segment from the
/// last point back to the first), as kerf::Isoline and kerf::SurfacePath store them.
struct SurfaceCurve
{
  std::vector<Vector3> points;
  std::vector<int> faces;
  bool closed = false;
};

/// Where a distance field is 0: any mix of vertices, points inside faces and curves.
struct GeodesicSource
{
  std::vector<int> vertices;
  std::vector<SurfacePoint> points;
  std::vector<SurfaceCurve> curves;

  bool empty() const { return vertices.empty() && points.empty() && curves.empty(); }
};

/// The position of a surface point.
Vector3 surfacePosition(const TriangleMesh& mesh, const SurfacePoint& point);

/// The surface point of vertex v (in the first triangle using it). Throws kerf::Error if no
/// triangle uses v.
SurfacePoint vertexSurfacePoint(const TriangleMesh& mesh, int v);

/// Barycentric coordinates of p (projected onto the plane of `face`) w.r.t. the face's corners.
/// Zero-area faces give the coordinates of the nearest point on their longest edge.
Vector3 barycentricInFace(const TriangleMesh& mesh, int face, const Vector3& p);

/// Number of segments of a curve (points - 1, or points when closed).
int segmentCount(const SurfaceCurve& curve);

/// Throws kerf::Error with a sentence naming the problem when a surface point is not on the mesh:
/// a face index out of range, non-finite coordinates, or coordinates that do not sum to 1 or
/// lie outside the triangle by more than `tolerance`. `what` names the point in the message.
void checkSurfacePoint(const TriangleMesh& mesh, const SurfacePoint& point, const char* what, double tolerance = 1e-6);

/// Throws kerf::Error for an empty source, vertices out of range or used by no triangle, bad
/// surface points (checkSurfacePoint), and curves whose segment counts disagree with their faces,
/// that hold non-finite points, faces out of range, or points farther than 1e-6 of the mesh's
/// diagonal from the face holding their segment.
void checkGeodesicSource(const TriangleMesh& mesh, const GeodesicSource& source);

/// The connected components (TriangleMesh::faceComponent) the source touches, sorted.
std::vector<int> sourceComponents(const TriangleMesh& mesh, const GeodesicSource& source);

} // namespace kerf
