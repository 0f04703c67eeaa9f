// The heat method on the intrinsic Delaunay triangulation, with factorizations sharing one symbolic analysis.
#include "Geodesic/HeatGeodesics.h"

#include "CacheKey.h"
#include "Error.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/IntrinsicTriangulation.h"
#include "Numerics/NestedDissection.h"
#include "Numerics/SerialOpenMP.h"
#include "Surface/Surface.h"

#include <Eigen/SparseCore>

#ifdef KERF_HAVE_CHOLMOD
#include "Numerics/SupernodalFactorization.h"
#include "Numerics/SupernodalSolve.h"

#include <cholmod.h>
#else
#include <Eigen/SparseCholesky>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace kerf
{

namespace
{
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Cholesky factorizations of several symmetric positive-definite matrices with one sparsity
/// pattern: the ordering and symbolic analysis are computed once, then each matrix is factored
/// numerically into its own copy of the symbolic factor.
class SharedPatternCholesky
{
public:
  /// `points`: one per row, for the geometric ordering.
  SharedPatternCholesky(
    const SparseMatrix& lowerPattern, CholeskyOrdering ordering, int count, const std::vector<Vector3>& points)
  {
#ifdef KERF_HAVE_CHOLMOD
    startCholmod(&this->Common);
    if (ordering == CholeskyOrdering::Automatic)
    {
      ordering = lowerPattern.rows() >= GeometricOrderingRows ? CholeskyOrdering::Geometric : CholeskyOrdering::AMD;
    }
    this->Common.nmethods = 1;
    this->Common.method[0].ordering = ordering == CholeskyOrdering::METIS ? CHOLMOD_METIS
      : ordering == CholeskyOrdering::Geometric                           ? CHOLMOD_GIVEN
                                                                          : CHOLMOD_AMD;
    this->Common.postorder = 1;
    cholmod_sparse view = cholmodView(lowerPattern, -1);
    std::vector<int> given;
    if (ordering == CholeskyOrdering::Geometric)
    {
      given = geometricNestedDissection(points, lowerPattern);
    }
    const CholmodAllocatorScope allocator; // the analysis's workspace
    cholmod_factor* symbolic = given.empty() ? cholmod_analyze(&view, &this->Common)
                                             : cholmod_analyze_p(&view, given.data(), nullptr, 0, &this->Common);
    if (!symbolic || this->Common.status < CHOLMOD_OK)
    {
      if (symbolic)
      {
        cholmod_free_factor(&symbolic, &this->Common);
      }
      cholmod_finish(&this->Common);
      throw Error("the sparse Cholesky analysis of the heat-method matrices failed");
    }
    this->Factors.push_back(symbolic);
    for (int i = 1; i < count; ++i)
    {
      this->Factors.push_back(cholmod_copy_factor(symbolic, &this->Common));
    }
#else
    (void)lowerPattern;
    (void)ordering;
    (void)points;
    for (int i = 0; i < count; ++i)
    {
      this->Factors.push_back(std::make_unique<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>());
    }
#endif
  }

  ~SharedPatternCholesky()
  {
#ifdef KERF_HAVE_CHOLMOD
    for (cholmod_factor*& factor : this->Factors)
    {
      cholmod_free_factor(&factor, &this->Common);
    }
    cholmod_finish(&this->Common);
#endif
  }
  SharedPatternCholesky(const SharedPatternCholesky&) = delete;
  SharedPatternCholesky& operator=(const SharedPatternCholesky&) = delete;

  /// Factors matrix `index` (lower triangle, the pattern given at construction).
  void factor(int index, const SparseMatrix& lower)
  {
#ifdef KERF_HAVE_CHOLMOD
    cholmod_sparse view = cholmodView(lower, -1);
    cholmod_factor* factor = this->Factors[index];
    bool factored = false;
    {
      const SerialOpenMP serial;
      factored = factorizeSupernodal(&view, factor, &this->Common);
    }
    if (!factored || this->Common.status != CHOLMOD_OK || factor->minor < factor->n)
    {
      throw Error("the heat-method matrices could not be factored (not positive definite)");
    }
#else
    this->Factors[index]->compute(lower.selfadjointView<Eigen::Lower>());
    if (this->Factors[index]->info() != Eigen::Success)
    {
      throw Error("the heat-method matrices could not be factored (not positive definite)");
    }
#endif
  }

  Eigen::VectorXd solve(int index, Eigen::VectorXd b) const
  {
#ifdef KERF_HAVE_CHOLMOD
    if (SupernodalSolve::supports(*this->Factors[index]))
    {
      Eigen::VectorXd x(b.size());
      SupernodalSolve::solve(*this->Factors[index], b.data(), x.data(), this->Work);
      return x;
    }
    cholmod_dense right;
    right.nrow = static_cast<size_t>(b.size());
    right.ncol = 1;
    right.nzmax = right.nrow;
    right.d = right.nrow;
    right.x = b.data();
    right.z = nullptr;
    right.xtype = CHOLMOD_REAL;
    right.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, this->Factors[index], &right, &this->Common);
    if (!x)
    {
      throw Error("the heat-method solve failed");
    }
    Eigen::VectorXd result = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
    cholmod_free_dense(&x, &this->Common);
    return result;
#else
    return this->Factors[index]->solve(b);
#endif
  }

private:
#ifdef KERF_HAVE_CHOLMOD
  mutable cholmod_common Common;
  std::vector<cholmod_factor*> Factors;
  mutable std::vector<double> Work; // SupernodalSolve's workspace
#else
  std::vector<std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>> Factors; // not movable
#endif
};

enum Matrix
{
  HeatNeumann = 0,
  Poisson = 1,
  HeatDirichlet = 2
};
} // namespace

