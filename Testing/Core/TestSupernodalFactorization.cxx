// The numeric supernodal factorization's routes (Kerf's driver with Eigen's kernels per
// instruction-set level, CHOLMOD's) against each other, on the matrices the solvers factor.
#include "Harmonic/LaplacianWeights.h"
#include "Harmonic/NestedDissection.h"
#include "Harmonic/SparseCholesky.h"
#include "Harmonic/SupernodalFactorization.h"
#include "Mesh/MeshGenerators.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cstring>
#include <vector>

using namespace kerf;

namespace
{

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// A cotangent Laplacian with a small mass shift (positive definite), its lower triangle only.
Eigen::SparseMatrix<double> shiftedLaplacian(const TriangleMesh& mesh, double shift)
{
  const Eigen::SparseMatrix<double> L =
    assembleLaplacian(mesh, computeLaplacianWeights(mesh, LaplacianWeightOptions()));
  Eigen::SparseMatrix<double> identity(L.rows(), L.cols());
  identity.setIdentity();
  Eigen::SparseMatrix<double> A = (L + shift * identity).triangularView<Eigen::Lower>();
  A.makeCompressed();
  return A;
}

std::vector<SupernodalRoute> kerfRoutes()
{
  std::vector<SupernodalRoute> routes;
  for (SupernodalRoute route : { SupernodalRoute::AVX2, SupernodalRoute::AVX512 })
  {
    if (supernodalRouteAvailable(route))
    {
      routes.push_back(route);
    }
  }
  return routes;
}

} // namespace

TEST(SupernodalFactorization, KerfRoutesMatchCHOLMOD)
{
  const std::vector<SupernodalRoute> routes = kerfRoutes();
  if (routes.empty())
  {
    GTEST_SKIP() << "this processor runs no Kerf kernel level (CHOLMOD factors)";
  }
  // An icosphere (closed, AMD), a finer one ordered by nested dissection (large supernodes), a
  // grid (open, the upper triangle given too: only the lower one may be read).
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const TriangleMesh fine = makeIcosphere(1.0, 5);
  const TriangleMesh grid = makeGrid(1.0, 0.7, 60, 40);
  struct Case
  {
    Eigen::SparseMatrix<double> A;
    std::vector<int> permutation;
  };
  std::vector<Case> cases;
  cases.push_back({ shiftedLaplacian(sphere, 1e-3), {} });
  cases.push_back({ shiftedLaplacian(fine, 1e-6), {} });
  cases.back().permutation = geometricNestedDissection(fine.points(), cases.back().A, 16);
  {
    const Eigen::SparseMatrix<double> lower = shiftedLaplacian(grid, 1e-2);
    Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
    full.makeCompressed();
    cases.push_back({ full, {} });
  }
  for (const Case& c : cases)
  {
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(c.A.rows(), -1.0, 2.0);
    SparseCholesky reference;
    reference.setSupernodalRoute(SupernodalRoute::CHOLMOD);
    ASSERT_TRUE(c.permutation.empty() ? reference.factor(c.A) : reference.factor(c.A, c.permutation));
    const Eigen::VectorXd x = reference.solve(b);
    const Eigen::SparseMatrix<double> full = c.A.selfadjointView<Eigen::Lower>();
    ASSERT_LE((full * x - b).norm(), 1e-9 * b.norm());
    for (SupernodalRoute route : routes)
    {
      SparseCholesky kerfFactor;
      kerfFactor.setSupernodalRoute(route);
      ASSERT_TRUE(c.permutation.empty() ? kerfFactor.factor(c.A) : kerfFactor.factor(c.A, c.permutation));
      EXPECT_EQ(kerfFactor.factorNonZeros(), reference.factorNonZeros());
      const Eigen::VectorXd y = kerfFactor.solve(b);
      EXPECT_LE((y - x).norm(), 1e-10 * x.norm()) << "route " << static_cast<int>(route);
      EXPECT_LE((full * y - b).norm(), 1e-9 * b.norm());
      // The same bits when factored again, and after another matrix was factored.
      ASSERT_TRUE(kerfFactor.factor(shiftedLaplacian(sphere, 0.5)));
      ASSERT_TRUE(c.permutation.empty() ? kerfFactor.factor(c.A) : kerfFactor.factor(c.A, c.permutation));
      EXPECT_TRUE(sameBits(kerfFactor.solve(b), y));
    }
  }
}

TEST(SupernodalFactorization, MatricesThatAreNotPositiveDefiniteAreRefusedByEveryRoute)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  // The Laplacian shifted down past its smallest eigenvalue (0): indefinite. The same shifted up
  // factors, so the refusal is the matrix's, not the route's.
  const Eigen::SparseMatrix<double> indefinite = shiftedLaplacian(sphere, -1e-2);
  const Eigen::SparseMatrix<double> definite = shiftedLaplacian(sphere, 1e-2);
  std::vector<SupernodalRoute> routes = kerfRoutes();
  routes.push_back(SupernodalRoute::CHOLMOD);
  for (SupernodalRoute route : routes)
  {
    SparseCholesky cholesky;
    cholesky.setSupernodalRoute(route);
    EXPECT_FALSE(cholesky.factor(indefinite)) << "route " << static_cast<int>(route);
    EXPECT_TRUE(cholesky.factor(definite)) << "route " << static_cast<int>(route);
  }
}

TEST(SupernodalFactorization, AutomaticTakesTheWidestLevelThisProcessorRuns)
{
  const SupernodalRoute automatic = automaticSupernodalRoute();
  EXPECT_TRUE(supernodalRouteAvailable(automatic));
  if (supernodalRouteAvailable(SupernodalRoute::AVX512))
  {
    EXPECT_EQ(automatic, SupernodalRoute::AVX512);
    EXPECT_TRUE(supernodalRouteAvailable(SupernodalRoute::AVX2));
  }
  else if (supernodalRouteAvailable(SupernodalRoute::AVX2))
  {
    EXPECT_EQ(automatic, SupernodalRoute::AVX2);
  }
  RecordProperty("AutomaticRoute", static_cast<int>(automatic));
}
