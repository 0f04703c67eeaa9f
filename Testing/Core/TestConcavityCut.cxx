// The best-scored isoline of a harmonic field lies in the neck of a two-lobe shape.
#include "BenchmarkMeshes.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/LaplacianWeights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace kerf;

namespace
{
struct NeckCase
{
  LaplacianWeighting weighting;
  const char* name;
  bool mustFindTheNeck;
};

void PrintTo(const NeckCase& c, std::ostream* out)
{
  *out << c.name;
}

class ConcavityCut : public ::testing::TestWithParam<NeckCase>
{
};
} // namespace

TEST_P(ConcavityCut, BestIsolineLiesInTheNeck)
{
  // The benchmarks' dumbbell: lobes of radii 1 and 0.8, the neck off-centre at z = 0.3 and
  // pinched to a third.
  const double halfLength = benchmarks::DumbbellHalfLength;
  const std::array<double, 2> radii = benchmarks::DumbbellLobeRadii;
  const TriangleMesh shape =
    makeDumbbell(halfLength, radii, benchmarks::DumbbellNeckCentre, benchmarks::DumbbellNeckDepth, 5);
  const double zNeck = benchmarks::DumbbellNeckHeight();
  // Hard values on the two tips (the last 5% of the length at each end).
  FieldConstraints constraints;
  for (int v = 0; v < shape.vertexCount(); ++v)
  {
    const double z = shape.point(v).z();
    if (std::abs(z) > 0.9 * halfLength)
    {
      constraints.dirichletVertices.push_back(v);
      constraints.dirichletValues.push_back(z > 0 ? 1.0 : 0.0);
    }
  }
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(shape);
  LaplacianWeightOptions options;
  options.weighting = GetParam().weighting;
  const std::vector<double> weights = computeLaplacianWeights(shape, options, &descriptors);
  HarmonicFieldSolver solver;
  const HarmonicFieldSolution solution = solver.solve(shape, weights, constraints);
  EXPECT_LE(solution.relativeResidual, 1e-10);

  std::vector<double> magnitudes;
  for (const Vector3& g : computeFaceGradients(shape, solution.field))
  {
    magnitudes.push_back(g.norm());
  }
  const std::vector<IsovalueScore> scores = scoreIsovalues(shape, solution.field, magnitudes, 50);
  ASSERT_EQ(scores.size(), 50u);
  const auto best = std::max_element(
    scores.begin(), scores.end(), [](const IsovalueScore& a, const IsovalueScore& b) { return a.score < b.score; });
  const std::vector<Isoline> lines = extractIsolines(shape, solution.field, best->value);
  ASSERT_FALSE(lines.empty());
  double worst = 0.0;
  for (const Isoline& line : lines)
  {
    for (const Vector3& p : line.points)
    {
      worst = std::max(worst, std::abs(p.z() - zNeck));
    }
  }
  const double tolerance = 0.1 * std::min(radii[0], radii[1]);
  RecordProperty("Weighting", GetParam().name);
  RecordProperty("WorstDistanceFromNeck", std::to_string(worst));
  std::cout << GetParam().name << ": best isovalue " << best->value << ", farthest isoline point " << worst
            << " from the neck (tolerance " << tolerance << ")" << std::endl;
  if (GetParam().mustFindTheNeck)
  {
    EXPECT_LE(worst, tolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(Weightings, ConcavityCut,
  ::testing::Values(NeckCase{ LaplacianWeighting::ConcavityAware, "ConcavityAware", true },
    NeckCase{ LaplacianWeighting::SmoothConcavity, "SmoothConcavity", true },
    NeckCase{ LaplacianWeighting::Cotangent, "Cotangent", false }),
  [](const ::testing::TestParamInfo<NeckCase>& info) { return std::string(info.param.name); });
