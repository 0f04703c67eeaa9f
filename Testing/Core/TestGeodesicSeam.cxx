// SeamCut seams: meridians from the equator, regrowth on one field, anchoring, bad input.
#include "Error.h"
#include "Geodesic/GeodesicSeam.h"
#include "Geometry/ClosestPoint.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// The equator of a mesh as a source line: the isoline z = 0.
SurfaceCurve equator(const TriangleMesh& mesh)
{
  std::vector<double> height(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    height[v] = mesh.point(v).z();
  }
  const std::vector<Isoline> isolines = extractIsolines(mesh, height, 1e-9);
  SurfaceCurve curve;
  curve.points = isolines.at(0).points;
  curve.faces = isolines.at(0).faces;
  curve.closed = isolines.at(0).closed;
  return curve;
}

SurfacePoint pointNear(const Surface& surface, const Vector3& p)
{
  const ClosestPointLocator::Hit hit = surface.locator().closest(p);
  SurfacePoint point;
  point.face = hit.face;
  point.barycentric = hit.barycentric;
  return point;
}

double longitude(const Vector3& p)
{
  return std::atan2(p.y(), p.x());
}
} // namespace

TEST(GeodesicSeam, IsotropicSeamsAreMeridians)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  const SeamField field(*surface, equator(surface->mesh()));
  for (double angle : { 0.3, 1.9, -2.4 })
  {
    const Vector3 target(std::cos(angle) * 0.5, std::sin(angle) * 0.5, std::sqrt(0.75)); // latitude 60
    const SurfacePath seam = field.seam(pointNear(*surface, target));
    const Vector3& onLine = seam.curve.points.front();
    EXPECT_NEAR(onLine.z(), 0.0, 1e-9); // it ends on the source line
    // Down the meridian (measured: within 0.041 radians, 2.3 degrees over the 60-degree arc).
    EXPECT_NEAR(longitude(onLine), angle, 0.05);
    EXPECT_NEAR(seam.length, Pi / 3.0, 0.01 * Pi / 3.0);
    // Regrowth reuses the field: the same target gives the same seam, bit for bit.
    const SurfacePath again = field.seam(pointNear(*surface, target));
    EXPECT_EQ(again.curve.points, seam.curve.points);
  }
}

TEST(GeodesicSeam, AnchoredSeamMeetsTheLineAtTheAnchor)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  const SeamField field(*surface, equator(surface->mesh()));
  const Vector3 target(0.5, 0.0, std::sqrt(0.75));
  const SurfacePoint anchor = pointNear(*surface, Vector3(std::cos(0.5), std::sin(0.5), 0.0));
  const SurfacePath seam = field.anchoredSeam(pointNear(*surface, target), anchor);
  EXPECT_NEAR(seam.curve.points.front().z(), 0.0, 1e-9);
  EXPECT_NEAR(longitude(seam.curve.points.front()), 0.5, 0.01);
  const double exact = std::acos(seam.curve.points.front().normalized().dot(seam.curve.points.back().normalized()));
  EXPECT_NEAR(seam.length, exact, 0.015 * exact);
}

