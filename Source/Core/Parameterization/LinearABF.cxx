// linearAngleBasedAngles: the linearised ABF problem in closed form, the per-triangle constraints eliminated first.
#include "Parameterization/LinearABF.h"

#include "Error.h"
#include "Numerics/SparseCholesky.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <cmath>
#include <string>

namespace kerf
{
namespace
{
// The largest miss of an interior vertex's angle sum (2 pi) that counts as round-off.
constexpr double VertexSumTolerance = 1e-6;

// The rows of the vertex and wheel constraints one triangle takes part in: for each corner at an
// interior vertex j, its angle sum (row 2 j) and its wheel condition (row 2 j + 1), with their
// coefficients on the triangle's three corners.
struct TriangleRows
{
  int count = 0;
  std::array<int, 6> row{};
  std::array<Eigen::Vector3d, 6> coefficient;
};

TriangleRows triangleRows(const Triangle& t, const std::vector<int>& interior, const double* cotangent)
{
  TriangleRows rows;
  for (int k = 0; k < 3; ++k)
  {
    const int j = interior[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
    if (j < 0)
    {
      continue;
    }
    const int next = (k + 1) % 3;
    const int previous = (k + 2) % 3;
    rows.row[static_cast<std::size_t>(rows.count)] = 2 * j;
    rows.coefficient[static_cast<std::size_t>(rows.count)] = Eigen::Vector3d::Unit(k);
    ++rows.count;
    // The wheel condition around j: prod sin(alpha_next) = prod sin(alpha_previous), linearised
    // (Zayer, Lévy and Seidel 2007): sum cot(beta_next) e_next - sum cot(beta_previous) e_previous.
    Eigen::Vector3d wheel = Eigen::Vector3d::Zero();
    wheel[next] = cotangent[next];
    wheel[previous] = -cotangent[previous];
    rows.row[static_cast<std::size_t>(rows.count)] = 2 * j + 1;
    rows.coefficient[static_cast<std::size_t>(rows.count)] = wheel;
    ++rows.count;
  }
  return rows;
}
} // namespace

LinearABFAngles linearAngleBasedAngles(const TriangleMesh& chart)
{
  if (chart.empty())
  {
    throw Error("the chart has no triangle");
  }
  const int faces = chart.faceCount();
  const int n = chart.vertexCount();
  LinearABFAngles result;
  std::vector<double>& beta = result.targets;
  beta.resize(3 * static_cast<std::size_t>(faces));
  std::vector<double> vertexSum(static_cast<std::size_t>(n), 0.0);
  for (int f = 0; f < faces; ++f)
  {
    const Triangle& t = chart.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      const Vector3& p = chart.point(t[static_cast<std::size_t>(k)]);
      const Vector3 a = chart.point(t[static_cast<std::size_t>((k + 1) % 3)]) - p;
      const Vector3 b = chart.point(t[static_cast<std::size_t>((k + 2) % 3)]) - p;
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      if (!(angle > 0.0))
      {
        throw Error("triangle " + std::to_string(f) + " of the chart has a zero angle (zero area)");
      }
      beta[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)] = angle;
      vertexSum[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] += angle;
    }
  }
  std::vector<int> interior(static_cast<std::size_t>(n), -1);
  int interiorCount = 0;
  for (int v = 0; v < n; ++v)
  {
    if (!chart.isBoundaryVertex(v) && !chart.vertexFaces(v).empty())
    {
      interior[static_cast<std::size_t>(v)] = interiorCount++;
    }
  }
  result.interiorVertices = interiorCount;
  // ABF's optimal angles: an interior vertex's 3D angles scaled to sum 2 pi (Sheffer and de Sturler 2001).
  for (int f = 0; f < faces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int v = chart.triangle(f)[static_cast<std::size_t>(k)];
      if (interior[static_cast<std::size_t>(v)] >= 0)
      {
        beta[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)] *=
          2.0 * M_PI / vertexSum[static_cast<std::size_t>(v)];
      }
    }
  }
  // W^-1 = diag(beta^2) (ABF's weights 1 / beta^2), cot(beta) and log sin(beta) per corner.
  std::vector<double> inverseWeight(beta.size()), cotangent(beta.size()), logSine(beta.size());
  for (std::size_t c = 0; c < beta.size(); ++c)
  {
    inverseWeight[c] = beta[c] * beta[c];
    cotangent[c] = 1.0 / std::tan(beta[c]);
    logSine[c] = std::log(std::sin(beta[c]));
  }

  // Right-hand side of the vertex and wheel rows: 2 pi minus the angle sum, and the wheel's
  // sum log sin(beta_previous) - sum log sin(beta_next).
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * interiorCount);
  for (int f = 0; f < faces; ++f)
  {
    const Triangle& t = chart.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      const int j = interior[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      if (j >= 0)
      {
        const std::size_t c = 3 * static_cast<std::size_t>(f);
        rhs[2 * j] -= beta[c + static_cast<std::size_t>(k)];
        rhs[2 * j + 1] +=
          logSine[c + static_cast<std::size_t>((k + 2) % 3)] - logSine[c + static_cast<std::size_t>((k + 1) % 3)];
      }
    }
  }
  for (int j = 0; j < interiorCount; ++j)
  {
    rhs[2 * j] += 2.0 * M_PI;
  }

  // The triangle constraints (sum of a triangle's e = pi - sum of its beta) are block diagonal:
  // eliminated, they leave S = sum over triangles of G P G^T with G the triangle's vertex and
  // wheel rows and P = W^-1 - W^-1 1 1^T W^-1 / (1^T W^-1 1) its 3 x 3 projection (Sheffer et al.
  // 2005 reduce ABF++'s Newton steps the same way).
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(faces) * 21);
  std::vector<Eigen::Matrix3d> projection(static_cast<std::size_t>(faces));
  std::vector<Eigen::Vector3d> particular(static_cast<std::size_t>(faces)); // W^-1 1 r_f / (1^T W^-1 1)
  for (int f = 0; f < faces; ++f)
  {
    const std::size_t c = 3 * static_cast<std::size_t>(f);
    const Eigen::Vector3d w(inverseWeight[c], inverseWeight[c + 1], inverseWeight[c + 2]);
    const double total = w.sum();
    Eigen::Matrix3d& P = projection[static_cast<std::size_t>(f)];
    P = Eigen::Matrix3d(w.asDiagonal()) - w * w.transpose() / total;
    particular[static_cast<std::size_t>(f)] = w * ((M_PI - beta[c] - beta[c + 1] - beta[c + 2]) / total);
    const TriangleRows rows = triangleRows(chart.triangle(f), interior, cotangent.data() + c);
    for (int a = 0; a < rows.count; ++a)
    {
      const Eigen::Vector3d Pg = P * rows.coefficient[static_cast<std::size_t>(a)];
      rhs[rows.row[static_cast<std::size_t>(a)]] -=
        rows.coefficient[static_cast<std::size_t>(a)].dot(particular[static_cast<std::size_t>(f)]);
      for (int b = 0; b < rows.count; ++b)
      {
        if (rows.row[static_cast<std::size_t>(a)] >= rows.row[static_cast<std::size_t>(b)])
        {
          triplets.emplace_back(rows.row[static_cast<std::size_t>(a)], rows.row[static_cast<std::size_t>(b)],
            Pg.dot(rows.coefficient[static_cast<std::size_t>(b)]));
        }
      }
    }
  }
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2 * interiorCount);
  if (interiorCount > 0)
  {
    Eigen::SparseMatrix<double> lower(2 * interiorCount, 2 * interiorCount);
    lower.setFromTriplets(triplets.begin(), triplets.end());
    triplets = {};
    // CHOLMOD rather than Eigen's SimplicialLDLT: faster at every size measured (the figures are in
    // Documentation/filters/ChartParameterization.md).
    SparseCholesky cholesky;
    if (!cholesky.factor(lower))
    {
      throw Error("the angle system of the chart is not positive definite");
    }
    lambda = cholesky.solve(rhs);
  }

  // e = W^-1 C^T lambda, per triangle: its particular part plus P G^T lambda.
  result.angles.resize(beta.size());
  std::vector<double> angleSum(static_cast<std::size_t>(n), 0.0);
  for (int f = 0; f < faces; ++f)
  {
    const std::size_t c = 3 * static_cast<std::size_t>(f);
    const TriangleRows rows = triangleRows(chart.triangle(f), interior, cotangent.data() + c);
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (int a = 0; a < rows.count; ++a)
    {
      y += lambda[rows.row[static_cast<std::size_t>(a)]] * rows.coefficient[static_cast<std::size_t>(a)];
    }
    const Eigen::Vector3d e = particular[static_cast<std::size_t>(f)] + projection[static_cast<std::size_t>(f)] * y;
    for (int k = 0; k < 3; ++k)
    {
      result.angles[c + static_cast<std::size_t>(k)] = beta[c + static_cast<std::size_t>(k)] + e[k];
      angleSum[static_cast<std::size_t>(chart.triangle(f)[static_cast<std::size_t>(k)])] +=
        result.angles[c + static_cast<std::size_t>(k)];
    }
  }
  // A rank-deficient C (a closed chart has dependent vertex and triangle sums) leaves a singular
  // system whose solution misses the constraints.
  for (int v = 0; v < n; ++v)
  {
    if (interior[static_cast<std::size_t>(v)] >= 0 &&
      !(std::abs(angleSum[static_cast<std::size_t>(v)] - 2.0 * M_PI) < VertexSumTolerance))
    {
      throw Error("the angle system of the chart is singular: vertex " + std::to_string(v) + "'s angles sum to " +
        std::to_string(angleSum[static_cast<std::size_t>(v)]) + " instead of 2 pi (is the chart a disk?)");
    }
  }
  return result;
}

} // namespace kerf
