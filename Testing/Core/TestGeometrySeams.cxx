// Geometry seam carving's preprocessing: the field against its analytic answer, ring invariants, errors.
#include "Error.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"
#include "SeamCarving/GeometrySeams.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <set>
#include <string>

namespace kerf
{
namespace
{

// Radius 1, height 4, 48 points around, 49 rings (spacing 1/12): handle z <= 1, fixed z >= 3.
TriangleMesh plainCylinder()
{
  return makeCylinder(1.0, 4.0, 48, 49);
}

// The same cylinder with six bumps around z = 2, in the middle of the modeling region.
TriangleMesh bumpyCylinder()
{
  return makeBumpyCylinder(1.0, 4.0, 48, 49, 6, 2.0, 0.3, 0.15);
}

GeometrySeamsResult run(const TriangleMesh& mesh, const GeometrySeamsOptions& options)
{
  return computeGeometrySeams(
    mesh, heightBandRegions(mesh, 1.0, 3.0), computeSurfaceDescriptors(mesh).normalConeAngle, options);
}

int findRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    i = parent[i] = parent[parent[i]];
  }
  return i;
}

// True if, without the triangles of ring `k`, no chain of triangles sharing a point joins a
// handle triangle to a fixed triangle.
bool ringSeparates(const TriangleMesh& mesh, const std::vector<double>& region, const std::vector<int>& ring, int k)
{
  std::vector<int> parent(mesh.vertexCount());
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (ring[f] == k)
    {
      continue;
    }
    const Triangle& t = mesh.triangle(f);
    parent[findRoot(parent, t[1])] = findRoot(parent, t[0]);
    parent[findRoot(parent, t[2])] = findRoot(parent, t[0]);
  }
  std::set<int> handle, fixed;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    bool kept = false;
    for (int f : mesh.vertexFaces(v))
    {
      kept = kept || ring[f] != k;
    }
    if (kept && region[v] == 2.0)
    {
      handle.insert(findRoot(parent, v));
    }
    if (kept && region[v] == 0.0)
    {
      fixed.insert(findRoot(parent, v));
    }
  }
  for (int root : handle)
  {
    if (fixed.count(root))
    {
      return false;
    }
  }
  return !handle.empty() && !fixed.empty();
}

// True if the triangles of ring `k` form one edge-connected strip in which every triangle has
// at least two neighbours (a closed band, no loose end).
bool ringIsClosedStrip(const TriangleMesh& mesh, const std::vector<int>& ring, int k)
{
  std::vector<int> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (ring[f] == k)
    {
      faces.push_back(f);
    }
  }
  if (faces.size() < 3)
  {
    return false;
  }
  std::vector<char> seen(mesh.faceCount(), 0);
  std::vector<int> stack{ faces.front() };
  seen[faces.front()] = 1;
  std::size_t reached = 1;
  while (!stack.empty())
  {
    const int f = stack.back();
    stack.pop_back();
    int neighbours = 0;
    for (int j = 0; j < 3; ++j)
    {
      const int g = mesh.faceNeighbor(f, j);
      if (g >= 0 && ring[g] == k)
      {
        ++neighbours;
        if (!seen[g])
        {
          seen[g] = 1;
          ++reached;
          stack.push_back(g);
        }
      }
    }
    if (neighbours < 2)
    {
      return false;
    }
  }
  return reached == faces.size();
}

