// parameterizeCharts: split, disk check, LSCM or LinABF, distortion, overlap count; the charts laid out by
// ChartPacking.
#include "Parameterization/ChartParameterization.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/Planar.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/SerialOpenMP.h"
#include "Numerics/SparseCholesky.h"
#include "Numerics/SupernodalFactorization.h"
#include "Numerics/SupernodalSolve.h"
#include "Parameterization/CutToDisk.h"
#include "Parameterization/LinearABF.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <limits>
#include <new>
#include <numeric>
#include <utility>

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>
#endif

namespace kerf
{
namespace
{

// Calls edge(i, j, w) for each triangle's edge i-j with its share w = cot(angle opposite) / 2 of
// the cotangent Laplacian's weight, the cotangents given per corner (cornerCotangents).
template <typename EdgeFunction>
void forEachCotangentWeight(const TriangleMesh& chart, const std::vector<double>& cotangents, EdgeFunction edge)
{
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    const Triangle& t = chart.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      const int i = t[static_cast<std::size_t>((k + 1) % 3)];
      const int j = t[static_cast<std::size_t>((k + 2) % 3)];
      edge(i, j, 0.5 * cotangents[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)]);
    }
  }
}

// The boundary vertex farthest from `from` in 3D (the first of equals).
int farthestBoundaryVertex(const TriangleMesh& chart, const std::vector<int>& loop, int from)
{
  int best = loop.front();
  double bestDistance = -1.0;
  for (int v : loop)
  {
    const double distance = (chart.point(v) - chart.point(from)).squaredNorm();
    if (distance > bestDistance)
    {
      bestDistance = distance;
      best = v;
    }
  }
  return best;
}

Eigen::VectorXd solveSystem(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rhs, ChartSolver solver)
{
  if (solver == ChartSolver::RealCHOLMOD)
  {
    SparseCholesky cholesky;
    if (!cholesky.factor(lower))
    {
      throw Error("the conformal map's system is not positive definite");
    }
    return cholesky.solve(rhs);
  }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(lower);
  if (ldlt.info() != Eigen::Success)
  {
    throw Error("the conformal map's system is not positive definite");
  }
  return ldlt.solve(rhs);
}

double signedArea(const Vector2& a, const Vector2& b, const Vector2& c)
{
  return 0.5 * cross2(b - a, c - a);
}

// Adds one face's distortion to a summary (means are finished by finishSummary).
void accumulate(DistortionSummary& summary, const FaceDistortion& face, double area)
{
  summary.meanStretch += area * face.stretch;
  summary.surfaceStretch += area * face.inverseStretch * face.inverseStretch;
  summary.meanShear += area * face.shear;
  summary.maxStretch = std::max(summary.maxStretch, face.stretch);
  summary.maxShear = std::max(summary.maxShear, face.shear);
  summary.flippedFaces += face.flipped ? 1 : 0;
  summary.area += area;
}

void finishSummary(DistortionSummary& summary)
{
  if (summary.area > 0.0)
  {
    summary.meanStretch /= summary.area;
    summary.surfaceStretch = std::sqrt(summary.surfaceStretch / summary.area); // Sander et al. 2001, section 3
    summary.meanShear /= summary.area;
  }
}

} // namespace

std::string chartTopologyProblem(const TriangleMesh& chart)
{
  if (chart.empty())
  {
    return "it has no triangle";
  }
  const MeshReport report = inspectMesh(chart);
  if (report.zeroAreaFaces > 0)
  {
    return "it has " + std::to_string(report.zeroAreaFaces) + " zero-area triangles";
  }
  if (report.nonManifoldEdges > 0 || report.nonManifoldVertices > 0)
  {
    return "it is not manifold (" + std::to_string(report.nonManifoldEdges) + " non-manifold edges, " +
      std::to_string(report.nonManifoldVertices) + " non-manifold vertices)";
  }
  if (report.inconsistentEdges > 0)
  {
    return "its triangles are not consistently oriented";
  }
  if (report.components != 1)
  {
    return "it has " + std::to_string(report.components) + " separate pieces";
  }
  const int loops = report.boundaryLoops;
  const int genus = (2 - report.eulerCharacteristic - loops) / 2;
  if (loops != 1 || genus != 0)
  {
    return "it has " + std::to_string(loops) + " boundary loops and genus " + std::to_string(genus) +
      " (a disk has one boundary loop and genus 0)";
  }
  return {};
}

namespace
{
using Complex = std::complex<double>;

#ifdef KERF_HAVE_CHOLMOD
// CHOLMOD's analysis and L L^H (its supernodal values by factorizeSupernodal: Kerf's driver with
// Eigen's kernels for the processor) of one Hermitian system after another (the charts of one
// parameterizeCharts call) with one cholmod_common, and one buffer for a supernodal factor's values kept from system
// to system: the factorization writes every value of it, and a fresh factor's pages cost more to
// touch first than to fill (Documentation/filters/ChartParameterization.md, "Speed").
class HermitianSolves
{
public:
  HermitianSolves()
  {
    startCholmod(&this->Common);
    this->Common.print = 0; // a failure is reported by the exception below, never printed
    // AMD alone: METIS' ordering costs more than its fill saves on these charts (the figures are
    // in Documentation/filters/ChartParameterization.md).
    this->Common.nmethods = 1;
    this->Common.method[0].ordering = CHOLMOD_AMD;
  }
  ~HermitianSolves()
  {
    std::free(this->Values);
    cholmod_finish(&this->Common);
  }
  HermitianSolves(const HermitianSolves&) = delete;
  HermitianSolves& operator=(const HermitianSolves&) = delete;

