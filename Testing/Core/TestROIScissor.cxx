// ROI Scissor: the same protrusion from different clicks, a boundary in the crease, Boolean discs, bad input.
#include "Error.h"
#include "Geodesic/ROIScissor.h"
#include "IO/MeshFormats.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/Triangulation.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace kerf;

namespace
{
// The dumbbell of the harmonic-cut tests: lobes of radii 1 (below) and 0.8 (above, the
// protrusion), the neck at z = 0.3 pinched by 0.65.
const double HalfLength = 2.2, NeckHeight = 0.3, NeckDepth = 0.65;
const std::array<double, 2> Radii{ 1.0, 0.8 };

// One surface for every test: its heat-method set-up, curvature and weights are cached on it.
std::shared_ptr<Surface> dumbbell()
{
  static const std::shared_ptr<Surface> surface =
    std::make_shared<Surface>(makeDumbbell(HalfLength, Radii, NeckHeight, NeckDepth, 5));
  return surface;
}

// Height of the crease: where the profile is narrowest near the neck.
double creaseHeight()
{
  double best = NeckHeight, narrowest = 1e9;
  for (double z = NeckHeight - 0.5; z <= NeckHeight + 0.5; z += 1e-4)
  {
    const double r = dumbbellRadius(z, HalfLength, Radii, NeckHeight, NeckDepth);
    if (r < narrowest)
    {
      narrowest = r;
      best = z;
    }
  }
  return best;
}

double faceArea(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  return 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
}

// A point of the surface at height z in the direction of angle `angle` around the axis.
Vector3 onDumbbell(double z, double angle)
{
  const double r = dumbbellRadius(z, HalfLength, Radii, NeckHeight, NeckDepth);
  return Vector3(r * std::cos(angle), r * std::sin(angle), z);
}
} // namespace

TEST(ROIScissor, ClicksInsideTheProtrusionGiveTheSameRegion)
{
  const std::shared_ptr<Surface> surface = dumbbell();
  const TriangleMesh& mesh = surface->mesh();
  const double crease = creaseHeight();
  const Vector3 clicks[3] = { onDumbbell(HalfLength - 0.05, 0.0), onDumbbell(1.3, 0.5), onDumbbell(0.9, 2.6) };
  std::vector<std::vector<int>> labels;
  double protrusionArea = 0.0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    if ((mesh.point(t[0]).z() + mesh.point(t[1]).z() + mesh.point(t[2]).z()) / 3.0 > crease)
    {
      protrusionArea += faceArea(mesh, f);
    }
  }
  for (const Vector3& click : clicks)
  {
    const ROIScissorResult result = roiScissor(*surface, { { click, 2.6 } });
    ASSERT_EQ(result.boundaries.size(), 1u);
    EXPECT_EQ(result.boundaries[0].selfCrossings, 0);
    // The boundary runs through the crease: every point within 0.1 of its height (the
    // protrusion is 1.9 tall, the mesh's edges about 0.05).
    double farthest = 0.0;
    for (const Vector3& p : result.boundaries[0].path.curve.points)
    {
      farthest = std::max(farthest, std::abs(p.z() - crease));
    }
    RecordProperty("CreaseDistance", std::to_string(farthest));
    EXPECT_LE(farthest, 0.1);
    // The region is the protrusion.
    double area = 0.0, misplaced = 0.0;
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const Triangle& t = mesh.triangle(f);
      const bool above = (mesh.point(t[0]).z() + mesh.point(t[1]).z() + mesh.point(t[2]).z()) / 3.0 > crease;
      area += result.faceLabels[f] ? faceArea(mesh, f) : 0.0;
      misplaced += (result.faceLabels[f] != 0) != above ? faceArea(mesh, f) : 0.0;
    }
    EXPECT_LE(misplaced, 0.05 * protrusionArea);
    EXPECT_TRUE(result.boundaryEncloses);
    labels.push_back(result.faceLabels);
  }
  for (std::size_t i = 1; i < labels.size(); ++i)
  {
    double region = 0.0, difference = 0.0;
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      region += labels[0][f] ? faceArea(mesh, f) : 0.0;
      difference += labels[0][f] != labels[i][f] ? faceArea(mesh, f) : 0.0;
    }
    RecordProperty("Difference" + std::to_string(i), std::to_string(difference / region));
    EXPECT_LE(difference, 0.02 * region) << "click " << i;
  }
}