TEST(GeodesicSeam, AnisotropicSeamFollowsTheMetric)
{
  // On a cylinder the metric is the same everywhere, so seams stay straight lines of the
  // unrolled cylinder, but their lengths are measured under it: an axial seam from the bottom
  // ring is shorter than its Euclidean length by sqrt(lambda2).
  const auto surface = std::make_shared<Surface>(makeCylinder(1.0, 3.0, 96, 97));
  const TriangleMesh& mesh = surface->mesh();
  SurfaceCurve bottom;
  const std::vector<int>& loop = mesh.boundaryLoops().at(0);
  for (std::size_t i = 0; i < loop.size(); ++i)
  {
    bottom.points.push_back(mesh.point(loop[i]));
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    for (int f : mesh.vertexFaces(a))
    {
      const Triangle& t = mesh.triangle(f);
      if (std::find(t.begin(), t.end(), b) != t.end())
      {
        bottom.faces.push_back(f);
        break;
      }
    }
  }
  bottom.closed = true;
  SeamOptions options;
  options.metric.gamma = 1.0;
  const SeamField field(*surface, bottom, options);
  const AnisotropicMetric& metric = anisotropicMetric(*surface, options.metric);
  const double top = mesh.point(loop[0]).z() < 1.0 ? 2.0 : 1.0;
  const SurfacePath seam = field.seam(pointNear(*surface, Vector3(1.0, 0.0, top)));
  const double euclidean = curveLength(mesh, seam.curve, computeAnisotropicMetric(mesh, surface->descriptors(), {}));
  const double lambda = metric.lambda1[mesh.triangle(seam.curve.faces.back())[0]];
  EXPECT_NEAR(seam.length, euclidean / std::sqrt(lambda), 0.01 * seam.length);
  EXPECT_NEAR(euclidean, mesh.point(loop[0]).z() < 1.0 ? 2.0 : 1.0, 0.01);
}

TEST(GeodesicSeam, RefusesBadInput)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 3));
  SurfaceCurve empty;
  EXPECT_THROW(SeamField(*surface, empty), Error);
  SurfaceCurve offSurface = equator(surface->mesh());
  offSurface.points[0] += Vector3(0.0, 0.0, 0.5);
  EXPECT_THROW(SeamField(*surface, offSurface), Error);
  const SeamField field(*surface, equator(surface->mesh()));
  SurfacePoint bad;
  bad.face = -3;
  EXPECT_THROW(field.seam(bad), Error);
}

TEST(GeodesicSeam, SessionKeepsTheFieldOfTheSameLine)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 3));
  SeamSession session(surface);
  const std::vector<SurfaceCurve> lines{ equator(surface->mesh()) };
  SeamOptions options;
  options.metric.gamma = 1.0;
  bool reused = true;
  const SeamField* first = &session.field(lines, options, &reused);
  EXPECT_FALSE(reused);
  const std::vector<double> distance = first->distance();
  EXPECT_EQ(&session.field(lines, options, &reused), first);
  EXPECT_TRUE(reused);
  // New options or a new line compute a new field.
  options.metric.gamma = 2.0;
  session.field(lines, options, &reused);
  EXPECT_FALSE(reused);
  std::vector<SurfaceCurve> moved = lines;
  moved[0].points[0] = 0.5 * (moved[0].points[0] + moved[0].points[1]);
  const SeamField& other = session.field(moved, options, &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(other.sourceLines()[0].points[0], moved[0].points[0]);
  // Back to the first line and options: the same distances, bit for bit.
  options.metric.gamma = 1.0;
  EXPECT_EQ(session.field(lines, options, &reused).distance(), distance);
  EXPECT_FALSE(reused);
  // A bad line is refused and the session stays usable.
  std::vector<SurfaceCurve> offSurface = lines;
  offSurface[0].points[0] += Vector3(0.0, 0.0, 0.5);
  EXPECT_THROW(session.field(offSurface, options), Error);
  EXPECT_EQ(session.field(lines, options).distance(), distance);
}

TEST(GeodesicSeam, SeveralLinesOnOneComponent)
{
  // The two boundary-free halves of a cut: latitudes +-30 degrees as two source lines; a seam
  // from the north pole ends on the northern one.
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& mesh = surface->mesh();
  std::vector<double> height(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    height[v] = mesh.point(v).z();
  }
  std::vector<SurfaceCurve> lines;
  for (double z : { -0.5, 0.5 })
  {
    const Isoline isoline = extractIsolines(mesh, height, z).at(0);
    lines.push_back({ isoline.points, isoline.faces, isoline.closed });
  }
  const SeamField field(*surface, lines);
  const SurfacePath seam = field.seam(pointNear(*surface, Vector3(0.1, 0.0, 0.995)));
  EXPECT_NEAR(seam.curve.points.front().z(), 0.5, 1e-9);
  EXPECT_NEAR(seam.length, std::asin(0.995) - std::asin(0.5), 0.02);
}