void expectError(const std::function<void()>& call, const std::string& words)
{
  try
  {
    call();
    ADD_FAILURE() << "no error; expected one with \"" << words << "\"";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

// On this cylinder the uniform Laplacian is harmonic for any function of the ring index that is
// linear (each point has two neighbours above and two below), so H = (z - 1) / 2 exactly.
TEST(GeometrySeams, FieldIsLinearAlongThePlainCylinder)
{
  const TriangleMesh mesh = plainCylinder();
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  GeometrySeamsOptions options;
  options.ringCount = 3;
  const GeometrySeamsResult result = run(mesh, options);
  double worst = 0.0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double h = result.harmonicField[v], z = mesh.point(v).z();
    if (region[v] == 2.0)
    {
      EXPECT_EQ(h, 0.0);
    }
    else if (region[v] == 0.0)
    {
      EXPECT_EQ(h, 1.0);
    }
    else
    {
      EXPECT_GT(h, 0.0);
      EXPECT_LT(h, 1.0);
      worst = std::max(worst, std::abs(h - (z - 1.0) / 2.0));
    }
  }
  EXPECT_LT(worst, 1e-9);
  // Monotone along the axis: each point above another (same angle) has a larger value.
  for (int v = 48; v < mesh.vertexCount(); ++v)
  {
    if (region[v] == 1.0)
    {
      EXPECT_GT(result.harmonicField[v], result.harmonicField[v - 48] + 1e-3);
    }
  }
}

TEST(GeometrySeams, ContoursAndSectorsOfThePlainCylinder)
{
  const TriangleMesh mesh = plainCylinder();
  GeometrySeamsOptions options;
  options.ringCount = 1;
  options.isoContourCount = 8;
  options.sectorCount = 6;
  const GeometrySeamsResult result = run(mesh, options);
  int iso = 0, sector = 0;
  for (const SeamContour& contour : result.contours)
  {
    if (contour.kind == SeamContour::Kind::Iso)
    {
      ++iso;
      EXPECT_TRUE(contour.closed);
      // Each iso-contour is one horizontal loop at z = 1 + 2 j / m.
      for (const Vector3& p : contour.points)
      {
        EXPECT_NEAR(p.z(), 1.0 + 2.0 * contour.index / 8.0, 1e-9);
      }
    }
    else
    {
      ++sector;
      EXPECT_FALSE(contour.closed);
      // Perpendicular to the iso-contours: straight up the cylinder, from z = 1 to z = 3.
      EXPECT_NEAR(contour.points.front().z(), 1.0, 1e-12);
      EXPECT_NEAR(contour.points.back().z(), 3.0, 1e-12);
      for (const Vector3& p : contour.points)
      {
        EXPECT_NEAR(p.x(), contour.points.front().x(), 1e-12);
        EXPECT_NEAR(p.y(), contour.points.front().y(), 1e-12);
      }
      EXPECT_NEAR(contour.length, 2.0, 1e-12);
    }
  }
  EXPECT_EQ(iso, 9);
  EXPECT_EQ(sector, 6);
  // Six contours cut the ring into six sectors; -1 on handle and fixed points.
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  std::set<int> sectors;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (region[v] == 1.0)
    {
      sectors.insert(result.sector[v]);
    }
    else
    {
      EXPECT_EQ(result.sector[v], -1);
    }
  }
  EXPECT_EQ(sectors, (std::set<int>{ 0, 1, 2, 3, 4, 5 }));
  // Per triangle: the modeling triangles (a modeling point) carry the six sectors, each point's
  // sector is the least of its triangles', and the other triangles carry -1.
  std::set<int> faceSectors;
  std::vector<int> leastOfFaces(mesh.vertexCount(), 1 << 30);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const kerf::Triangle& t = mesh.triangle(f);
    const bool modeling = region[t[0]] == 1.0 || region[t[1]] == 1.0 || region[t[2]] == 1.0;
    if (!modeling)
    {
      EXPECT_EQ(result.faceSector[f], -1);
      continue;
    }
    faceSectors.insert(result.faceSector[f]);
    for (int v : t)
    {
      leastOfFaces[v] = std::min(leastOfFaces[v], result.faceSector[f]);
    }
  }
  EXPECT_EQ(faceSectors, sectors);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (region[v] == 1.0)
    {
      EXPECT_EQ(result.sector[v], leastOfFaces[v]);
    }
  }
}