// Clicks on the camel's flanks and belly with a radius of 0.1 (7% of its diagonal): nothing
// concave is near, so the best isoline is the innermost, a loop within a few triangles of the
// click that the side labels cross without separating. The region stays the click's side inside
// the candidate region (it once became the whole camel but two triangles).
TEST(ROIScissor, RegionStaysInsideTheCandidateRegion)
{
  const PolygonMesh polygons = readOFF(std::string(KERF_SOURCE_DIR) + "/Data/camel.off");
  const Surface camel(TriangleMesh(polygons.points, triangulatePolygons(polygons).triangles));
  const TriangleMesh& mesh = camel.mesh();
  int xMax = 0, xMin = 0, zMin = 0;
  for (int v = 1; v < mesh.vertexCount(); ++v)
  {
    xMax = mesh.point(v).x() > mesh.point(xMax).x() ? v : xMax;
    xMin = mesh.point(v).x() < mesh.point(xMin).x() ? v : xMin;
    zMin = mesh.point(v).z() < mesh.point(zMin).z() ? v : zMin;
  }
  int fallbacks = 0;
  for (int v : { xMax, xMin, zMin })
  {
    const ROIScissorResult result = roiScissor(camel, { { mesh.point(v), 0.1 } });
    std::vector<char> inRegion(mesh.faceCount(), 0);
    for (int f : result.regionFaces)
    {
      inRegion[f] = 1;
    }
    int inside = 0, outsideRegion = 0;
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      inside += result.faceLabels[f];
      outsideRegion += result.faceLabels[f] && !inRegion[f] ? 1 : 0;
    }
    EXPECT_GE(inside, 1) << "vertex " << v;
    EXPECT_EQ(outsideRegion, 0) << "vertex " << v;
    EXPECT_LT(inside, static_cast<int>(result.regionFaces.size())) << "vertex " << v;
    EXPECT_EQ(result.faceLabels[result.clicks.front().face], 1);
    fallbacks += result.boundaryEncloses ? 0 : 1;
  }
  EXPECT_GE(fallbacks, 1); // the case that once failed takes the isoline's side
}

TEST(ROIScissor, ConstraintsFollowTheDiscs)
{
  const std::shared_ptr<Surface> surface = dumbbell();
  const TriangleMesh& mesh = surface->mesh();
  const Vector3 top = onDumbbell(HalfLength - 0.05, 0.0);
  const ROIScissorResult one = roiScissor(*surface, { { top, 2.6 } });
  // Zeros sit on both sides of the border and nowhere else; ones are near the click.
  for (int v : one.zeroVertices)
  {
    bool crossing = false;
    for (int w : mesh.vertexNeighbors(v))
    {
      crossing = crossing || one.candidate[w] != one.candidate[v];
    }
    EXPECT_TRUE(crossing);
  }
  for (int v : one.oneVertices)
  {
    EXPECT_LE((mesh.point(v) - top).norm(), 0.1 * 2.6 + 0.05);
    EXPECT_DOUBLE_EQ(one.field[v], 1.0);
  }
  // A union with a second disc grows the candidate region; a difference shrinks it.
  const ROIScissorResult both = roiScissor(*surface, { { top, 2.6 }, { onDumbbell(-1.5, 1.0), 0.5 } });
  const ROIScissorResult less = roiScissor(*surface, { { top, 2.6 } }, { { onDumbbell(1.2, 3.14), 0.3 } });
  int counts[3] = { 0, 0, 0 };
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    counts[0] += one.candidate[v];
    counts[1] += both.candidate[v];
    counts[2] += less.candidate[v];
    EXPECT_GE(both.candidate[v], one.candidate[v]);
    EXPECT_LE(less.candidate[v], one.candidate[v]);
  }
  EXPECT_GT(counts[1], counts[0]);
  EXPECT_LT(counts[2], counts[0]);
}

