// Seams as streamlines of v* = -D^-1 v (SeamCut, Eq. 2) from one distance field per source line.
#include "Geodesic/Seams.h"

#include "Error.h"
#include "Harmonic/FieldGradient.h"
#include "Session/Surface.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace kerf
{

SeamField::SeamField(const Surface& surface, const SurfaceCurve& sourceLine, const SeamOptions& options)
  : TheSurface(surface)
  , SourceLine(sourceLine)
  , Options(options)
{
  const TriangleMesh& mesh = surface.mesh();
  GeodesicSource source;
  source.curves = { sourceLine };
  checkGeodesicSource(mesh, source);
  const std::vector<int> components = sourceComponents(mesh, source);
  if (components.size() != 1)
  {
    throw Error("a seam's source line must lie on one connected component of the mesh");
  }
  this->Component = components.front();
  const AnisotropicMetric& metric = anisotropicMetric(surface, options.metric);
  if (options.metric.gamma == 0.0)
  {
    // Isotropic seams: the heat method's gradient is the more accurate.
    GeodesicDistance field = HeatGeodesics::of(surface).compute(source);
    this->Distance = std::move(field.distance);
    this->Directions = descentDirections(mesh, field.faceGradients, metric);
    return;
  }
  VectorDijkstraOptions dijkstra;
  dijkstra.depth = options.depth;
  this->Distance = shortTermVectorDijkstra(mesh, metric, source, dijkstra).distance;
  this->Directions = descentDirections(mesh, computeFaceGradients(mesh, this->Distance), metric);
}

SurfacePath SeamField::seam(const SurfacePoint& target) const
{
  const TriangleMesh& mesh = this->TheSurface.mesh();
  checkSurfacePoint(mesh, target, "the seam's target");
  if (mesh.faceComponent(target.face) != this->Component)
  {
    throw Error("the seam's target lies on another connected component than its source line");
  }
  GeodesicSource source;
  source.curves = { this->SourceLine };
  return traceToSource(mesh, this->Directions, target, source, anisotropicMetric(this->TheSurface, this->Options.metric));
}

SurfacePath SeamField::anchoredSeam(const SurfacePoint& target, const SurfacePoint& anchor) const
{
  const TriangleMesh& mesh = this->TheSurface.mesh();
  checkSurfacePoint(mesh, target, "the seam's target");
  checkSurfacePoint(mesh, anchor, "the seam's anchor");
  if (mesh.faceComponent(target.face) != this->Component)
  {
    throw Error("the seam's target lies on another connected component than its source line");
  }
  // The nearest point of the line to the anchor.
  const Vector3 a = surfacePosition(mesh, anchor);
  double best = std::numeric_limits<double>::infinity();
  SurfacePoint onLine;
  const int segments = segmentCount(this->SourceLine);
  for (int i = 0; i < segments; ++i)
  {
    const Vector3& p = this->SourceLine.points[i];
    const Vector3& q = this->SourceLine.points[(i + 1) % this->SourceLine.points.size()];
    const Vector3 d = q - p;
    const double s = d.squaredNorm() > 0.0 ? std::clamp((a - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const Vector3 x = p + s * d;
    if ((x - a).norm() < best)
    {
      best = (x - a).norm();
      onLine.face = this->SourceLine.faces[i];
      onLine.barycentric = barycentricInFace(mesh, onLine.face, x);
    }
  }
  GeodesicPathOptions options;
  options.metric = this->Options.metric;
  options.depth = this->Options.depth;
  options.vectorDijkstra = true; // as the seam itself
  return shortestPath(this->TheSurface, onLine, target, options);
}

} // namespace kerf