TEST(GeometrySeams, EdgeCostsLieInTheUnitInterval)
{
  const TriangleMesh mesh = bumpyCylinder();
  GeometrySeamsOptions options;
  options.ringCount = 1;
  const GeometrySeamsResult result = run(mesh, options);
  for (const std::vector<double>* term :
    { &result.saliencyTerm, &result.lengthTerm, &result.harmonicTerm, &result.edgeCost })
  {
    double low = 2.0, high = -2.0;
    int inside = 0;
    for (double value : *term)
    {
      if (value != -1.0)
      {
        ++inside;
        low = std::min(low, value);
        high = std::max(high, value);
      }
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GE(low, 0.0);
    EXPECT_LE(high, 1.0);
  }
  // Each term is normalised: it reaches 0 and 1 on the modeling region.
  for (const std::vector<double>* term : { &result.saliencyTerm, &result.harmonicTerm })
  {
    EXPECT_EQ(*std::max_element(term->begin(), term->end()), 1.0);
  }
  for (double value : result.faceCost)
  {
    EXPECT_TRUE(value == -1.0 || (value >= 0.0 && value <= 1.0));
  }
}

TEST(GeometrySeams, RingsAreDisjointClosedStripsSeparatingHandleFromFixed)
{
  const TriangleMesh mesh = plainCylinder();
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  GeometrySeamsOptions options;
  options.ringCount = 15;
  const GeometrySeamsResult result = run(mesh, options);
  ASSERT_EQ(result.ringCost.size(), 15u);
  for (int k = 0; k < 15; ++k)
  {
    EXPECT_TRUE(ringIsClosedStrip(mesh, result.ring, k)) << "ring " << k;
    EXPECT_TRUE(ringSeparates(mesh, region, result.ring, k)) << "ring " << k;
    if (k > 0)
    {
      EXPECT_GE(result.ringCost[k], result.ringCost[k - 1] * (1.0 - 1e-12)); // cheapest first
    }
  }
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const bool modeling = region[t[0]] == 1.0 || region[t[1]] == 1.0 || region[t[2]] == 1.0;
    EXPECT_TRUE(modeling || result.ring[f] == -1); // rings stay in the modeling region
  }
}

TEST(GeometrySeams, RingsAvoidTheBumps)
{
  const TriangleMesh mesh = bumpyCylinder();
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  const std::vector<double> angle = computeSurfaceDescriptors(mesh).normalConeAngle;
  GeometrySeamsOptions options;
  options.ringCount = 8;
  const GeometrySeamsResult result = run(mesh, options);
  ASSERT_EQ(result.ringCost.size(), 8u);
  double modelingSum = 0.0, ringSum = 0.0;
  int modelingCount = 0, ringCount = 0, bumpRingFaces = 0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const double mean = (angle[t[0]] + angle[t[1]] + angle[t[2]]) / 3.0;
    if (result.faceCost[f] >= 0.0)
    {
      modelingSum += mean;
      ++modelingCount;
    }
    if (result.ring[f] >= 0)
    {
      ringSum += mean;
      ++ringCount;
      const double z = (mesh.point(t[0]).z() + mesh.point(t[1]).z() + mesh.point(t[2]).z()) / 3.0;
      bumpRingFaces += std::abs(z - 2.0) < 0.3 ? 1 : 0;
    }
  }
  for (int k = 0; k < 8; ++k)
  {
    EXPECT_TRUE(ringIsClosedStrip(mesh, result.ring, k)) << "ring " << k;
    EXPECT_TRUE(ringSeparates(mesh, region, result.ring, k)) << "ring " << k;
  }
  // Below the modeling region's mean, and as low as on the plain cylinder (2 pi / 48 between
  // the normals of neighbouring columns).
  const std::vector<double> plain = computeSurfaceDescriptors(plainCylinder()).normalConeAngle;
  const double plainMean = std::accumulate(plain.begin(), plain.end(), 0.0) / plain.size();
  EXPECT_LT(ringSum / ringCount, 0.7 * modelingSum / modelingCount);
  EXPECT_LT(ringSum / ringCount, 1.001 * plainMean);
  EXPECT_EQ(bumpRingFaces, 0); // no ring crosses the band of bumps
}