struct HeatGeodesics::Implementation
{
  int flips = 0;
  double timeStep = 0.0;
  bool dirichlet = false; // a Dirichlet heat matrix was factored
  // Per intrinsic triangle: corners, corner gradients of the hat functions and cotangents.
  std::vector<Triangle> corners;
  std::vector<std::array<Eigen::Vector2d, 3>> hatGradients;
  std::vector<std::array<Eigen::Vector2d, 3>> layouts;
  std::vector<std::array<double, 3>> cotangents;
  std::vector<double> mass;
  std::vector<char> boundary;
  std::vector<int> component; // per vertex, -1 if unused
  int componentCount = 0;
  std::unique_ptr<SharedPatternCholesky> cholesky;
};

std::string cacheKey(const HeatGeodesicOptions& options)
{
  static const char* const boundaries[] = { "neumann", "dirichlet", "mean" };
  static const char* const orderings[] = { "automatic", "amd", "metis", "geometric" };
  return "t=" + cacheKey(options.timeFactor) + " boundary=" + boundaries[static_cast<int>(options.boundary)] +
    " ordering=" + orderings[static_cast<int>(options.ordering)];
}

HeatGeodesics::HeatGeodesics(const TriangleMesh& mesh, const HeatGeodesicOptions& options)
  : Mesh(mesh)
  , Options(options)
  , Impl(std::make_unique<Implementation>())
{
  if (mesh.empty())
  {
    throw Error("the heat method needs a mesh with at least one triangle");
  }
  if (!std::isfinite(options.timeFactor) || options.timeFactor <= 0.0)
  {
    throw Error("the heat method's time factor must be positive and finite");
  }
  Implementation& m = *this->Impl;
  const int n = mesh.vertexCount();

  IntrinsicTriangulation triangulation(mesh);
  m.flips = triangulation.flipToDelaunay();
  m.corners = triangulation.triangles();
  const int faces = triangulation.faceCount();
  m.hatGradients.resize(faces);
  m.layouts.resize(faces);
  m.cotangents.resize(faces);
  for (int f = 0; f < faces; ++f)
  {
    m.layouts[f] = triangulation.layout(f);
    const double twiceArea = 2.0 * triangulation.area(f);
    for (int k = 0; k < 3; ++k)
    {
      m.cotangents[f][k] = triangulation.cotangent(f, k);
      // grad phi_k = rot90(p_{k+2} - p_{k+1}) / 2A, counter-clockwise layout.
      const Eigen::Vector2d e = m.layouts[f][(k + 2) % 3] - m.layouts[f][(k + 1) % 3];
      m.hatGradients[f][k] =
        twiceArea > 0.0 ? Eigen::Vector2d(Eigen::Vector2d(-e.y(), e.x()) / twiceArea) : Eigen::Vector2d::Zero();
    }
  }
  m.mass = triangulation.vertexAreas();

  double edgeLength = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    edgeLength += (mesh.point(ev[1]) - mesh.point(ev[0])).norm();
  }
  edgeLength /= std::max(mesh.edgeCount(), 1);
  m.timeStep = options.timeFactor * edgeLength * edgeLength;

  m.boundary.assign(n, 0);
  m.component.assign(n, -1);
  for (int v = 0; v < n; ++v)
  {
    m.boundary[v] = mesh.isBoundaryVertex(v) ? 1 : 0;
    m.component[v] = mesh.vertexComponent(v);
  }
  m.componentCount = mesh.componentCount();
  m.dirichlet = options.boundary != HeatBoundaryCondition::Neumann &&
    std::any_of(m.boundary.begin(), m.boundary.end(), [](char b) { return b != 0; });

  // The lower triangle of L (diagonal included) in compressed columns; the three matrices are
  // this pattern with other values.
  // Straight from the halfedges (setFromTriplets sums edges that join the same pair): no sort.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * static_cast<std::size_t>(faces) / 2 + static_cast<std::size_t>(n));
  std::vector<double> diagonal(n, 0.0);
  for (int f = 0; f < faces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int h = 3 * f + k, t = triangulation.twin(h);
      if (t >= 0 && t < h)
      {
        continue; // counted from the other side
      }
      const int i = m.corners[f][k], j = m.corners[f][(k + 1) % 3];
      if (i == j)
      {
        continue;
      }
      double weight = 0.5 * m.cotangents[f][(k + 2) % 3];
      if (t >= 0)
      {
        weight += 0.5 * m.cotangents[t / 3][(t % 3 + 2) % 3];
      }
      weight = std::max(weight, 0.0);
      entries.emplace_back(std::max(i, j), std::min(i, j), -weight);
      diagonal[i] += weight;
      diagonal[j] += weight;
    }
  }
  double diagonalSum = 0.0;
  int used = 0;
  for (int v = 0; v < n; ++v)
  {
    entries.emplace_back(v, v, diagonal[v]);
    if (m.component[v] >= 0)
    {
      diagonalSum += diagonal[v];
      ++used;
    }
  }
  const double meanDiagonal = used > 0 && diagonalSum > 0.0 ? diagonalSum / used : 1.0;
  SparseMatrix laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  laplacian.makeCompressed();

  m.cholesky = std::make_unique<SharedPatternCholesky>(laplacian, options.ordering, m.dirichlet ? 3 : 2, mesh.points());

  std::vector<char> pinned(m.componentCount, 0);
  SparseMatrix heat = laplacian;
  SparseMatrix poisson = laplacian;
  for (int column = 0; column < n; ++column)
  {
    for (SparseMatrix::InnerIterator it(heat, column); it; ++it)
    {
      it.valueRef() *= m.timeStep;
      if (it.row() == column)
      {
        it.valueRef() += m.mass[column];
        if (m.component[column] < 0)
        {
          it.valueRef() = 1.0; // a vertex used by no triangle
        }
      }
    }
    for (SparseMatrix::InnerIterator it(poisson, column); it; ++it)
    {
      if (it.row() == column)
      {
        const int c = m.component[column];
        if (c < 0)
        {
          it.valueRef() = 1.0;
        }
        else if (!pinned[c])
        {
          // Fixes the component's constant (lowest vertex) without changing the pattern.
          pinned[c] = 1;
          it.valueRef() += meanDiagonal;
        }
      }
    }
  }
  m.cholesky->factor(HeatNeumann, heat);
  m.cholesky->factor(Poisson, poisson);
  if (m.dirichlet)
  {
    // u = 0 on the boundary: its rows and columns become the identity (explicit zeros keep the
    // pattern).
    for (int column = 0; column < n; ++column)
    {
      for (SparseMatrix::InnerIterator it(heat, column); it; ++it)
      {
        if (m.boundary[column] || m.boundary[it.row()])
        {
          it.valueRef() = it.row() == column ? 1.0 : 0.0;
        }
      }
    }
    m.cholesky->factor(HeatDirichlet, heat);
  }
}