  Eigen::VectorXcd solve(const Eigen::SparseMatrix<Complex>& lower, const Eigen::VectorXcd& rhs)
  {
    cholmod_sparse a = cholmodView(lower, -1); // the lower triangle
    const SerialOpenMP serial;
    const CholmodAllocatorScope allocator;
    cholmod_factor* factor = cholmod_analyze(&a, &this->Common);
    if (factor == nullptr)
    {
      throw Error("the sparse Cholesky analysis of the conformal map's system failed");
    }
    // The factor is given the kept buffer (CHOLMOD factors into values it finds allocated) and
    // takes it back before it is freed.
    struct Release
    {
      HermitianSolves& solves;
      cholmod_factor*& factor;
      ~Release()
      {
        if (this->factor->x == this->solves.Values)
        {
          this->factor->x = nullptr;
          this->factor->xtype = CHOLMOD_PATTERN;
        }
        cholmod_free_factor(&this->factor, &this->solves.Common);
      }
    } release{ *this, factor };
    if (factor->is_super)
    {
      const std::size_t doubles = 2 * factor->xsize;
      if (doubles > this->Capacity)
      {
        std::free(this->Values);
        this->Capacity = 0;
        this->Values = static_cast<double*>(std::malloc(doubles * sizeof(double)));
        if (this->Values == nullptr)
        {
          throw std::bad_alloc();
        }
        this->Capacity = doubles;
      }
      factor->x = this->Values;
      factor->xtype = CHOLMOD_COMPLEX;
    }
    if (!factorizeSupernodal(&a, factor, &this->Common) || this->Common.status != CHOLMOD_OK ||
      factor->minor < factor->n)
    {
      throw Error("the conformal map's system is not positive definite");
    }
    if (SupernodalSolve::supportsComplex(*factor))
    {
      // Kerf's one-column kernels (CHOLMOD's solve calls the BLAS per supernode).
      Eigen::VectorXcd solution(rhs.size());
      SupernodalSolve::solveComplex(*factor, rhs.data(), solution.data(), this->Work);
      return solution;
    }
    cholmod_dense b{};
    b.nrow = b.nzmax = b.d = static_cast<std::size_t>(rhs.size());
    b.ncol = 1;
    b.x = const_cast<Complex*>(rhs.data());
    b.xtype = CHOLMOD_COMPLEX;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor, &b, &this->Common);
    if (x == nullptr)
    {
      throw Error("the conformal map's system could not be solved");
    }
    const Eigen::VectorXcd solution = Eigen::Map<const Eigen::VectorXcd>(static_cast<const Complex*>(x->x), rhs.size());
    cholmod_free_dense(&x, &this->Common);
    return solution;
  }

private:
  cholmod_common Common;
  double* Values = nullptr; // a supernodal factor's values, interleaved real and imaginary parts
  std::size_t Capacity = 0; // doubles
  std::vector<double> Work; // SupernodalSolve's workspace
};
#else
class HermitianSolves
{
};
#endif

// Solves H z = rhs for the Hermitian positive definite H given by its lower triangle: with
// ComplexCHOLMOD, CHOLMOD's L L^H (supernodal or simplicial, CHOLMOD's choice by the flops per
// nonzero of the factor; supernodal values by factorizeSupernodal) after an AMD ordering, through `solves` if given;
// else Eigen's SimplicialLDLT.
Eigen::VectorXcd solveHermitian(
  const Eigen::SparseMatrix<Complex>& lower, const Eigen::VectorXcd& rhs, ChartSolver solver, HermitianSolves* solves)
{
#ifdef KERF_HAVE_CHOLMOD
  if (solver == ChartSolver::ComplexCHOLMOD)
  {
    if (solves != nullptr)
    {
      return solves->solve(lower, rhs);
    }
    HermitianSolves once;
    return once.solve(lower, rhs);
  }
#else
  (void)solver;
  (void)solves;
#endif
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>, Eigen::Lower> ldlt(lower);
  if (ldlt.info() != Eigen::Success)
  {
    throw Error("the conformal map's system is not positive definite");
  }
  return ldlt.solve(rhs);
}

