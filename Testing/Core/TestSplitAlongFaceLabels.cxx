// splitAlongFaceLabels: each label its own piece, areas, faces and positions unchanged, deterministic numbering.
#include "Error.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/SplitAlongFaceLabels.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace kerf
{
namespace
{

double triangleArea(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  return 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
}

TEST(SplitAlongFaceLabels, EachLabelIsOnePieceWithTheSameFacesAndArea)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<int> labels = octantLabels(sphere);
  const SplitMesh split = splitAlongFaceLabels(sphere, labels);
  ASSERT_EQ(split.mesh.faceCount(), sphere.faceCount());
  EXPECT_EQ(split.faceLabel, labels);
  EXPECT_EQ(split.mesh.componentCount(), 8);
  double before = 0.0, after = 0.0;
  std::map<int, std::set<int>> componentsOfLabel;
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    before += triangleArea(sphere, f);
    after += triangleArea(split.mesh, f);
    componentsOfLabel[labels[static_cast<std::size_t>(f)]].insert(split.mesh.faceComponent(f));
    for (int k = 0; k < 3; ++k)
    {
      const int v = split.mesh.triangle(f)[static_cast<std::size_t>(k)];
      // Each corner copies the input's corner, at the same position.
      EXPECT_EQ(split.originalPoint[static_cast<std::size_t>(v)], sphere.triangle(f)[static_cast<std::size_t>(k)]);
      EXPECT_EQ(split.mesh.point(v), sphere.point(sphere.triangle(f)[static_cast<std::size_t>(k)]));
    }
  }
  EXPECT_NEAR(after, before, 1e-12 * before);
  EXPECT_EQ(componentsOfLabel.size(), 8u);
  for (const auto& entry : componentsOfLabel)
  {
    EXPECT_EQ(entry.second.size(), 1u) << "label " << entry.first;
  }
  // No edge is shared by faces of two labels: every edge is inside one label.
  for (int e = 0; e < split.mesh.edgeCount(); ++e)
  {
    const auto& faces = split.mesh.edgeFaces(e);
    if (faces[1] >= 0)
    {
      EXPECT_EQ(labels[static_cast<std::size_t>(faces[0])], labels[static_cast<std::size_t>(faces[1])]);
    }
  }
  // Vertices are numbered by input vertex, then label.
  for (std::size_t v = 1; v < split.originalPoint.size(); ++v)
  {
    EXPECT_LE(split.originalPoint[v - 1], split.originalPoint[v]);
  }
  const SplitMesh again = splitAlongFaceLabels(sphere, labels);
  EXPECT_EQ(again.mesh.triangles(), split.mesh.triangles());
  EXPECT_EQ(again.originalPoint, split.originalPoint);
}

TEST(SplitAlongFaceLabels, OneLabelKeepsTheMeshAndDropsUnusedPoints)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 3, 3);
  const SplitMesh split = splitAlongFaceLabels(grid, std::vector<int>(static_cast<std::size_t>(grid.faceCount()), 7));
  EXPECT_EQ(split.mesh.vertexCount(), grid.vertexCount());
  EXPECT_EQ(split.mesh.triangles(), grid.triangles());

  std::vector<Vector3> points = grid.points();
  points.emplace_back(5.0, 5.0, 5.0);
  const TriangleMesh withUnused(points, grid.triangles());
  const SplitMesh dropped =
    splitAlongFaceLabels(withUnused, std::vector<int>(static_cast<std::size_t>(grid.faceCount()), 0));
  EXPECT_EQ(dropped.mesh.vertexCount(), grid.vertexCount());
}

TEST(SplitAlongFaceLabels, DuplicatesTheBorderBetweenTwoLabels)
{
  // A 2 x 1 grid: the middle column of 2 vertices is shared by the two labels.
  const TriangleMesh grid = makeGrid(2.0, 1.0, 2, 1);
  std::vector<int> labels;
  for (const Triangle& t : grid.triangles())
  {
    const double x = (grid.point(t[0]) + grid.point(t[1]) + grid.point(t[2])).x() / 3.0;
    labels.push_back(x < 1.0 ? 0 : 1);
  }
  const SplitMesh split = splitAlongFaceLabels(grid, labels);
  EXPECT_EQ(split.mesh.vertexCount(), grid.vertexCount() + 2);
  EXPECT_EQ(split.mesh.componentCount(), 2);
}

TEST(SplitAlongFaceLabels, SeparatesFansOfOneLabelOnRequest)
{
  // Two triangles of one label touching at vertex 0 only, and a third of another label.
  const TriangleMesh bowtie({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 0, 0 }, { -1, -1, 0 }, { 0, 1, 0 } },
    { { { 0, 1, 2 } }, { { 0, 3, 4 } }, { { 0, 2, 5 } } });
  const std::vector<int> labels = { 4, 4, 1 };
  const SplitMesh kept = splitAlongFaceLabels(bowtie, labels);
  EXPECT_EQ(kept.mesh.vertexCount(), 8); // vertices 0 and 2 copied for label 1
  EXPECT_EQ(kept.mesh.componentCount(), 2);
  const SplitMesh separated = splitAlongFaceLabels(bowtie, labels, LabelFans::Separate);
  EXPECT_EQ(separated.mesh.vertexCount(), 9);
  EXPECT_EQ(separated.mesh.componentCount(), 3);
  // Copies of vertex 0: label 1 first, then label 4's fans by their first face.
  EXPECT_EQ(separated.mesh.triangle(2)[0], 0);
  EXPECT_EQ(separated.mesh.triangle(0)[0], 1);
  EXPECT_EQ(separated.mesh.triangle(1)[0], 2);
}

TEST(SplitAlongFaceLabels, RefusesALabelCountOtherThanTheFaceCount)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 2, 2);
  EXPECT_THROW(splitAlongFaceLabels(grid, std::vector<int>(3, 0)), Error);
}

} // namespace
} // namespace kerf