TEST(ROIScissor, RefusesBadInput)
{
  const std::shared_ptr<Surface> surface = dumbbell();
  const Vector3 top = onDumbbell(HalfLength - 0.05, 0.0);
  EXPECT_THROW(roiScissor(*surface, {}), Error);
  EXPECT_THROW(roiScissor(*surface, { { Vector3(5.0, 0.0, 0.0), 1.0 } }), Error); // off the surface
  EXPECT_THROW(roiScissor(*surface, { { top, 0.0 } }), Error);
  EXPECT_THROW(roiScissor(*surface, { { top, -1.0 } }), Error);
  EXPECT_THROW(roiScissor(*surface, { { top, std::nan("") } }), Error);
  EXPECT_THROW(roiScissor(*surface, { { top, 100.0 } }), Error); // larger than the mesh
  // A second component: a sphere beside the dumbbell.
  const TriangleMesh& mesh = surface->mesh();
  std::vector<Vector3> points = mesh.points();
  std::vector<Triangle> triangles = mesh.triangles();
  const TriangleMesh ball = makeIcosphere(0.5, 2);
  const int offset = static_cast<int>(points.size());
  for (const Vector3& p : ball.points())
  {
    points.push_back(p + Vector3(4.0, 0.0, 0.0));
  }
  for (const Triangle& t : ball.triangles())
  {
    triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const auto two = std::make_shared<Surface>(TriangleMesh(points, triangles));
  EXPECT_THROW(roiScissor(*two, { { top, 2.6 }, { Vector3(4.5, 0.0, 0.0), 0.3 } }), Error);
}

TEST(ROIScissor, ClickDistancesAreKeptPerClick)
{
  const std::shared_ptr<Surface> surface = dumbbell();
  ClickDistances distances(surface);
  const ROIClick top{ onDumbbell(HalfLength - 0.05, 0.0), 2.6 };
  const ROIClick side{ onDumbbell(1.2, 3.14), 0.3 };
  const GeodesicDiscRegion alone = geodesicDiscRegion(*surface, { top }, {}, ROIScissorOptions(), &distances);
  EXPECT_EQ(distances.computations(), 1);
  // A second click computes only its own field; the first radius changed computes none.
  const GeodesicDiscRegion less = geodesicDiscRegion(*surface, { top }, { side }, ROIScissorOptions(), &distances);
  EXPECT_EQ(distances.computations(), 2);
  const GeodesicDiscRegion wider =
    geodesicDiscRegion(*surface, { { top.position, 2.8 } }, { side }, ROIScissorOptions(), &distances);
  EXPECT_EQ(distances.computations(), 2);
  // The same regions as without the cache, and faces follow their vertices.
  EXPECT_EQ(alone.candidate, geodesicDiscRegion(*surface, { top }, {}).candidate);
  EXPECT_EQ(less.candidate, geodesicDiscRegion(*surface, { top }, { side }).candidate);
  const TriangleMesh& mesh = surface->mesh();
  int wholeFacesInside = 0, candidateFaces = 0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const int corners = alone.candidate[t[0]] + alone.candidate[t[1]] + alone.candidate[t[2]];
    candidateFaces += alone.candidateFaces[f];
    wholeFacesInside += corners == 3 ? 1 : 0;
    if (corners == 3)
    {
      EXPECT_EQ(alone.candidateFaces[f], 1);
    }
    if (corners == 0)
    {
      EXPECT_EQ(alone.candidateFaces[f], 0);
    }
  }
  EXPECT_GE(candidateFaces, wholeFacesInside);
  int grown = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_GE(wider.candidate[v], less.candidate[v]);
    grown += wider.candidate[v] - less.candidate[v];
  }
  EXPECT_GT(grown, 0);
  // The ROI Scissor selection through the cache equals the one without it.
  const ROIScissorResult cached = roiScissor(*surface, { top }, {}, ROIScissorOptions(), &distances);
  EXPECT_EQ(distances.computations(), 2);
  EXPECT_EQ(cached.faceLabels, roiScissor(*surface, { top }).faceLabels);
}

namespace
{
// The unit icosphere of 10,242 vertices, shared by the disc tests (its heat set-up is cached on it).
std::shared_ptr<Surface> unitSphere()
{
  static const std::shared_ptr<Surface> surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  return surface;
}

double discArea(const TriangleMesh& mesh, const std::vector<char>& faces)
{
  double area = 0.0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    area += faces[f] ? faceArea(mesh, f) : 0.0;
  }
  return area;
}

double greatCircle(const Vector3& a, const Vector3& b)
{
  return std::atan2(a.normalized().cross(b.normalized()).norm(), a.normalized().dot(b.normalized()));
}
} // namespace

