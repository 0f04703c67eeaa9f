// The numeric supernodal factorization's routes (Kerf's driver with Eigen's kernels per
// instruction-set level, CHOLMOD's) against each other, on the matrices the solvers factor.
#include "Mesh/MeshGenerators.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/NestedDissection.h"
#include "Numerics/SerialOpenMP.h"
#include "Numerics/SparseCholesky.h"
#include "Numerics/SupernodalFactorization.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>
#endif

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
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

#ifdef KERF_HAVE_CHOLMOD
using Complex = std::complex<double>;

// CHOLMOD's supernodal analysis (AMD) of the lower triangle `lower`; freed with the object.
struct Analysis
{
  template <typename Scalar>
  explicit Analysis(const Eigen::SparseMatrix<Scalar>& lower)
  {
    startCholmod(&this->common);
    this->common.supernodal = CHOLMOD_SUPERNODAL;
    this->common.print = 0;
    this->a = cholmodView(lower, -1);
    this->factor = cholmod_analyze(&this->a, &this->common);
  }
  ~Analysis()
  {
    cholmod_free_factor(&this->factor, &this->common);
    cholmod_finish(&this->common);
  }
  Analysis(const Analysis&) = delete;
  Analysis& operator=(const Analysis&) = delete;
  cholmod_common common;
  cholmod_sparse a{};
  cholmod_factor* factor = nullptr;
};

// The values of the supernodal factor of the lower triangle `lower` (AMD), computed by `route`
// through factorizeSupernodal, and the solution of A x = b with it (CHOLMOD's solve).
template <typename Scalar>
std::pair<std::vector<Scalar>, std::vector<Scalar>> factorAndSolve(
  const Eigen::SparseMatrix<Scalar>& lower, SupernodalRoute route, const std::vector<Scalar>& b)
{
  Analysis analysis(lower);
  cholmod_common& common = analysis.common;
  cholmod_sparse& a = analysis.a;
  cholmod_factor*& factor = analysis.factor;
  std::pair<std::vector<Scalar>, std::vector<Scalar>> result;
  if (factor && factorizeSupernodal(&a, factor, &common, route) && factor->minor == factor->n && factor->is_super)
  {
    const Scalar* values = static_cast<const Scalar*>(factor->x);
    result.first.assign(values, values + factor->xsize);
    cholmod_dense rhs{};
    rhs.nrow = rhs.nzmax = rhs.d = b.size();
    rhs.ncol = 1;
    rhs.x = const_cast<Scalar*>(b.data());
    rhs.xtype = a.xtype;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor, &rhs, &common);
    if (x)
    {
      result.second.assign(static_cast<const Scalar*>(x->x), static_cast<const Scalar*>(x->x) + b.size());
      cholmod_free_dense(&x, &common);
    }
  }
  return result;
}

// The values of the supernodal factor of `lower` computed by `route` into memory lent to the
// factor `offset` bytes past a 64-byte boundary (as the charts lend their kept buffer).
template <typename Scalar>
std::vector<Scalar> factorValuesAt(const Eigen::SparseMatrix<Scalar>& lower, SupernodalRoute route, std::size_t offset)
{
  Analysis analysis(lower);
  cholmod_common& common = analysis.common;
  cholmod_sparse& a = analysis.a;
  cholmod_factor*& factor = analysis.factor;
  std::vector<Scalar> values;
  if (factor && factor->is_super)
  {
    std::vector<unsigned char> memory(factor->xsize * sizeof(Scalar) + 128);
    unsigned char* start = memory.data() + (64 - reinterpret_cast<std::uintptr_t>(memory.data()) % 64) % 64 + offset;
    std::memset(start, 0xff, factor->xsize * sizeof(Scalar)); // stale values: NaN
    factor->x = start;
    factor->xtype = a.xtype;
    if (factorizeSupernodal(&a, factor, &common, route) && factor->minor == factor->n)
    {
      values.resize(factor->xsize);
      std::memcpy(values.data(), start, factor->xsize * sizeof(Scalar));
    }
    factor->x = nullptr;
    factor->xtype = CHOLMOD_PATTERN;
  }
  return values;
}

template <typename Scalar>
double largestDifference(const std::vector<Scalar>& a, const std::vector<Scalar>& b)
{
  double largest = a.size() == b.size() ? 0.0 : 1e300;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    largest = std::max(largest, std::abs(a[i] - b[i]));
  }
  return largest;
}

template <typename Scalar>
double largestMagnitude(const std::vector<Scalar>& a)
{
  double largest = 0.0;
  for (const Scalar& v : a)
  {
    largest = std::max(largest, std::abs(v));
  }
  return largest;
}
#endif

} // namespace