// The tube of a single knob, with the defaults (15 rings): the tube is featureless above and below
// the knob, so no ring comes near it, and the rings lie on both sides of it. (With mu(e) shifted
// to start at 0, the iso-contour across the knob, a few percent longer than the others, had the
// cheapest edges of the region: 10 of the 15 rings crossed the knob.)
TEST(GeometrySeams, RingsGoAroundAKnob)
{
  const TriangleMesh mesh = makeFeatureTube(TubeFeature::Knob, 64, 81);
  const std::vector<double> region = heightBandRegions(mesh, 0.8, 4.2);
  const std::vector<int> knob = featureTubePoints(mesh);
  ASSERT_GT(knob.size(), 90u);
  std::vector<char> onKnob(mesh.vertexCount(), 0);
  for (int v : knob)
  {
    onKnob[v] = 1;
  }
  const GeometrySeamsResult result =
    computeGeometrySeams(mesh, region, computeSurfaceDescriptors(mesh).normalConeAngle, GeometrySeamsOptions());
  ASSERT_EQ(result.ringCost.size(), 15u);
  int knobFaces = 0, below = 0, above = 0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (result.ring[f] < 0)
    {
      continue;
    }
    const Triangle& t = mesh.triangle(f);
    knobFaces += onKnob[t[0]] || onKnob[t[1]] || onKnob[t[2]] ? 1 : 0;
    const double z = (mesh.point(t[0]).z() + mesh.point(t[1]).z() + mesh.point(t[2]).z()) / 3.0;
    below += z < 1.55 ? 1 : 0;
    above += z > 2.45 ? 1 : 0;
  }
  EXPECT_EQ(knobFaces, 0);
  EXPECT_GT(below, 0);
  EXPECT_GT(above, 0);
}

// A ridge from the handle to the fixed region leaves no way around: every ring crosses it, once.
TEST(GeometrySeams, RingsCrossARidgeWhereTheyMust)
{
  const TriangleMesh mesh = makeFeatureTube(TubeFeature::Ridge, 64, 81);
  const std::vector<double> region = heightBandRegions(mesh, 0.8, 4.2);
  const GeometrySeamsResult result =
    computeGeometrySeams(mesh, region, computeSurfaceDescriptors(mesh).normalConeAngle, GeometrySeamsOptions());
  ASSERT_EQ(result.ringCost.size(), 15u);
  for (int k = 0; k < 15; ++k)
  {
    EXPECT_TRUE(ringIsClosedStrip(mesh, result.ring, k)) << "ring " << k;
    EXPECT_TRUE(ringSeparates(mesh, region, result.ring, k)) << "ring " << k;
  }
}

TEST(GeometrySeams, GlobalCutFirstFindsTheExhaustiveMinimum)
{
  const TriangleMesh mesh = bumpyCylinder();
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  GeometrySeamsOptions options;
  options.ringCount = 3;
  const GeometrySeamsResult fast = run(mesh, options);
  options.search = RingCandidateSearch::Exhaustive;
  const GeometrySeamsResult exhaustive = run(mesh, options);
  ASSERT_EQ(fast.ringCost.size(), 3u);
  ASSERT_EQ(exhaustive.ringCost.size(), 3u);
  EXPECT_NEAR(fast.ringCost[0], exhaustive.ringCost[0], 1e-9 * exhaustive.ringCost[0]);
  EXPECT_EQ(fast.maxFlowCount, 3);
  EXPECT_GT(exhaustive.maxFlowCount, 3 * 20);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_TRUE(ringSeparates(mesh, region, exhaustive.ring, k)) << "ring " << k;
  }
}

TEST(GeometrySeams, Deterministic)
{
  const TriangleMesh mesh = bumpyCylinder();
  GeometrySeamsOptions options;
  const GeometrySeamsResult first = run(mesh, options), second = run(mesh, options);
  EXPECT_EQ(first.harmonicField, second.harmonicField);
  EXPECT_EQ(first.ring, second.ring);
  EXPECT_EQ(first.ringCost, second.ringCost);
  EXPECT_EQ(first.edgeCost, second.edgeCost);
  EXPECT_EQ(first.sector, second.sector);
  EXPECT_EQ(first.cutContour, second.cutContour);
}