// The conformal energy as the Hermitian form z^H H z / 2 in z = u + i v: H = L - i C, L the
// cotangent Laplacian and C the antisymmetric boundary term of the real form, so H has the
// Laplacian's pattern and half the real form's unknowns.
std::vector<Vector2> complexConformalMap(const TriangleMesh& chart, const std::vector<double>& cotangents,
  const std::vector<int>& loop, int pinA, int pinB, double pinDistance, ChartSolver solver, HermitianSolves* solves)
{
  const int n = chart.vertexCount();
  std::vector<int> freeIndex(static_cast<std::size_t>(n), -1);
  int freeCount = 0;
  for (int v = 0; v < n; ++v)
  {
    if (v != pinA && v != pinB)
    {
      freeIndex[static_cast<std::size_t>(v)] = freeCount++;
    }
  }
  std::vector<Complex> pinned(static_cast<std::size_t>(n), Complex(0.0, 0.0));
  pinned[static_cast<std::size_t>(pinB)] = Complex(pinDistance, 0.0);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(freeCount);
  // The lower triangle is written column by column from the chart's edges instead of from
  // triplets: the diagonal sums its corners' weights and each edge its two triangles' weights in
  // the triplets' order, so the matrix is the same to the bit.
  std::vector<double> diagonal(static_cast<std::size_t>(n), 0.0);
  std::vector<double> edgeWeight(static_cast<std::size_t>(chart.edgeCount()), 0.0);
  // The pinned vertices move to the right-hand side: rhs_a -= H_ab z_b for free a, pinned b.
  auto addPinned = [&](int a, int b, Complex value) {
    const int fa = freeIndex[static_cast<std::size_t>(a)];
    const int fb = freeIndex[static_cast<std::size_t>(b)];
    if (fa >= 0 && fb < 0)
    {
      rhs[fa] -= value * pinned[static_cast<std::size_t>(b)];
    }
    else if (fb >= 0 && fa < 0)
    {
      rhs[fb] -= std::conj(value) * pinned[static_cast<std::size_t>(a)];
    }
  };
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    const Triangle& t = chart.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      // Edge (k + 1) % 3 joins corners k + 1 and k + 2, opposite corner k.
      const int i = t[static_cast<std::size_t>((k + 1) % 3)];
      const int j = t[static_cast<std::size_t>((k + 2) % 3)];
      const double weight = 0.5 * cotangents[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)];
      diagonal[static_cast<std::size_t>(i)] += weight;
      diagonal[static_cast<std::size_t>(j)] += weight;
      edgeWeight[static_cast<std::size_t>(chart.faceEdge(f, (k + 1) % 3))] += weight;
      addPinned(i, j, -weight);
    }
  }
  // C_ij = -1/2 for a boundary edge i -> j, so H_ij = -i C_ij = i / 2: per edge, the imaginary
  // part of H at (larger vertex, smaller vertex).
  std::vector<double> edgeImaginary(static_cast<std::size_t>(chart.edgeCount()), 0.0);
  for (std::size_t e = 0; e < loop.size(); ++e)
  {
    const int i = loop[e];
    const int j = loop[(e + 1) % loop.size()];
    const IndexRange neighbors = chart.vertexNeighbors(i);
    const std::size_t at =
      static_cast<std::size_t>(std::find(neighbors.begin(), neighbors.end(), j) - neighbors.begin());
    edgeImaginary[static_cast<std::size_t>(chart.vertexEdges(i)[at])] = i > j ? 0.5 : -0.5;
    addPinned(i, j, Complex(0.0, 0.5));
  }
  // Free vertices keep the chart's order, so column fv holds the neighbours w > v.
  std::size_t nonZeros = 0;
  for (int v = 0; v < n; ++v)
  {
    if (freeIndex[static_cast<std::size_t>(v)] >= 0)
    {
      ++nonZeros;
      for (int w : chart.vertexNeighbors(v))
      {
        nonZeros += w > v && freeIndex[static_cast<std::size_t>(w)] >= 0 ? 1 : 0;
      }
    }
  }
  Eigen::SparseMatrix<Complex> lower(freeCount, freeCount);
  lower.resizeNonZeros(static_cast<Eigen::Index>(nonZeros));
  int* columnStart = lower.outerIndexPtr();
  int* rows = lower.innerIndexPtr();
  Complex* values = lower.valuePtr();
  std::vector<std::pair<int, int>> below; // (row, edge) of one column
  int entry = 0;
  for (int v = 0; v < n; ++v)
  {
    const int fv = freeIndex[static_cast<std::size_t>(v)];
    if (fv < 0)
    {
      continue;
    }
    columnStart[fv] = entry;
    rows[entry] = fv;
    values[entry++] = Complex(diagonal[static_cast<std::size_t>(v)], 0.0);
    below.clear();
    const IndexRange neighbors = chart.vertexNeighbors(v);
    for (std::size_t i = 0; i < neighbors.size(); ++i)
    {
      const int fw = freeIndex[static_cast<std::size_t>(neighbors[i])];
      if (neighbors[i] > v && fw >= 0)
      {
        below.emplace_back(fw, chart.vertexEdges(v)[i]);
      }
    }
    std::sort(below.begin(), below.end());
    for (const auto& [row, edge] : below)
    {
      rows[entry] = row;
      values[entry++] =
        Complex(-edgeWeight[static_cast<std::size_t>(edge)], edgeImaginary[static_cast<std::size_t>(edge)]);
    }
  }
  columnStart[freeCount] = entry;
  const Eigen::VectorXcd solution = solveHermitian(lower, rhs, solver, solves);
  std::vector<Vector2> uv(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
  {
    const int fv = freeIndex[static_cast<std::size_t>(v)];
    const Complex z = fv < 0 ? pinned[static_cast<std::size_t>(v)] : solution[fv];
    uv[static_cast<std::size_t>(v)] = Vector2(z.real(), z.imag());
  }
  return uv;
}
} // namespace

namespace
{
// leastSquaresConformalMap or linearAngleBasedFlattening of a chart known to be a disk
// (parameterizeCharts checks every chart once, before any is flattened).
std::vector<Vector2> flattenDisk(
  const TriangleMesh& chart, ChartMethod method, ChartSolver solver, HermitianSolves* solves = nullptr);

void requireDisk(const TriangleMesh& chart)
{
  const std::string problem = chartTopologyProblem(chart);
  if (!problem.empty())
  {
    throw Error("the chart is not a disk: " + problem);
  }
}
} // namespace