// Spherical caps: a vertex is inside when its great-circle distance is below r (away from the
// rim), and the faces' area is the cap's, 2 pi (1 - cos r); a union of two caps apart adds their
// areas, a concentric difference leaves the ring 2 pi (cos r2 - cos r1).
TEST(GeodesicDiscs, SphericalCapsMatchTheirAnalyticArea)
{
  const std::shared_ptr<Surface> surface = unitSphere();
  const TriangleMesh& mesh = surface->mesh();
  const Vector3 north(0.0, 0.0, 1.0), south(0.0, 0.0, -1.0);
  const double r = 0.9, r2 = 0.5, pi = std::acos(-1.0);
  const GeodesicDiscs cap = geodesicDiscs(*surface, { { north, r } }, {}, 1e-3);
  int misplaced = 0, rim = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double d = greatCircle(mesh.point(v), north);
    EXPECT_NEAR(cap.nearestAdded[v], d, 0.01 * d + 0.005); // 0.7% at the antipode
    if (std::abs(d - r) < 0.01)
    {
      ++rim;
      continue;
    }
    misplaced += cap.vertices[v] != (d < r ? 1 : 0);
  }
  EXPECT_EQ(misplaced, 0);
  std::cout << "cap of radius 0.9: area " << discArea(mesh, cap.faces) << " against " << 2 * pi * (1 - std::cos(r))
            << "; " << rim << " vertices within 0.01 of the rim not checked\n";
  EXPECT_NEAR(discArea(mesh, cap.faces) / (2 * pi * (1 - std::cos(r))), 1.0, 0.01);
  EXPECT_NEAR(cap.area, discArea(mesh, cap.faces), 1e-12);
  EXPECT_NEAR(cap.surfaceArea, 4 * pi, 0.01 * 4 * pi);

  const GeodesicDiscs two = geodesicDiscs(*surface, { { north, r }, { south, r2 } }, {}, 1e-3);
  EXPECT_NEAR(discArea(mesh, two.faces) / (2 * pi * (2 - std::cos(r) - std::cos(r2))), 1.0, 0.01);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_EQ(two.nearestAdded[v], std::min((*two.distances[0])[v], (*two.distances[1])[v]));
    EXPECT_GE(two.vertices[v], cap.vertices[v]);
  }
  const GeodesicDiscs ring = geodesicDiscs(*surface, { { north, r } }, { { north, r2 } }, 1e-3);
  EXPECT_NEAR(discArea(mesh, ring.faces) / (2 * pi * (std::cos(r2) - std::cos(r))), 1.0, 0.02);
  EXPECT_EQ(ring.addedCount, 1u);
  ASSERT_EQ(ring.clicks.size(), 2u);
  // A subtracting click does not count as the nearest click: one at the south pole, whose disc
  // lies outside the cap, leaves the cap and its distances as they were.
  const GeodesicDiscs apart = geodesicDiscs(*surface, { { north, r } }, { { south, r2 } }, 1e-3);
  EXPECT_EQ(apart.nearestAdded, cap.nearestAdded);
  EXPECT_EQ(apart.vertices, cap.vertices);
  // Half the sphere is nearer the south click: counting it would change those distances.
  int nearerSouth = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    nearerSouth += (*apart.distances[1])[v] < apart.nearestAdded[v] ? 1 : 0;
  }
  EXPECT_GT(nearerSouth, mesh.vertexCount() / 3);
}

TEST(GeodesicDiscs, RefusesBadDiscs)
{
  const std::shared_ptr<Surface> surface = unitSphere();
  const Vector3 north(0.0, 0.0, 1.0);
  EXPECT_THROW(geodesicDiscs(*surface, {}, {}, 1e-3), Error);
  EXPECT_THROW(geodesicDiscs(*surface, { { Vector3(0.0, 0.0, 1.5), 0.5 } }, {}, 1e-3), Error); // off the surface
  EXPECT_THROW(geodesicDiscs(*surface, { { north, 0.0 } }, {}, 1e-3), Error);
  EXPECT_THROW(geodesicDiscs(*surface, { { north, std::nan("") } }, {}, 1e-3), Error);
  EXPECT_THROW(geodesicDiscs(*surface, { { north, 4.0 } }, {}, 1e-3), Error); // larger than the sphere (pi)
  // A click between vertices with a radius below the edge length holds no vertex.
  const TriangleMesh& mesh = surface->mesh();
  const Triangle& t = mesh.triangle(0);
  const Vector3 centre = ((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0).normalized();
  EXPECT_THROW(geodesicDiscs(*surface, { { centre, 1e-3 } }, {}, 1e-3), Error);
  // Every added click inside a subtracted disc.
  EXPECT_THROW(geodesicDiscs(*surface, { { north, 0.3 } }, { { north, 0.6 } }, 1e-3), Error);
}