TEST(GeometrySeams, FewerRingsWhenNoMoreFit)
{
  // 24 rows of triangles between the handle and the fixed region hold at most 24 rings.
  const TriangleMesh mesh = plainCylinder();
  GeometrySeamsOptions options;
  options.ringCount = 40;
  int reported = 0;
  options.ringDone = [&](int done) { reported = done; };
  const GeometrySeamsResult result = run(mesh, options);
  EXPECT_GE(result.ringCost.size(), 10u);
  EXPECT_LE(result.ringCost.size(), 24u);
  EXPECT_EQ(reported, static_cast<int>(result.ringCost.size()));
}

TEST(GeometrySeams, BadRegionsAreRefused)
{
  const TriangleMesh mesh = plainCylinder();
  const std::vector<double> angle(mesh.vertexCount(), 0.0);
  const GeometrySeamsOptions options;
  auto seams = [&](const std::vector<double>& region) {
    return [&mesh, &angle, &options, region]() { computeGeometrySeams(mesh, region, angle, options); };
  };
  expectError(seams(heightBandRegions(mesh, -1.0, 3.0)), "no point is in the handle region");
  expectError(seams(heightBandRegions(mesh, 1.0, 10.0)), "no point is in the fixed region");
  // A column of handle points up to the fixed region.
  std::vector<double> touching = heightBandRegions(mesh, 1.0, 3.0);
  for (int v = 0; v < mesh.vertexCount(); v += 48)
  {
    touching[v] = touching[v] == 1.0 ? 2.0 : touching[v];
  }
  expectError(seams(touching), "share an edge");
  expectError(seams(std::vector<double>(mesh.vertexCount(), 1.0)), "no point is in the handle region");
  // Handle at both ends, fixed in the middle: two modeling bands.
  std::vector<double> twoBands(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double z = mesh.point(v).z();
    twoBands[v] = z <= 1.0 || z >= 3.0 ? 2.0 : std::abs(z - 2.0) <= 0.25 ? 0.0 : 1.0;
  }
  expectError(seams(twoBands), "2 separate parts");
  std::vector<double> odd = heightBandRegions(mesh, 1.0, 3.0);
  odd[100] = 3.0;
  expectError(seams(odd), "region value 3; the values");
  expectError(seams(std::vector<double>(5, 1.0)), "5 values for");
  // A modeling band reaching the border of a plane is not a ring.
  const TriangleMesh grid = makeGrid(4.0, 1.0, 16, 4);
  std::vector<double> gridRegion;
  for (const Vector3& p : grid.points())
  {
    gridRegion.push_back(p.x() <= 1.0 ? 2.0 : p.x() >= 3.0 ? 0.0 : 1.0);
  }
  expectError([&]() { checkSeamRegions(grid, gridRegion); }, "reaches the surface's border");
  // Handle points with no handle triangle, fixed ends: the modeling region never meets the handle.
  std::vector<double> island(mesh.vertexCount(), 1.0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double z = mesh.point(v).z();
    island[v] = z >= 3.0 ? 0.0 : (std::abs(z - 1.5) < 0.05 && mesh.point(v).x() > 0.99) ? 2.0 : z <= 0.0 ? 0.0 : 1.0;
  }
  expectError(seams(island), "meets the handle region along 0 boundary loops");
}

TEST(GeometrySeams, BadOptionsAreRefused)
{
  const TriangleMesh mesh = plainCylinder();
  const std::vector<double> region = heightBandRegions(mesh, 1.0, 3.0);
  const std::vector<double> angle(mesh.vertexCount(), 0.0);
  auto with = [&](const std::function<void(GeometrySeamsOptions&)>& change) {
    return [&, change]() {
      GeometrySeamsOptions options;
      change(options);
      computeGeometrySeams(mesh, region, angle, options);
    };
  };
  expectError(with([](GeometrySeamsOptions& o) { o.ringCount = 0; }), "number of rings");
  expectError(with([](GeometrySeamsOptions& o) { o.isoContourCount = -2; }), "number of iso-contours");
  expectError(with([](GeometrySeamsOptions& o) { o.sectorCount = 0; }), "number of sectors");
  expectError(with([](GeometrySeamsOptions& o) { o.beta = std::nan(""); }), "finite");
  expectError(with([](GeometrySeamsOptions& o) { o.alpha = o.beta = o.gamma = 0.0; }), "all 0");
}

} // namespace
} // namespace kerf