std::vector<Vector2> leastSquaresConformalMap(const TriangleMesh& chart, ChartSolver solver)
{
  requireDisk(chart);
  return flattenDisk(chart, ChartMethod::LSCM, solver);
}

std::vector<Vector2> linearAngleBasedFlattening(const TriangleMesh& chart, ChartSolver solver)
{
  requireDisk(chart);
  return flattenDisk(chart, ChartMethod::LinABF, solver);
}

namespace
{
// The conformal energy E_D - A with the cotangent weights of `cotangents` (per corner) minimised
// with the two boundary vertices farthest apart pinned: LSCM with the 3D angles' cotangents, the
// angle-based reconstruction with LinABF's.
std::vector<Vector2> conformalMapOfDisk(
  const TriangleMesh& chart, const std::vector<double>& cotangents, ChartSolver solver, HermitianSolves* solves)
{
  const int n = chart.vertexCount();
  const std::vector<int>& loop = chart.boundaryLoops().front();
  const int pinA = farthestBoundaryVertex(chart, loop, farthestBoundaryVertex(chart, loop, loop.front()));
  const int pinB = farthestBoundaryVertex(chart, loop, pinA);
  const double pinDistance = (chart.point(pinA) - chart.point(pinB)).norm();
  if (solver == ChartSolver::ComplexLDLT || solver == ChartSolver::ComplexCHOLMOD)
  {
    std::vector<Vector2> uv = complexConformalMap(chart, cotangents, loop, pinA, pinB, pinDistance, solver, solves);
    for (std::size_t v = 0; v < uv.size(); ++v)
    {
      if (!uv[v].allFinite())
      {
        throw Error("the conformal map is not finite at vertex " + std::to_string(v) + " of the chart");
      }
    }
    return uv;
  }

  // Unknowns u_i, v_i interleaved (index 2i, 2i+1) without the four pinned coordinates.
  std::vector<int> freeIndex(2 * static_cast<std::size_t>(n), -1);
  int freeCount = 0;
  for (int v = 0; v < n; ++v)
  {
    if (v != pinA && v != pinB)
    {
      freeIndex[2 * static_cast<std::size_t>(v)] = freeCount++;
      freeIndex[2 * static_cast<std::size_t>(v) + 1] = freeCount++;
    }
  }
  Eigen::VectorXd pinned = Eigen::VectorXd::Zero(2 * n);
  pinned[2 * pinB] = pinDistance;

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(chart.faceCount()) * 12 + loop.size() * 2);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(freeCount);
  // Entry (a, b) of the symmetric 2n x 2n matrix Q of E = x^T Q x / 2, given once for a != b.
  auto add = [&](int a, int b, double value) {
    const int fa = freeIndex[static_cast<std::size_t>(a)];
    const int fb = freeIndex[static_cast<std::size_t>(b)];
    if (fa >= 0 && fb >= 0)
    {
      triplets.emplace_back(std::max(fa, fb), std::min(fa, fb), value);
    }
    else if (fa >= 0)
    {
      rhs[fa] -= value * pinned[b];
    }
    else if (fb >= 0 && a != b)
    {
      rhs[fb] -= value * pinned[a];
    }
  };
  // Dirichlet energy: the cotangent Laplacian on u and on v.
  forEachCotangentWeight(chart, cotangents, [&](int i, int j, double weight) {
    for (int c = 0; c < 2; ++c)
    {
      add(2 * i + c, 2 * i + c, weight);
      add(2 * j + c, 2 * j + c, weight);
      add(2 * i + c, 2 * j + c, -weight);
    }
  });
  // Minus twice the signed area's matrix: A = sum over boundary edges i -> j of (u_i v_j - u_j v_i) / 2.
  for (std::size_t e = 0; e < loop.size(); ++e)
  {
    const int i = loop[e];
    const int j = loop[(e + 1) % loop.size()];
    add(2 * i, 2 * j + 1, -0.5);
    add(2 * j, 2 * i + 1, 0.5);
  }
  Eigen::SparseMatrix<double> lower(freeCount, freeCount);
  lower.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::VectorXd solution = solveSystem(lower, rhs, solver);

  std::vector<Vector2> uv(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
  {
    const int fu = freeIndex[2 * static_cast<std::size_t>(v)];
    uv[static_cast<std::size_t>(v)] =
      fu < 0 ? Vector2(pinned[2 * v], pinned[2 * v + 1]) : Vector2(solution[fu], solution[fu + 1]);
    if (!uv[static_cast<std::size_t>(v)].allFinite())
    {
      throw Error("the conformal map is not finite at vertex " + std::to_string(v) + " of the chart");
    }
  }
  return uv;
}

// LinABF's smallest angle passed to the reconstruction. Its linearised wheel condition can leave
// a corner of a very distorted chart at or below zero, where a triangle with those angles does
// not exist: such a corner is raised to this and its triangle's three angles scaled to sum pi.
constexpr double MinimumReconstructionAngle = 1e-6;

std::vector<double> reconstructionCotangents(const TriangleMesh& chart)
{
  const LinearABFAngles angles = linearAngleBasedAngles(chart);
  std::vector<double> cotangents(angles.angles.size());
  for (std::size_t c = 0; c < cotangents.size(); c += 3)
  {
    std::array<double, 3> alpha = { { angles.angles[c], angles.angles[c + 1], angles.angles[c + 2] } };
    if (std::min({ alpha[0], alpha[1], alpha[2] }) < MinimumReconstructionAngle)
    {
      for (double& a : alpha)
      {
        a = std::max(a, MinimumReconstructionAngle);
      }
      const double scale = M_PI / (alpha[0] + alpha[1] + alpha[2]);
      for (double& a : alpha)
      {
        a *= scale;
      }
    }
    for (std::size_t k = 0; k < 3; ++k)
    {
      cotangents[c + k] = 1.0 / std::tan(alpha[k]);
    }
  }
  return cotangents;
}

std::vector<Vector2> flattenDisk(
  const TriangleMesh& chart, ChartMethod method, ChartSolver solver, HermitianSolves* solves)
{
  return conformalMapOfDisk(
    chart, method == ChartMethod::LinABF ? reconstructionCotangents(chart) : cornerCotangents(chart), solver, solves);
}

} // namespace

