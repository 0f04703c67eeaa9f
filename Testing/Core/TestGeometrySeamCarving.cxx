// Tests of geometry seam carving's editing: feature preservation against plain Laplace editing, exact undo,
// manifoldness, errors.
#include "Error.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/MeshValidation.h"
#include "SeamCarving/GeometrySeamCarving.h"
#include "SeamCarving/GeometrySeams.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace kerf
{
namespace
{

// Radius 1, height 4, 48 points around, 49 rings (spacing 1/12), six bumps around z = 2:
// handle z <= 0.5, fixed z >= 3.5, so the modeling region is 36 rows, the bumps about 7 of them.
struct BumpyCylinder
{
  TriangleMesh mesh = makeBumpyCylinder(1.0, 4.0, 48, 49, 6, 2.0, 0.3, 0.15);
  std::vector<double> region = heightBandRegions(mesh, 0.5, 3.5);
  std::vector<double> angle = computeSurfaceDescriptors(mesh).normalConeAngle;
  GeometrySeamsResult seams;
  BumpyCylinder(int rings = 20, int sectors = 6)
  {
    GeometrySeamsOptions options;
    options.ringCount = rings;
    options.sectorCount = sectors;
    this->seams = computeGeometrySeams(this->mesh, this->region, this->angle, options);
  }
  SeamCarvingInput input() const
  {
    SeamCarvingInput in;
    in.mesh = &this->mesh;
    in.region = this->region;
    in.faceRing = this->seams.ring;
    in.faceSector = this->seams.faceSector;
    in.faceCost = this->seams.faceCost;
    in.normalConeAngle = this->angle;
    return in;
  }
};

Eigen::Matrix4d translation(double dz)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(2, 3) = dz;
  return m;
}

// The bumps' triangles: every corner raised off the cylinder by more than 0.01.
std::vector<int> bumpTriangles(const TriangleMesh& mesh)
{
  std::vector<int> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    bool raised = true;
    for (int v : mesh.triangle(f))
    {
      raised &= mesh.point(v).head<2>().norm() > 1.01;
    }
    if (raised)
    {
      faces.push_back(f);
    }
  }
  return faces;
}

// Mean |l' / l - 1| over the edges of the given input triangles, l' measured in the result.
double edgeLengthChange(const TriangleMesh& mesh, const std::vector<int>& faces, const SeamCarvingResult& result)
{
  std::map<int, int> outputOf;
  for (std::size_t i = 0; i < result.pointOrigin.size(); ++i)
  {
    if (result.pointOrigin[i] >= 0)
    {
      outputOf[result.pointOrigin[i]] = static_cast<int>(i);
    }
  }
  double sum = 0.0;
  int count = 0;
  for (int f : faces)
  {
    const Triangle& t = mesh.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      const double rest = (mesh.point(a) - mesh.point(b)).norm();
      const double now = (result.points[outputOf.at(a)] - result.points[outputOf.at(b)]).norm();
      sum += std::abs(now / rest - 1.0);
      ++count;
    }
  }
  return sum / count;
}

// The result is a manifold, consistently oriented surface without degenerate triangles.
void expectValid(const SeamCarvingResult& result)
{
  const TriangleMesh out(result.points, result.triangles);
  const MeshReport report = inspectMesh(out);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.inconsistentEdges, 0);
  EXPECT_EQ(report.zeroAreaFaces, 0);
  EXPECT_EQ(report.repeatedVertexFaces, 0);
  EXPECT_EQ(report.duplicateFaces, 0);
  EXPECT_EQ(report.unreferencedVertices, 0);
  EXPECT_EQ(report.components, 1);
  EXPECT_EQ(report.eulerCharacteristic, 0); // an open cylinder
}

} // namespace

