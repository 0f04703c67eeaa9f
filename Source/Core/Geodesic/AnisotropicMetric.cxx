// Per-vertex metric tensors aligned with the principal curvature directions (Zhuang et al. 2014).
#include "Geodesic/AnisotropicMetric.h"

#include "Error.h"

#include <algorithm>
#include <cmath>

namespace kerf
{

double anisotropyLambda(double larger, double smaller, const AnisotropicMetricOptions& options, double regularization)
{
  const double difference = std::abs(larger) - std::abs(smaller);
  double measure = difference;
  if (options.measure == AnisotropyMeasure::Normalized)
  {
    const double denominator = std::abs(larger) + std::abs(smaller) + regularization;
    measure = denominator > 0.0 ? difference / denominator : 0.0;
  }
  const double lambda = 1.0 + options.gamma * measure;
  if (!(lambda > 0.0) || !std::isfinite(lambda))
  {
    throw Error("the anisotropic metric's lambda1 = 1 + gamma * (|k1| - |k2|) must be positive and finite");
  }
  return lambda;
}

Eigen::Matrix3d AnisotropicMetric::tensorAt(const TriangleMesh& mesh, int face, const Vector3& barycentric) const
{
  if (this->isotropic)
  {
    return Eigen::Matrix3d::Identity();
  }
  const Triangle& t = mesh.triangle(face);
  return barycentric[0] * this->tensors[t[0]] + barycentric[1] * this->tensors[t[1]] +
    barycentric[2] * this->tensors[t[2]];
}

double AnisotropicMetric::length(const Vector3& v, int a, int b) const
{
  if (this->isotropic)
  {
    return v.norm();
  }
  const double squared = 0.5 * (v.dot(this->tensors[a] * v) + v.dot(this->tensors[b] * v));
  return std::sqrt(std::max(squared, 0.0));
}

AnisotropicMetric computeAnisotropicMetric(
  const TriangleMesh& mesh, const SurfaceDescriptors& descriptors, const AnisotropicMetricOptions& options)
{
  if (!std::isfinite(options.gamma) || options.gamma < 0.0)
  {
    throw Error("the anisotropy gamma must be finite and >= 0");
  }
  if (!std::isfinite(options.umbilicRegularization) || options.umbilicRegularization < 0.0)
  {
    throw Error("the anisotropic metric's umbilic regularization must be finite and >= 0");
  }
  const int n = mesh.vertexCount();
  if (static_cast<int>(descriptors.maximumCurvature.size()) != n || static_cast<int>(descriptors.normals.size()) != n)
  {
    throw Error("the surface descriptors do not belong to this mesh (wrong number of vertices)");
  }
  AnisotropicMetric metric;
  metric.tensors.assign(n, Eigen::Matrix3d::Identity());
  metric.inverses.assign(n, Eigen::Matrix3d::Identity());
  metric.lambda1.assign(n, 1.0);
  metric.isotropic = options.gamma == 0.0;
  if (metric.isotropic)
  {
    return metric;
  }
  metric.normals = descriptors.normals;
  double squaredCurvature = 0.0;
  int used = 0;
  for (int v = 0; v < n; ++v)
  {
    if (!mesh.vertexFaces(v).empty())
    {
      const double k1 = descriptors.maximumCurvature[v], k2 = descriptors.minimumCurvature[v];
      squaredCurvature += k1 * k1 + k2 * k2;
      ++used;
    }
  }
  const double regularization = used > 0 ? options.umbilicRegularization * std::sqrt(squaredCurvature / used) : 0.0;
  for (int v = 0; v < n; ++v)
  {
    const Vector3& normal = descriptors.normals[v];
    if (mesh.vertexFaces(v).empty() || normal.squaredNorm() == 0.0)
    {
      continue;
    }
    double larger = descriptors.maximumCurvature[v];
    double smaller = descriptors.minimumCurvature[v];
    Vector3 e1 = descriptors.maximumDirections[v];
    Vector3 e2 = descriptors.minimumDirections[v];
    if (std::abs(smaller) > std::abs(larger))
    {
      std::swap(larger, smaller);
      std::swap(e1, e2);
    }
    const double lambda1 = anisotropyLambda(larger, smaller, options, regularization);
    const double lambda2 = 1.0 / lambda1;
    // ROI Scissor, Eq. 4, with the normal as a third eigenvector of eigenvalue 1.
    metric.tensors[v] = lambda1 * e1 * e1.transpose() + lambda2 * e2 * e2.transpose() + normal * normal.transpose();
    metric.inverses[v] = lambda2 * e1 * e1.transpose() + lambda1 * e2 * e2.transpose() + normal * normal.transpose();
    metric.lambda1[v] = lambda1;
  }
  return metric;
}

} // namespace kerf