FaceDistortion faceDistortion(
  const Vector3& p0, const Vector3& p1, const Vector3& p2, const Vector2& t0, const Vector2& t1, const Vector2& t2)
{
  // The triangle in an orthonormal frame of its plane, p0 at the origin and p1 on the x axis.
  const Vector3 e1 = p1 - p0;
  const Vector3 e2 = p2 - p0;
  const double length = e1.norm();
  const Vector3 x = e1 / length;
  const Vector3 y = (e1.cross(e2)).cross(e1).normalized();
  Eigen::Matrix2d local;
  local << length, e2.dot(x), 0.0, e2.dot(y);
  Eigen::Matrix2d image;
  image.col(0) = t1 - t0;
  image.col(1) = t2 - t0;
  const Eigen::Matrix2d J = image * local.inverse();
  // Singular values of a 2 x 2 matrix in closed form.
  const double E = 0.5 * (J(0, 0) + J(1, 1));
  const double F = 0.5 * (J(0, 0) - J(1, 1));
  const double G = 0.5 * (J(1, 0) + J(0, 1));
  const double H = 0.5 * (J(1, 0) - J(0, 1));
  // sqrt rather than std::hypot, whose guard against overflow (Jacobian entries beyond 1e150) cost
  // about 2% of parameterizeCharts.
  const double Q = std::sqrt(E * E + H * H);
  const double R = std::sqrt(F * F + G * G);
  const double s1 = Q + R;
  const double s2 = std::abs(Q - R);
  FaceDistortion distortion;
  distortion.stretch = std::sqrt(0.5 * (s1 * s1 + s2 * s2)); // Sander et al. 2001, section 3
  distortion.shear = s2 > 0.0 ? s1 / s2 : std::numeric_limits<double>::infinity();
  // The inverse map's singular values are 1 / s2 and 1 / s1.
  distortion.inverseStretch =
    s2 > 0.0 ? std::sqrt(0.5 * (1.0 / (s1 * s1) + 1.0 / (s2 * s2))) : std::numeric_limits<double>::infinity();
  distortion.flipped = J.determinant() < 0.0;
  return distortion;
}

namespace
{
// Per face: the stretch of the inverse map (Sander et al. 2001) after the chart is scaled to its
// 3D area, whatever the triangle's orientation, capped at SeamScoreCap (collapsed triangles get
// it). Returns the capped L2 norm, sqrt(sum A_f score_f^2 / sum A_f): finite, so that maps with
// collapsed triangles can be compared.
constexpr double SeamScoreCap = 1e3;
// A seam starts in a triangle whose score is at least this fraction of the worst one.
constexpr double SeamCandidateFraction = 0.1;

double seamScore(const TriangleMesh& chart, const std::vector<Vector2>& uv, std::vector<double>& faceScore)
{
  double area3D = 0.0;
  double areaUV = 0.0;
  std::vector<double> areas(static_cast<std::size_t>(chart.faceCount()));
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    const Triangle& t = chart.triangle(f);
    areas[static_cast<std::size_t>(f)] =
      0.5 * (chart.point(t[1]) - chart.point(t[0])).cross(chart.point(t[2]) - chart.point(t[0])).norm();
    area3D += areas[static_cast<std::size_t>(f)];
    areaUV += signedArea(
      uv[static_cast<std::size_t>(t[0])], uv[static_cast<std::size_t>(t[1])], uv[static_cast<std::size_t>(t[2])]);
  }
  const double scale = std::abs(areaUV) > 0.0 ? std::sqrt(area3D / std::abs(areaUV)) : 0.0;
  const double mirror = areaUV < 0.0 ? -1.0 : 1.0;
  auto scaled = [&](int v) {
    const Vector2& p = uv[static_cast<std::size_t>(v)];
    return Vector2(p.x() * scale, p.y() * scale * mirror);
  };
  faceScore.assign(static_cast<std::size_t>(chart.faceCount()), SeamScoreCap);
  double sum = 0.0;
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    const Triangle& t = chart.triangle(f);
    const FaceDistortion d =
      faceDistortion(chart.point(t[0]), chart.point(t[1]), chart.point(t[2]), scaled(t[0]), scaled(t[1]), scaled(t[2]));
    double& score = faceScore[static_cast<std::size_t>(f)];
    if (d.inverseStretch < SeamScoreCap)
    {
      score = d.inverseStretch;
    }
    sum += areas[static_cast<std::size_t>(f)] * score * score;
  }
  return area3D > 0.0 ? std::sqrt(sum / area3D) : SeamScoreCap;
}

