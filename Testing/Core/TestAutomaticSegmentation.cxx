// The automatic segmentation methods in the Core on a body with three fingers (k = 4): every face labelled, segments connected, deterministic, and 1 - Rand index against the construction within a committed baseline.
#include "Evaluation/SegmentationMetrics.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/ConsensusCutSegmentation.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Segmentation/KMeansSegmentation.h"
#include "Segmentation/SpectralSegmentation.h"
#include "Segmentation/WatershedSegmentation.h"
#include "Session/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace kerf
{
namespace
{

// makeProtrusions' fingers: a sphere of radius 1 with three fingers of length 1 and angular
// width 0.35 in the xy plane (5,120 triangles).
constexpr int FingerCount = 3;
constexpr double FingerLength = 1.0, FingerWidth = 0.35;
constexpr double Pi = 3.14159265358979323846;

struct Fingers
{
  std::shared_ptr<Surface> surface = std::make_shared<Surface>(makeProtrusions(FingerCount, FingerLength, FingerWidth, 4));
  /// The construction's parts: a face belongs to the finger whose axis is nearest to its
  /// centroid's direction when that angle is below the crease's, else to the body.
  std::vector<int> parts;
  /// The crease: the angle from a finger's axis where the profile 1 + L exp(-(a / w)^4) bends
  /// most concavely (largest second derivative), 1.24 w.
  double creaseAngle = 0.0;

  Fingers()
  {
    const auto profile = [](double a) { return 1.0 + FingerLength * std::exp(-std::pow(a / FingerWidth, 4)); };
    double bend = -1e300;
    for (double a = FingerWidth; a < 2.0 * FingerWidth; a += 1e-4)
    {
      const double second = (profile(a + 1e-4) - 2.0 * profile(a) + profile(a - 1e-4)) / 1e-8;
      if (second > bend)
      {
        bend = second;
        this->creaseAngle = a;
      }
    }
    const TriangleMesh& mesh = this->surface->mesh();
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const Triangle& t = mesh.triangle(f);
      const Vector3 c = ((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0).normalized();
      int part = 0;
      for (int i = 0; i < FingerCount; ++i)
      {
        const Vector3 axis(std::cos(2 * Pi * i / FingerCount), std::sin(2 * Pi * i / FingerCount), 0.0);
        if (std::acos(std::max(-1.0, std::min(1.0, c.dot(axis)))) < this->creaseAngle)
        {
          part = i + 1;
        }
      }
      this->parts.push_back(part);
    }
  }
};

const Fingers& fingers()
{
  static const Fingers shape;
  return shape;
}

/// Checks what every method must give: one label per face, `expected` segments numbered from 0,
/// each segment edge-connected; returns 1 - Rand index against the construction.
double checkSegmentation(const std::vector<int>& labels, int expected)
{
  const TriangleMesh& mesh = fingers().surface->mesh();
  EXPECT_EQ(static_cast<int>(labels.size()), mesh.faceCount());
  std::set<int> distinct(labels.begin(), labels.end());
  EXPECT_EQ(static_cast<int>(distinct.size()), expected);
  EXPECT_EQ(*distinct.begin(), 0);
  EXPECT_EQ(*distinct.rbegin(), expected - 1);
  // Each segment is one edge-connected piece: flood each from its first face.
  std::vector<char> reached(labels.size(), 0);
  for (int label : distinct)
  {
    int start = 0;
    while (labels[static_cast<std::size_t>(start)] != label)
    {
      ++start;
    }
    std::vector<int> stack{ start };
    reached[static_cast<std::size_t>(start)] = 1;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && !reached[static_cast<std::size_t>(g)] && labels[static_cast<std::size_t>(g)] == label)
        {
          reached[static_cast<std::size_t>(g)] = 1;
          stack.push_back(g);
        }
      }
    }
  }
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    EXPECT_TRUE(reached[f]) << "segment " << labels[f] << " is in several pieces (face " << f << ")";
  }
  return compareSegmentations(mesh, labels, fingers().parts).randIndexError;
}