TEST(GeometrySeamCarving, StretchKeepsTheBumps)
{
  const BumpyCylinder setup;
  const std::vector<int> bumps = bumpTriangles(setup.mesh);
  ASSERT_GT(bumps.size(), 100u);
  SeamCarvingOptions plainOptions;
  plainOptions.plastic = false;
  plainOptions.stiffnessScale = 0.0;
  GeometrySeamCarving plain(setup.input(), plainOptions);
  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  const double stretch = 1.5; // the modeling region's height 3 becomes 4.5
  const SeamCarvingResult& plainResult = plain.deform(translation(-1.5));
  const double plainChange = edgeLengthChange(setup.mesh, bumps, plainResult);
  SeamCarvingResult carved;
  for (int step = 1; step <= 10; ++step)
  {
    carved = carving.deform(translation(-1.5 * step / 10.0));
  }
  const double carvedChange = edgeLengthChange(setup.mesh, bumps, carved);
  std::printf("stretch %.2f: plain Laplace editing %.4f, seam carving %.4f (%d segments split, %d skipped)\n", stretch,
    plainChange, carvedChange, carved.splitSegments, carved.skippedOperations);
  EXPECT_EQ(plainResult.splitSegments, 0);
  EXPECT_GT(carved.splitSegments, 0);
  EXPECT_EQ(carved.collapsedSegments, 0);
  EXPECT_LT(carvedChange, 0.05);
  EXPECT_GT(plainChange, 2.0 * carvedChange);
  expectValid(carved);
}

TEST(GeometrySeamCarving, SquashKeepsTheBumps)
{
  const BumpyCylinder setup;
  const std::vector<int> bumps = bumpTriangles(setup.mesh);
  SeamCarvingOptions plainOptions;
  plainOptions.plastic = false;
  plainOptions.stiffnessScale = 0.0;
  GeometrySeamCarving plain(setup.input(), plainOptions);
  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  const SeamCarvingResult& plainResult = plain.deform(translation(0.9));
  const double plainChange = edgeLengthChange(setup.mesh, bumps, plainResult);
  SeamCarvingResult carved;
  for (int step = 1; step <= 10; ++step)
  {
    carved = carving.deform(translation(0.9 * step / 10.0));
  }
  const double carvedChange = edgeLengthChange(setup.mesh, bumps, carved);
  std::printf("squash 0.70: plain Laplace editing %.4f, seam carving %.4f (%d segments collapsed, %d skipped)\n",
    plainChange, carvedChange, carved.collapsedSegments, carved.skippedOperations);
  EXPECT_GT(carved.collapsedSegments, 0);
  EXPECT_EQ(carved.splitSegments, 0);
  EXPECT_LT(carvedChange, 0.05);
  EXPECT_GT(plainChange, 2.0 * carvedChange);
  expectValid(carved);
}