HeatGeodesics::~HeatGeodesics() = default;
HeatGeodesics::HeatGeodesics(HeatGeodesics&&) noexcept = default;

const HeatGeodesics& HeatGeodesics::of(const Surface& surface, const HeatGeodesicOptions& options)
{
  return *surface.derived<std::shared_ptr<const HeatGeodesics>>("heat-geodesics:" + cacheKey(options),
    [&surface, &options] { return std::make_shared<const HeatGeodesics>(surface.mesh(), options); });
}

double HeatGeodesics::timeStep() const
{
  return this->Impl->timeStep;
}

int HeatGeodesics::flips() const
{
  return this->Impl->flips;
}

namespace
{
// Adds weight * (the hat functions' values at the barycentric point) to u.
void deposit(Eigen::VectorXd& u, const Triangle& t, const Vector3& barycentric, double weight)
{
  for (int k = 0; k < 3; ++k)
  {
    u[t[k]] += weight * barycentric[k];
  }
}

// Calls visit(face, barycentric, weight) for the source's sample points: vertices and points
// with weight 1, curve segments at both ends with half their length each (the trapezoid rule,
// exact for the hat functions, which are linear along a segment).
template <typename Visit>
void forEachSourceSample(const TriangleMesh& mesh, const GeodesicSource& source, Visit visit)
{
  for (int v : source.vertices)
  {
    const SurfacePoint p = vertexSurfacePoint(mesh, v);
    visit(p.face, p.barycentric, 1.0);
  }
  for (const SurfacePoint& p : source.points)
  {
    visit(p.face, p.barycentric, 1.0);
  }
  for (const SurfaceCurve& curve : source.curves)
  {
    const int segments = segmentCount(curve);
    for (int i = 0; i < segments; ++i)
    {
      const int f = curve.faces[i];
      const Vector3& a = curve.points[i];
      const Vector3& b = curve.points[(i + 1) % curve.points.size()];
      const double half = 0.5 * (b - a).norm();
      visit(f, barycentricInFace(mesh, f, a), half);
      visit(f, barycentricInFace(mesh, f, b), half);
    }
  }
}
// Distance from a point to the segment [a, b].
double segmentDistance(const Vector3& p, const Vector3& a, const Vector3& b)
{
  const Vector3 d = b - a;
  const double squared = d.squaredNorm();
  const double s = squared > 0.0 ? std::clamp((p - a).dot(d) / squared, 0.0, 1.0) : 0.0;
  return (p - (a + s * d)).norm();
}

// The length of the straight path from s across the edge (a, b) to w, with s and w laid out
// on either side of the edge by their distances to a and b; +infinity if the straight segment
// misses the edge (the shortest path then bends at a or b).
double unfoldedDistance(double ab, double sa, double sb, double wa, double wb)
{
  if (!(ab > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  const auto place = [ab](double fromA, double fromB, double side) {
    const double x = (ab * ab + fromA * fromA - fromB * fromB) / (2.0 * ab);
    return Eigen::Vector2d(x, side * std::sqrt(std::max(fromA * fromA - x * x, 0.0)));
  };
  const Eigen::Vector2d s = place(sa, sb, 1.0);
  const Eigen::Vector2d w = place(wa, wb, -1.0);
  const double height = s.y() - w.y();
  const double crossing = height > 0.0 ? s.x() + s.y() / height * (w.x() - s.x()) : s.x();
  const double slack = 1e-9 * ab;
  if (crossing < -slack || crossing > ab + slack)
  {
    return std::numeric_limits<double>::infinity();
  }
  return (s - w).norm();
}

// Vertices around a source with a distance measured directly: `exact` ones are the corners of the
// triangles holding the source, the neighbours of a source vertex, and vertices one triangle
// beyond that a straight path reaches across one edge (distances by unfolding, exact on the
// polyhedron); the others are the remaining neighbours of the corners, at their Euclidean
// distance to the source (exact to second order), used only to fix the constant.
struct NearSourceDistances
{
  std::vector<int> vertices;
  std::vector<double> distances;
  std::vector<char> exact;
  std::vector<char> atSource; // a source vertex or corner (excluded from the constant's fit)
};

NearSourceDistances nearSourceDistances(const TriangleMesh& mesh, const GeodesicSource& source)
{
  std::vector<int> slot(mesh.vertexCount(), -1);
  NearSourceDistances near;
  auto offer = [&](int v, double distance, bool exact) {
    if (slot[v] < 0)
    {
      slot[v] = static_cast<int>(near.vertices.size());
      near.vertices.push_back(v);
      near.distances.push_back(distance);
      near.exact.push_back(exact ? 1 : 0);
      near.atSource.push_back(0);
      return;
    }
    const int i = slot[v];
    if (exact && !near.exact[i])
    {
      near.distances[i] = distance;
      near.exact[i] = 1;
    }
    else if (exact == (near.exact[i] != 0))
    {
      near.distances[i] = std::min(near.distances[i], distance);
    }
  };
  const auto length = [&mesh](int a, int b) { return (mesh.point(a) - mesh.point(b)).norm(); };
  // Offers the vertex across each edge (a, b) of `face` (a source triangle) by unfolding, with
  // sa, sb the source's distances to a and b.
  auto offerAcross = [&](int face, const std::array<double, 3>& cornerDistances) {
    const Triangle& t = mesh.triangle(face);
    for (int k = 0; k < 3; ++k)
    {
      const int g = mesh.faceNeighbor(face, k);
      if (g < 0)
      {
        continue;
      }
      const int a = t[k], b = t[(k + 1) % 3];
      for (int w : mesh.triangle(g))
      {
        if (w != a && w != b)
        {
          const double d = unfoldedDistance(
            length(a, b), cornerDistances[k], cornerDistances[(k + 1) % 3], length(w, a), length(w, b));
          if (std::isfinite(d))
          {
            offer(w, d, true);
          }
        }
      }
    }
  };
  for (int v : source.vertices)
  {
    offer(v, 0.0, true);
    near.atSource[slot[v]] = 1;
    for (int w : mesh.vertexNeighbors(v))
    {
      offer(w, length(v, w), true);
    }
    for (int f : mesh.vertexFaces(v))
    {
      // The edge of f opposite v: k such that v is corner k + 2.
      const Triangle& t = mesh.triangle(f);
      std::array<double, 3> distances;
      for (int k = 0; k < 3; ++k)
      {
        distances[k] = length(v, t[k]);
      }
      for (int k = 0; k < 3; ++k)
      {
        if (t[(k + 2) % 3] != v)
        {
          continue;
        }
        const int g = mesh.faceNeighbor(f, k);
        if (g < 0)
        {
          continue;
        }
        const int a = t[k], b = t[(k + 1) % 3];
        for (int w : mesh.triangle(g))
        {
          if (w != a && w != b && w != v)
          {
            const double d =
              unfoldedDistance(length(a, b), distances[k], distances[(k + 1) % 3], length(w, a), length(w, b));
            if (std::isfinite(d))
            {
              offer(w, d, true);
            }
          }
        }
      }
    }
  }
  for (const SurfacePoint& point : source.points)
  {
    const Vector3 p = surfacePosition(mesh, point);
    const Triangle& t = mesh.triangle(point.face);
    std::array<double, 3> distances;
    for (int k = 0; k < 3; ++k)
    {
      distances[k] = (mesh.point(t[k]) - p).norm();
      offer(t[k], distances[k], true);
      near.atSource[slot[t[k]]] = 1;
    }
    offerAcross(point.face, distances);
    for (int c : t)
    {
      for (int w : mesh.vertexNeighbors(c))
      {
        offer(w, (mesh.point(w) - p).norm(), false);
      }
    }
  }
  for (const SurfaceCurve& curve : source.curves)
  {
    const int segments = segmentCount(curve);
    for (int i = 0; i < segments; ++i)
    {
      const Vector3& a = curve.points[i];
      const Vector3& b = curve.points[(i + 1) % curve.points.size()];
      for (int c : mesh.triangle(curve.faces[i]))
      {
        offer(c, segmentDistance(mesh.point(c), a, b), true);
        for (int w : mesh.vertexNeighbors(c))
        {
          offer(w, segmentDistance(mesh.point(w), a, b), false);
        }
      }
    }
  }
  return near;
}
} // namespace

GeodesicDistance HeatGeodesics::compute(const GeodesicSource& source) const
{
  const TriangleMesh& mesh = this->Mesh;
  checkGeodesicSource(mesh, source);
  const Implementation& m = *this->Impl;
  const int n = mesh.vertexCount();

  // Step I: heat flow from the source (Crane et al. 2013, Algorithm 1).
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(n);
  std::vector<char> sourceComponent(m.componentCount, 0);
  forEachSourceSample(mesh, source, [&](int f, const Vector3& barycentric, double weight) {
    // Curves of zero length still mark their point.
    deposit(u0, mesh.triangle(f), barycentric, weight > 0.0 ? weight : 1e-300);
    sourceComponent[mesh.faceComponent(f)] = 1;
  });
  Eigen::VectorXd u = m.cholesky->solve(HeatNeumann, u0);
  if (m.dirichlet)
  {
    Eigen::VectorXd interior = u0;
    for (int v = 0; v < n; ++v)
    {
      if (m.boundary[v])
      {
        interior[v] = 0.0;
      }
    }
    const Eigen::VectorXd uD = m.cholesky->solve(HeatDirichlet, interior);
    u = this->Options.boundary == HeatBoundaryCondition::Dirichlet ? uD : Eigen::VectorXd(0.5 * (u + uD));
  }

  // Steps II and III: X = -grad u / |grad u| per triangle, and b = -div X.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t f = 0; f < m.corners.size(); ++f)
  {
    const Triangle& t = m.corners[f];
    const Eigen::Vector2d gradient =
      u[t[0]] * m.hatGradients[f][0] + u[t[1]] * m.hatGradients[f][1] + u[t[2]] * m.hatGradients[f][2];
    const double norm = gradient.norm();
    if (!(norm > 0.0))
    {
      continue;
    }
    const Eigen::Vector2d X = -gradient / norm;
    for (int k = 0; k < 3; ++k)
    {
      const int j = (k + 1) % 3, l = (k + 2) % 3;
      // div X at corner k: (cot theta_l (e_kj . X) + cot theta_j (e_kl . X)) / 2.
      const double divergence = 0.5 *
        (m.cotangents[f][l] * (m.layouts[f][j] - m.layouts[f][k]).dot(X) +
          m.cotangents[f][j] * (m.layouts[f][l] - m.layouts[f][k]).dot(X));
      rhs[t[k]] -= divergence;
    }
  }
  // Compatibility per component: remove the area-weighted mean.
  std::vector<double> sum(m.componentCount, 0.0), area(m.componentCount, 0.0);
  for (int v = 0; v < n; ++v)
  {
    if (m.component[v] >= 0)
    {
      sum[m.component[v]] += rhs[v];
      area[m.component[v]] += m.mass[v];
    }
  }
  for (int v = 0; v < n; ++v)
  {
    const int c = m.component[v];
    if (c >= 0 && area[c] > 0.0)
    {
      rhs[v] -= sum[c] / area[c] * m.mass[v];
    }
  }
  const Eigen::VectorXd phi = m.cholesky->solve(Poisson, rhs);

  // phi is fixed up to a constant per component. At a point source the Poisson solution has a
  // defect of about 0.13 h (it underestimates the source's own value), so the constant is
  // fitted on the vertices around the source, whose distance is measured directly, and the
  // vertices whose distance is exact get it.
  const NearSourceDistances near = nearSourceDistances(mesh, source);
  // Per component: [0] over the vertices near the source, [1] with the source vertices too (for
  // meshes where nothing else is near).
  std::vector<std::array<double, 2>> offset(m.componentCount, { 0.0, 0.0 }), count(m.componentCount, { 0.0, 0.0 });
  for (std::size_t i = 0; i < near.vertices.size(); ++i)
  {
    const int c = m.component[near.vertices[i]];
    const double difference = phi[near.vertices[i]] - near.distances[i];
    for (int k = near.atSource[i] ? 1 : 0; k < 2; ++k)
    {
      offset[c][k] += difference;
      count[c][k] += 1.0;
    }
  }
  GeodesicDistance result;
  result.distance.assign(n, std::numeric_limits<double>::infinity());
  for (int v = 0; v < n; ++v)
  {
    const int c = m.component[v];
    if (c >= 0 && sourceComponent[c])
    {
      const int k = count[c][0] > 0.0 ? 0 : 1;
      result.distance[v] = std::max(phi[v] - offset[c][k] / count[c][k], 0.0);
    }
  }
  for (std::size_t i = 0; i < near.vertices.size(); ++i)
  {
    if (near.exact[i])
    {
      result.distance[near.vertices[i]] = near.distances[i];
    }
  }
  result.faceGradients.assign(mesh.faceCount(), Vector3::Zero());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (sourceComponent[mesh.faceComponent(f)])
    {
      result.faceGradients[f] = faceGradient(mesh, result.distance, f);
    }
  }
  return result;
}

} // namespace kerf