/// Runs `segment` twice (deterministic), checks the result and 1 - Rand index <= `threshold`.
void expectFingers(const std::string& method, const std::function<std::vector<int>()>& segment, double threshold)
{
  const std::vector<int> labels = segment();
  EXPECT_EQ(segment(), labels) << method << " is not deterministic";
  const double error = checkSegmentation(labels, FingerCount + 1);
  std::vector<std::vector<int>> confusion(FingerCount + 1, std::vector<int>(FingerCount + 1, 0));
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    ++confusion[static_cast<std::size_t>(labels[f])][static_cast<std::size_t>(fingers().parts[f])];
  }
  for (const auto& row : confusion)
  {
    std::cout << "  segment:";
    for (int count : row)
    {
      std::cout << " " << count;
    }
    std::cout << " (faces of the body, finger 1, 2, 3)" << std::endl;
  }
  std::cout << method << ": 1 - Rand index " << error << " against the body and its three fingers" << std::endl;
  EXPECT_LE(error, threshold) << method;
}

} // namespace

// The thresholds are the measured values (in the comments) with a small margin: a committed
// baseline, so that a method that gets worse fails. Only convex flooding and the consensus cuts
// find the three fingers at k = 4; the others do not, and the baselines record how they fail.
TEST(AutomaticSegmentation, ConsensusCutsOnABodyWithThreeFingers)
{
  // Measured 0.113: the three fingers are found, each cut a little below the crease (about 110
  // body faces on each finger's side).
  expectFingers("consensus cuts",
    [] { return segmentByConsensusCuts(*fingers().surface, FingerCount + 1, ConsensusCutOptions()).labels; }, 0.13);
}

TEST(AutomaticSegmentation, ConvexFloodingOnABodyWithThreeFingers)
{
  // Measured 0.020: the three fingers, cut within a ring of the crease.
  ConvexFloodingOptions options;
  options.segmentCount = FingerCount + 1;
  expectFingers("convex flooding",
    [&] { return segmentByConvexFlooding(FaceGraph(fingers().surface->mesh()), options).labels; }, 0.03);
}

TEST(AutomaticSegmentation, WatershedOnABodyWithThreeFingers)
{
  // Measured 0.230: the basins merge into the body and fingers together, with three slivers of
  // 8 to 24 faces on one finger (the weakness the documentation names).
  WatershedOptions options;
  options.segmentCount = FingerCount + 1;
  expectFingers("watershed", [&] { return segmentByWatershed(FaceGraph(fingers().surface->mesh()), options).labels; }, 0.25);
}

TEST(AutomaticSegmentation, SpectralClusteringOnABodyWithThreeFingers)
{
  // Measured 0.461: two finger tips and the body split in two halves.
  expectFingers("spectral",
    [] {
      return segmentSpectrally(FaceGraph(fingers().surface->mesh()), FingerCount + 1, SpectralSegmentationOptions()).labels;
    },
    0.48);
}

TEST(AutomaticSegmentation, KMeansOnABodyWithThreeFingers)
{
  // Measured 0.614: four sectors of the body, the fingers shared among them.
  expectFingers("k-means",
    [] {
      return segmentByKMeans(FaceGraph(fingers().surface->mesh()), FingerCount + 1, KMeansSegmentationOptions()).labels;
    },
    0.63);
}

TEST(AutomaticSegmentation, FaceClusteringOnABodyWithThreeFingers)
{
  // Measured 0.622: four sectors of the body, as k-means.
  expectFingers("face clustering",
    [] {
      return cutHierarchyAtCount(
        buildFaceClusterHierarchy(FaceGraph(fingers().surface->mesh()), HierarchicalClusteringOptions()), FingerCount + 1);
    },
    0.64);
}

} // namespace kerf