TEST(GeometrySeamCarving, MovingBackToTheIdentityRestoresTheInput)
{
  const BumpyCylinder setup;
  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  const double moves[] = { -0.5, -1.2, -1.5, -0.3, 0.4, 0.9, 0.2, -0.8, 0.0 };
  int maxSplit = 0, maxCollapsed = 0;
  for (double dz : moves)
  {
    const SeamCarvingResult& r = carving.deform(translation(dz));
    maxSplit = std::max(maxSplit, r.splitSegments);
    maxCollapsed = std::max(maxCollapsed, r.collapsedSegments);
    expectValid(r);
  }
  EXPECT_GT(maxSplit, 0);
  EXPECT_GT(maxCollapsed, 0);
  const SeamCarvingResult& back = carving.deform(Eigen::Matrix4d::Identity());
  EXPECT_EQ(back.splitSegments, 0);
  EXPECT_EQ(back.collapsedSegments, 0);
  ASSERT_EQ(back.points.size(), setup.mesh.points().size());
  ASSERT_EQ(back.triangles, setup.mesh.triangles());
  double worst = 0.0;
  for (int v = 0; v < setup.mesh.vertexCount(); ++v)
  {
    EXPECT_EQ(back.pointOrigin[v], v);
    worst = std::max(worst, (back.points[v] - setup.mesh.point(v)).norm());
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(GeometrySeamCarving, RotationOfTheHandleKeepsTheSurfaceValid)
{
  const BumpyCylinder setup;
  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  Eigen::Matrix4d bend = Eigen::Matrix4d::Identity();
  bend.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const SeamCarvingResult& r = carving.deform(bend);
  expectValid(r);
  // Handle points moved rigidly, fixed points stayed.
  for (std::size_t i = 0; i < r.points.size(); ++i)
  {
    const int v = r.pointOrigin[i];
    if (v >= 0 && setup.region[v] == 2.0)
    {
      EXPECT_LT((r.points[i] - (bend * setup.mesh.point(v).homogeneous()).head<3>()).norm(), 1e-12);
    }
    else if (v >= 0 && setup.region[v] == 0.0)
    {
      EXPECT_EQ(r.points[i], setup.mesh.point(v));
    }
  }
}

TEST(GeometrySeamCarving, Deterministic)
{
  const BumpyCylinder setup;
  GeometrySeamCarving a(setup.input(), SeamCarvingOptions());
  GeometrySeamCarving b(setup.input(), SeamCarvingOptions());
  for (double dz : { -0.7, -1.4, 0.6 })
  {
    const SeamCarvingResult ra = a.deform(translation(dz));
    const SeamCarvingResult& rb = b.deform(translation(dz));
    EXPECT_EQ(ra.points, rb.points);
    EXPECT_EQ(ra.triangles, rb.triangles);
    EXPECT_EQ(ra.sectorState, rb.sectorState);
  }
}

TEST(GeometrySeamCarving, ExecutionOrderFollowsTheSegmentsError)
{
  const BumpyCylinder setup;
  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  ASSERT_EQ(carving.sectorCount(), 6);
  EXPECT_EQ(carving.ringCount(), static_cast<int>(setup.seams.ringCost.size()));
  for (const std::vector<int>& order : carving.executionOrder())
  {
    EXPECT_EQ(order.size(), setup.seams.ringCost.size());
    EXPECT_EQ(std::set<int>(order.begin(), order.end()).size(), order.size());
  }
}

TEST(GeometrySeamCarving, BadInputIsRefused)
{
  const BumpyCylinder setup;
  auto message = [](const SeamCarvingInput& input, const SeamCarvingOptions& options = SeamCarvingOptions()) {
    try
    {
      GeometrySeamCarving carving(input, options);
      return std::string();
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
  };
  SeamCarvingInput noHandle = setup.input();
  for (double& r : noHandle.region)
  {
    r = r == 2.0 ? 1.0 : r;
  }
  EXPECT_NE(message(noHandle).find("no point is in the handle region"), std::string::npos);
  SeamCarvingInput noFixed = setup.input();
  for (double& r : noFixed.region)
  {
    r = r == 0.0 ? 1.0 : r;
  }
  EXPECT_NE(message(noFixed).find("no point is in the fixed region"), std::string::npos);
  // Not a ring: the handle reaches the fixed region (a column of handle points up the cylinder).
  SeamCarvingInput notARing = setup.input();
  for (int v = 0; v < setup.mesh.vertexCount(); ++v)
  {
    if (v % 48 == 0)
    {
      notARing.region[v] = 2.0;
    }
  }
  EXPECT_NE(message(notARing).find("share an edge"), std::string::npos) << message(notARing);
  SeamCarvingInput shortRings = setup.input();
  shortRings.faceRing.pop_back();
  EXPECT_NE(message(shortRings).find("one value per triangle"), std::string::npos);
  SeamCarvingInput noSectors = setup.input();
  std::fill(noSectors.faceSector.begin(), noSectors.faceSector.end(), -1);
  EXPECT_NE(message(noSectors).find("has no sector"), std::string::npos);
  SeamCarvingOptions badStiffness;
  badStiffness.stiffnessEpsilon = 0.0;
  EXPECT_NE(message(setup.input(), badStiffness).find("stiffness"), std::string::npos);

  GeometrySeamCarving carving(setup.input(), SeamCarvingOptions());
  Eigen::Matrix4d singular = Eigen::Matrix4d::Identity();
  singular(2, 2) = 0.0;
  EXPECT_THROW(carving.deform(singular), Error);
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
  projective(3, 2) = 0.5;
  EXPECT_THROW(carving.deform(projective), Error);
  Eigen::Matrix4d nan = Eigen::Matrix4d::Identity();
  nan(0, 3) = std::nan("");
  EXPECT_THROW(carving.deform(nan), Error);
  // A refused transform leaves the session usable.
  EXPECT_EQ(carving.deform(Eigen::Matrix4d::Identity()).triangles, setup.mesh.triangles());
}

} // namespace kerf