#ifdef KERF_HAVE_CHOLMOD
TEST(SupernodalFactorization, HermitianFactorsMatchCHOLMODEntryByEntry)
{
  const std::vector<SupernodalRoute> routes = kerfRoutes();
  if (routes.empty())
  {
    GTEST_SKIP() << "this processor runs no Kerf kernel level (CHOLMOD factors)";
  }
  // H = L + shift I + i S on an icosphere, S_ij = -S_ji = 0.2 w_ij: Hermitian, and positive
  // definite by diagonal dominance (|L_ij + i S_ij| = 1.02 w_ij, shift 0.1 times the largest
  // diagonal entry).
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const std::vector<double> w = computeLaplacianWeights(sphere, LaplacianWeightOptions());
  const Eigen::SparseMatrix<double> L = assembleLaplacian(sphere, w);
  const double shift = 0.1 * L.diagonal().maxCoeff();
  std::vector<Eigen::Triplet<Complex>> entries;
  for (int e = 0; e < sphere.edgeCount(); ++e)
  {
    const int i = std::max(sphere.edgeVertices(e)[0], sphere.edgeVertices(e)[1]);
    const int j = std::min(sphere.edgeVertices(e)[0], sphere.edgeVertices(e)[1]);
    entries.emplace_back(i, j, Complex(-w[e], 0.2 * w[e]));
  }
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    entries.emplace_back(v, v, Complex(L.coeff(v, v) + shift, 0.0));
  }
  Eigen::SparseMatrix<Complex> H(sphere.vertexCount(), sphere.vertexCount());
  H.setFromTriplets(entries.begin(), entries.end());
  H.makeCompressed();
  std::vector<Complex> b(static_cast<std::size_t>(H.rows()));
  for (std::size_t k = 0; k < b.size(); ++k)
  {
    b[k] = Complex(std::cos(0.01 * k), std::sin(0.02 * k));
  }
  // The real system too, entry by entry.
  const Eigen::SparseMatrix<double> R = shiftedLaplacian(sphere, shift);
  std::vector<double> c(static_cast<std::size_t>(R.rows()));
  for (std::size_t k = 0; k < c.size(); ++k)
  {
    c[k] = std::cos(0.01 * k);
  }
  const auto referenceH = factorAndSolve(H, SupernodalRoute::CHOLMOD, b);
  const auto referenceR = factorAndSolve(R, SupernodalRoute::CHOLMOD, c);
  ASSERT_FALSE(referenceH.first.empty());
  ASSERT_FALSE(referenceR.first.empty());
  for (SupernodalRoute route : routes)
  {
    const auto h = factorAndSolve(H, route, b);
    EXPECT_LE(largestDifference(h.first, referenceH.first), 1e-12 * largestMagnitude(referenceH.first));
    EXPECT_LE(largestDifference(h.second, referenceH.second), 1e-11 * largestMagnitude(referenceH.second));
    const auto r = factorAndSolve(R, route, c);
    EXPECT_LE(largestDifference(r.first, referenceR.first), 1e-12 * largestMagnitude(referenceR.first));
    EXPECT_LE(largestDifference(r.second, referenceR.second), 1e-11 * largestMagnitude(referenceR.second));
    // Deterministic: the same bits again, and wherever the values' memory starts (the charts
    // lend theirs), over stale values.
    EXPECT_EQ(factorAndSolve(H, route, b).first, h.first);
    const std::vector<Complex> lent = factorValuesAt(H, route, 0);
    ASSERT_EQ(lent.size(), h.first.size());
    EXPECT_LE(largestDifference(lent, referenceH.first), 1e-12 * largestMagnitude(referenceH.first));
    for (std::size_t offset : { 16, 32, 48 })
    {
      EXPECT_TRUE(factorValuesAt(H, route, offset) == lent) << "offset " << offset;
      EXPECT_TRUE(factorValuesAt(R, route, offset / 2) == factorValuesAt(R, route, 0)) << "offset " << offset / 2;
    }
  }
}
#endif

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