// Cut augmentation of Gu, Gortler and Hoppe 2002 (section 3.2): while the map's L2 stretch is
// above the target and seams are left, cut the chart from its worst place to its boundary along
// the shortest edge path and flatten it again; stop at the first seam that does not lower the
// stretch (it is dropped). The worst place: of the triangles whose
// score is at least SeamCandidateFraction of the worst, the vertex farthest from the boundary
// (the tip of a protrusion the map shrank).
void addSeams(TriangleMesh& chart, std::vector<int>& toChart, std::vector<Vector2>& uv, ChartSummary& summary,
  const ChartParameterizationOptions& options, HermitianSolves* solves)
{
  if (options.maximumSeams <= 0)
  {
    return;
  }
  // The chart as it is cut further, and the last state that lowered the stretch.
  struct State
  {
    TriangleMesh chart;
    std::vector<int> toChart;
    std::vector<Vector2> uv;
    std::vector<double> faceScore;
    double score = 0.0;
    int seams = 0;
    double seamLength = 0.0;
  };
  std::vector<double> faceScore;
  const double score = seamScore(chart, uv, faceScore);
  if (!(score > options.seamStretchTarget))
  {
    return; // nothing to cut, nothing copied
  }
  State current{ chart, toChart, uv, std::move(faceScore), score, 0, 0.0 };
  State best = current;
  while (current.seams < options.maximumSeams && current.score > options.seamStretchTarget)
  {
    // Distances from the boundary along the edges, and the edge towards it.
    const EdgePathTree paths = shortestEdgePaths(current.chart, current.chart.boundaryLoops().front());
    const std::vector<double>& distance = paths.distance;
    const std::vector<int>& towards = paths.towards;
    const double worst = *std::max_element(current.faceScore.begin(), current.faceScore.end());
    int tip = -1;
    for (int f = 0; f < current.chart.faceCount(); ++f)
    {
      if (current.faceScore[static_cast<std::size_t>(f)] < SeamCandidateFraction * worst)
      {
        continue;
      }
      for (int v : current.chart.triangle(f))
      {
        if (tip < 0 || distance[static_cast<std::size_t>(v)] > distance[static_cast<std::size_t>(tip)] ||
          (distance[static_cast<std::size_t>(v)] == distance[static_cast<std::size_t>(tip)] && v < tip))
        {
          tip = v;
        }
      }
    }
    if (tip < 0 || !(distance[static_cast<std::size_t>(tip)] > 0.0))
    {
      break;
    }
    std::vector<char> flags(static_cast<std::size_t>(current.chart.edgeCount()), 0);
    for (int v = tip; towards[static_cast<std::size_t>(v)] >= 0;)
    {
      const int e = towards[static_cast<std::size_t>(v)];
      flags[static_cast<std::size_t>(e)] = 1;
      const std::array<int, 2>& ends = current.chart.edgeVertices(e);
      v = ends[0] == v ? ends[1] : ends[0];
    }
    EdgeCut cut = splitAlongEdges(current.chart, flags);
    try
    {
      requireDisk(cut.mesh);
      current.uv = flattenDisk(cut.mesh, options.method, options.solver, solves);
    }
    catch (const Error&)
    {
      break; // the best map so far stands
    }
    for (int& original : cut.originalVertex)
    {
      original = current.toChart[static_cast<std::size_t>(original)];
    }
    current.toChart = std::move(cut.originalVertex);
    current.chart = std::move(cut.mesh);
    current.score = seamScore(current.chart, current.uv, current.faceScore);
    ++current.seams;
    current.seamLength += cut.cutLength;
    if (!(current.score < best.score))
    {
      break; // Gu, Gortler and Hoppe 2002: stop when a seam no longer lowers the stretch
    }
    best = current;
  }
  chart = std::move(best.chart);
  toChart = std::move(best.toChart);
  uv = std::move(best.uv);
  summary.seams = best.seams;
  summary.seamLength = best.seamLength;
}
} // namespace

