// Seams as streamlines of v* = -D^-1 v (SeamCut, Eq. 2) from one distance field per source line.
#include "Geodesic/GeodesicSeam.h"

#include "Error.h"
#include "Numerics/FieldGradient.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace kerf
{

SeamField::SeamField(const Surface& surface, const SurfaceCurve& sourceLine, const SeamOptions& options)
  : SeamField(surface, std::vector<SurfaceCurve>{ sourceLine }, options)
{
}

SeamField::SeamField(const Surface& surface, const std::vector<SurfaceCurve>& sourceLines, const SeamOptions& options)
  : TheSurface(surface)
  , SourceLines(sourceLines)
  , Options(options)
{
  const TriangleMesh& mesh = surface.mesh();
  if (sourceLines.empty())
  {
    throw Error("a seam needs a source line");
  }
  GeodesicSource source;
  source.curves = sourceLines;
  checkGeodesicSource(mesh, source);
  const std::vector<int> components = sourceComponents(mesh, source);
  if (components.size() != 1)
  {
    throw Error("a seam's source lines must lie on one connected component of the mesh");
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
  source.curves = this->SourceLines;
  return traceToSource(
    mesh, this->Directions, target, source, anisotropicMetric(this->TheSurface, this->Options.metric));
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
  for (const SurfaceCurve& line : this->SourceLines)
  {
    const int segments = segmentCount(line);
    for (int i = 0; i < segments; ++i)
    {
      const Vector3& p = line.points[i];
      const Vector3& q = line.points[(i + 1) % line.points.size()];
      const Vector3 d = q - p;
      const double s = d.squaredNorm() > 0.0 ? std::clamp((a - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      const Vector3 x = p + s * d;
      if ((x - a).norm() < best)
      {
        best = (x - a).norm();
        onLine.face = line.faces[i];
        onLine.barycentric = barycentricInFace(mesh, onLine.face, x);
      }
    }
  }
  GeodesicPathOptions options;
  options.metric = this->Options.metric;
  options.depth = this->Options.depth;
  options.vectorDijkstra = true; // as the seam itself
  return shortestPath(this->TheSurface, onLine, target, options);
}

namespace
{
bool sameCurves(const std::vector<SurfaceCurve>& a, const std::vector<SurfaceCurve>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (a[i].closed != b[i].closed || a[i].faces != b[i].faces || a[i].points != b[i].points)
    {
      return false;
    }
  }
  return true;
}

bool sameOptions(const SeamOptions& a, const SeamOptions& b)
{
  return a.depth == b.depth && a.metric.gamma == b.metric.gamma && a.metric.measure == b.metric.measure &&
    a.metric.umbilicRegularization == b.metric.umbilicRegularization;
}
} // namespace

SeamSession::SeamSession(std::shared_ptr<const Surface> surface)
  : SurfacePointer(std::move(surface))
{
  if (!this->SurfacePointer)
  {
    throw Error("a seam session needs a surface");
  }
}

const SeamField& SeamSession::field(
  const std::vector<SurfaceCurve>& sourceLines, const SeamOptions& options, bool* reused)
{
  const bool same =
    this->Field && sameCurves(this->Field->sourceLines(), sourceLines) && sameOptions(this->Field->options(), options);
  if (!same)
  {
    this->Field.reset();
    this->Field = std::make_unique<SeamField>(*this->SurfacePointer, sourceLines, options);
  }
  if (reused)
  {
    *reused = same;
  }
  return *this->Field;
}

} // namespace kerf