#ifdef KERF_HAVE_CHOLMOD
TEST(SupernodalFactorization, AnEntryOutsideTheAnalysedPatternIsRefusedByKerfsRoutes)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const Eigen::SparseMatrix<double> A = shiftedLaplacian(sphere, 1e-2);
  for (SupernodalRoute route : kerfRoutes())
  {
    Analysis analysis(A);
    ASSERT_NE(analysis.factor, nullptr);
    ASSERT_TRUE(analysis.factor->is_super);
    // A pair of rows that the factor's pattern does not join (the permuted column of the earlier
    // one, in its supernode's row list, lacks the later one).
    const cholmod_factor& f = *analysis.factor;
    const int* perm = static_cast<const int*>(f.Perm);
    const int* super = static_cast<const int*>(f.super);
    const int* pi = static_cast<const int*>(f.pi);
    const int* rows = static_cast<const int*>(f.s);
    const int n = static_cast<int>(f.n);
    std::vector<int> inverse(n), supernodeOf(n);
    for (int k = 0; k < n; ++k)
    {
      inverse[perm[k]] = k;
    }
    for (int t = 0; t < static_cast<int>(f.nsuper); ++t)
    {
      std::fill(supernodeOf.begin() + super[t], supernodeOf.begin() + super[t + 1], t);
    }
    int outsideRow = -1, outsideColumn = -1;
    for (int v = 1; v < n && outsideRow < 0; ++v)
    {
      const int a = std::min(inverse[0], inverse[v]), b = std::max(inverse[0], inverse[v]);
      const int t = supernodeOf[a];
      if (std::find(rows + pi[t], rows + pi[t + 1], b) == rows + pi[t + 1])
      {
        outsideRow = v;
        outsideColumn = 0;
      }
    }
    ASSERT_GE(outsideRow, 0);
    Eigen::SparseMatrix<double> B = A;
    B.coeffRef(outsideRow, outsideColumn) = -1e-3;
    B.makeCompressed();
    cholmod_sparse b = cholmodView(B, -1);
    EXPECT_FALSE(factorizeSupernodal(&b, analysis.factor, &analysis.common, route))
      << "route " << static_cast<int>(route);
    EXPECT_EQ(analysis.common.status, CHOLMOD_INVALID);
    // The same factor still takes the analysed matrix.
    cholmod_sparse a = cholmodView(A, -1);
    EXPECT_TRUE(factorizeSupernodal(&a, analysis.factor, &analysis.common, route));
    EXPECT_EQ(analysis.factor->minor, analysis.factor->n);
  }
}
#endif

TEST(SupernodalFactorization, MatricesWithNaNAreRefusedByKerfsRoutes)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  Eigen::SparseMatrix<double> withNaN = shiftedLaplacian(sphere, 1e-2);
  withNaN.valuePtr()[withNaN.nonZeros() / 2] = std::numeric_limits<double>::quiet_NaN();
  // Kerf's routes refuse it (CHOLMOD's, with OpenBLAS's potrf, factors it into NaNs; Kerf's
  // solvers validate their input's numbers first either way).
  for (SupernodalRoute route : kerfRoutes())
  {
    SparseCholesky cholesky;
    cholesky.setSupernodalRoute(route);
    EXPECT_FALSE(cholesky.factor(withNaN)) << "route " << static_cast<int>(route);
  }
}

TEST(SupernodalFactorization, AutomaticTakesTheWidestLevelThisProcessorRuns)
{
  // Core.SupernodalRouteFromEnvironment.* run this test again with KERF_SUPERNODAL_ROUTE set.
  const SupernodalRoute automatic = automaticSupernodalRoute();
  EXPECT_TRUE(supernodalRouteAvailable(automatic));
  const char* named = std::getenv("KERF_SUPERNODAL_ROUTE");
  const std::string name = named ? named : "";
  RecordProperty("AutomaticRoute", static_cast<int>(automatic));
  if (name == "cholmod")
  {
    EXPECT_EQ(automatic, SupernodalRoute::CHOLMOD);
    return;
  }
  if (name == "avx2" && supernodalRouteAvailable(SupernodalRoute::AVX2))
  {
    EXPECT_EQ(automatic, SupernodalRoute::AVX2);
    return;
  }
  if (supernodalRouteAvailable(SupernodalRoute::AVX512))
  {
    EXPECT_EQ(automatic, SupernodalRoute::AVX512);
    EXPECT_TRUE(supernodalRouteAvailable(SupernodalRoute::AVX2));
  }
  else if (supernodalRouteAvailable(SupernodalRoute::AVX2))
  {
    EXPECT_EQ(automatic, SupernodalRoute::AVX2);
  }
}

#ifdef KERF_HAVE_CHOLMOD
// SerialOpenMP changes the OpenMP runtime CHOLMOD loaded on the calling thread only, and for its
// lifetime only: a host application's other threads keep their own setting.
TEST(SupernodalFactorization, SerialOpenMPChangesOnlyTheCallingThreadWhileAlive)
{
  const auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  ASSERT_NE(get, nullptr) << "CHOLMOD loads an OpenMP runtime (libgomp on Debian)";
  const int before = get();
  ASSERT_GT(before, 0);
  {
    const SerialOpenMP serial;
    EXPECT_EQ(get(), 0);
    int other = -1;
    std::thread([&] { other = get(); }).join();
    EXPECT_EQ(other, before) << "another thread's setting is its own";
  }
  EXPECT_EQ(get(), before);
}
#endif