ChartParameterizationResult parameterizeCharts(
  const TriangleMesh& mesh, const std::vector<int>& faceLabels, const ChartParameterizationOptions& options)
{
  if (mesh.empty())
  {
    throw Error("the surface has no triangle");
  }
  if (!(options.margin >= 0.0 && options.margin <= 0.25))
  {
    throw Error("the margin between charts is " + std::to_string(options.margin) + ", outside [0, 0.25]");
  }
  ChartParameterizationResult result;
  // Pinched vertices are cut (one copy per fan), so each chart is a piece joined by edges.
  result.split = splitAlongFaceLabels(mesh, faceLabels, LabelFans::Separate);
  const TriangleMesh& split = result.split.mesh;

  // Charts: the connected pieces, in increasing label order, then piece order; faces in mesh order.
  // A piece has one label (the split gives each label its own copies of the vertices).
  std::vector<std::pair<int, int>> pieces(
    static_cast<std::size_t>(split.componentCount()), { 0, -1 }); // (label, component)
  for (int f = 0; f < split.faceCount(); ++f)
  {
    std::pair<int, int>& piece = pieces[static_cast<std::size_t>(split.faceComponent(f))];
    if (piece.second < 0)
    {
      piece = { faceLabels[static_cast<std::size_t>(f)], split.faceComponent(f) };
    }
  }
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
  std::vector<int> labels(pieces.size());
  std::vector<int> componentChart(static_cast<std::size_t>(split.componentCount()));
  for (std::size_t c = 0; c < pieces.size(); ++c)
  {
    labels[c] = pieces[c].first;
    componentChart[static_cast<std::size_t>(pieces[c].second)] = static_cast<int>(c);
  }
  std::vector<int> faceChart(faceLabels.size());
  std::vector<std::vector<int>> chartFaces(labels.size());
  for (int f = 0; f < split.faceCount(); ++f)
  {
    faceChart[static_cast<std::size_t>(f)] = componentChart[static_cast<std::size_t>(split.faceComponent(f))];
    chartFaces[static_cast<std::size_t>(faceChart[static_cast<std::size_t>(f)])].push_back(f);
  }
  // "chart 3", or "chart 3 (piece 2 of 4)" for a label in several pieces.
  auto chartName = [&](std::size_t c) {
    const auto first = std::lower_bound(labels.begin(), labels.end(), labels[c]);
    const auto last = std::upper_bound(labels.begin(), labels.end(), labels[c]);
    std::string name = "chart " + std::to_string(labels[c]);
    if (last - first > 1)
    {
      name += " (piece " + std::to_string(labels.begin() + static_cast<long>(c) - first + 1) + " of " +
        std::to_string(last - first) + ")";
    }
    return name;
  };

  // Each chart as its own mesh (vertices in split-mesh order), checked before any is solved.
  std::vector<TriangleMesh> pieceMeshes = split.componentMeshes();
  std::vector<TriangleMesh> charts(labels.size());
  std::vector<std::vector<int>> chartVertices(labels.size());
  std::string problems;
  // Charts cut into disks or along seams: per chart vertex, the vertex of the chart as first
  // built that it copies; and the summaries of those cuts.
  std::vector<std::vector<int>> toChart(labels.size());
  std::vector<ChartSummary> summaries(labels.size());
  // The split mesh's pieces share no vertex: each vertex is in its piece's chart, in increasing order.
  for (int v = 0; v < split.vertexCount(); ++v)
  {
    const int component = split.vertexComponent(v);
    if (component >= 0)
    {
      chartVertices[static_cast<std::size_t>(componentChart[static_cast<std::size_t>(component)])].push_back(v);
    }
  }
  for (std::size_t c = 0; c < labels.size(); ++c)
  {
    charts[c] = std::move(pieceMeshes[static_cast<std::size_t>(pieces[c].second)]);
    toChart[c].resize(chartVertices[c].size());
    std::iota(toChart[c].begin(), toChart[c].end(), 0);
    const std::string problem = chartTopologyProblem(charts[c]);
    if (problem.empty())
    {
      continue;
    }
    const MeshReport report = inspectMesh(charts[c]);
    if (options.cutToDisks && report.zeroAreaFaces == 0 && report.nonManifoldEdges == 0 &&
      report.nonManifoldVertices == 0 && report.inconsistentEdges == 0 && report.components == 1)
    {
      // Closed, several boundary loops or handles: cut into a disk.
      EdgeCut cut = cutToDisk(charts[c]);
      ChartSummary& summary = summaries[c];
      summary.cutFrom = std::to_string(report.boundaryLoops) + " boundary loops and genus " +
        std::to_string((2 - report.eulerCharacteristic - report.boundaryLoops) / 2);
      summary.cutEdgeCount = static_cast<int>(cut.cutEdges.size());
      summary.cutLength = cut.cutLength;
      toChart[c] = std::move(cut.originalVertex);
      charts[c] = std::move(cut.mesh);
      ++result.cutCharts;
      continue;
    }
    problems += (problems.empty() ? "" : "; ") + chartName(c) + ": " + problem;
  }
  if (!problems.empty())
  {
    throw Error(
      "these charts are not topological disks and cannot be flattened (cut them into disks first): " + problems);
  }
  // Flatten each chart, adding seams where the map is worst (options.maximumSeams).
  std::vector<std::vector<Vector2>> chartUV(labels.size());
  HermitianSolves solves;
  for (std::size_t c = 0; c < labels.size(); ++c)
  {
    chartUV[c] = flattenDisk(charts[c], options.method, options.solver, &solves);
    addSeams(charts[c], toChart[c], chartUV[c], summaries[c], options, &solves);
  }
  // Vertices copied by the cuts: the first copy keeps the split mesh's vertex, the others are
  // appended to it (charts share no vertex of the split mesh).
  std::vector<char> taken(static_cast<std::size_t>(split.vertexCount()), 0);
  std::vector<int> addedOriginal;
  std::vector<Vector3> addedPoints;
  for (std::size_t c = 0; c < labels.size(); ++c)
  {
    std::vector<int> globals(toChart[c].size());
    for (std::size_t i = 0; i < globals.size(); ++i)
    {
      const int global = chartVertices[c][static_cast<std::size_t>(toChart[c][i])];
      if (taken[static_cast<std::size_t>(global)])
      {
        globals[i] = split.vertexCount() + static_cast<int>(addedPoints.size());
        addedOriginal.push_back(result.split.originalPoint[static_cast<std::size_t>(global)]);
        addedPoints.push_back(split.point(global));
      }
      else
      {
        taken[static_cast<std::size_t>(global)] = 1;
        globals[i] = global;
      }
    }
    chartVertices[c] = std::move(globals);
  }
  if (!addedPoints.empty())
  {
    std::vector<Vector3> points = split.points();
    points.insert(points.end(), addedPoints.begin(), addedPoints.end());
    std::vector<Triangle> triangles = split.triangles();
    for (std::size_t c = 0; c < labels.size(); ++c)
    {
      for (std::size_t f = 0; f < chartFaces[c].size(); ++f)
      {
        const Triangle& t = charts[c].triangle(static_cast<int>(f));
        for (std::size_t k = 0; k < 3; ++k)
        {
          triangles[static_cast<std::size_t>(chartFaces[c][f])][k] = chartVertices[c][static_cast<std::size_t>(t[k])];
        }
      }
    }
    result.split.originalPoint.insert(result.split.originalPoint.end(), addedOriginal.begin(), addedOriginal.end());
    result.split.mesh = TriangleMesh(std::move(points), std::move(triangles));
  }

  // Flatten, scale each chart to its 3D area, measure, and find its minimal box.
  result.uv.assign(static_cast<std::size_t>(split.vertexCount()), Vector2::Zero());
  result.faces.resize(static_cast<std::size_t>(split.faceCount()));
  result.charts = std::move(summaries);
  std::vector<double> rotations(labels.size());
  std::vector<Vector2> boxSizes(labels.size());
  std::vector<Vector2> boxCorners(labels.size());
  for (std::size_t c = 0; c < labels.size(); ++c)
  {
    const TriangleMesh& chart = charts[c];
    std::vector<Vector2> uv = std::move(chartUV[c]);
    double area3D = 0.0;
    double areaUV = 0.0;
    for (const Triangle& t : chart.triangles())
    {
      area3D += 0.5 * (chart.point(t[1]) - chart.point(t[0])).cross(chart.point(t[2]) - chart.point(t[0])).norm();
      areaUV += signedArea(
        uv[static_cast<std::size_t>(t[0])], uv[static_cast<std::size_t>(t[1])], uv[static_cast<std::size_t>(t[2])]);
    }
    if (!(std::abs(areaUV) > 0.0))
    {
      throw Error("the flattened " + chartName(c) + " has no area");
    }
    // The conformal energy prefers the orientation of the triangles; a mirrored result is turned back.
    const double mirror = areaUV < 0.0 ? -1.0 : 1.0;
    const double scale = std::sqrt(area3D / std::abs(areaUV));
    for (Vector2& p : uv)
    {
      p = Vector2(p.x() * scale, p.y() * scale * mirror);
    }
    ChartSummary& summary = result.charts[c];
    summary.label = labels[c];
    summary.faceCount = chart.faceCount();
    summary.vertexCount = chart.vertexCount();
    for (int f = 0; f < chart.faceCount(); ++f)
    {
      const Triangle& t = chart.triangle(f);
      const FaceDistortion distortion = faceDistortion(chart.point(t[0]), chart.point(t[1]), chart.point(t[2]),
        uv[static_cast<std::size_t>(t[0])], uv[static_cast<std::size_t>(t[1])], uv[static_cast<std::size_t>(t[2])]);
      const double area =
        0.5 * (chart.point(t[1]) - chart.point(t[0])).cross(chart.point(t[2]) - chart.point(t[0])).norm();
      result.faces[static_cast<std::size_t>(chartFaces[c][static_cast<std::size_t>(f)])] = distortion;
      accumulate(summary.distortion, distortion, area);
      accumulate(result.distortion, distortion, area);
    }
    finishSummary(summary.distortion);

    rotations[c] = minimalBoundingBoxRotation(uv);
    summary.rotation = rotations[c];
    const Eigen::Rotation2Dd rotation(rotations[c]);
    Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity());
    Vector2 high = -low;
    for (Vector2& p : uv)
    {
      p = rotation * p;
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    boxSizes[c] = high - low;
    for (std::size_t i = 0; i < uv.size(); ++i)
    {
      result.uv[static_cast<std::size_t>(chartVertices[c][i])] = uv[i] - low;
    }
  }
  finishSummary(result.distortion);

  boxCorners = packBoxes(boxSizes, options.margin, result.texelScale);
  for (std::size_t c = 0; c < labels.size(); ++c)
  {
    for (int v : chartVertices[c])
    {
      Vector2& p = result.uv[static_cast<std::size_t>(v)];
      p = p * result.texelScale + boxCorners[c];
    }
  }
  // Only charts whose packed boxes intersect can overlap: the raster check runs on their
  // triangles alone (none, when the packing kept every box apart).
  std::vector<char> boxOverlaps(labels.size(), 0);
  for (std::size_t a = 0; a < labels.size(); ++a)
  {
    for (std::size_t b = a + 1; b < labels.size(); ++b)
    {
      const Vector2 lowA = boxCorners[a], highA = boxCorners[a] + boxSizes[a] * result.texelScale;
      const Vector2 lowB = boxCorners[b], highB = boxCorners[b] + boxSizes[b] * result.texelScale;
      if (lowA.x() < highB.x() && lowB.x() < highA.x() && lowA.y() < highB.y() && lowB.y() < highA.y())
      {
        boxOverlaps[a] = boxOverlaps[b] = 1;
      }
    }
  }
  std::vector<Triangle> suspects;
  std::vector<int> suspectCharts;
  for (int f = 0; f < split.faceCount(); ++f)
  {
    if (boxOverlaps[static_cast<std::size_t>(faceChart[static_cast<std::size_t>(f)])])
    {
      suspects.push_back(split.triangle(f));
      suspectCharts.push_back(faceChart[static_cast<std::size_t>(f)]);
    }
  }
  result.overlappingChartPairs =
    suspects.empty() ? 0 : countChartOverlaps(result.uv, suspects, suspectCharts, options.overlapResolution);
  return result;
}

} // namespace kerf
