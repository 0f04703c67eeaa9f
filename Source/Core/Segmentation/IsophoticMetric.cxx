// Edge lengths under the improved isophotic metric (Ji et al. 2006, section 3).
#include "Segmentation/IsophoticMetric.h"

#include "CacheKey.h"
#include "Error.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf
{

CurvatureAugmentation parseCurvatureAugmentation(const std::string& name)
{
  if (name == "exponential")
  {
    return CurvatureAugmentation::Exponential;
  }
  if (name == "linear")
  {
    return CurvatureAugmentation::Linear;
  }
  if (name == "square")
  {
    return CurvatureAugmentation::Square;
  }
  throw Error("the curvature augmentation must be exponential, linear or square, not '" + name + "'");
}

std::string cacheKey(const IsophoticMetricOptions& options)
{
  return cacheKey(options.normalWeight) + "," + cacheKey(options.curvatureWeight) + "," +
    std::to_string(static_cast<int>(options.augmentation)) + (options.curvaturePerEdge ? ",per-edge" : "");
}

void checkIsophoticMetricOptions(const IsophoticMetricOptions& options)
{
  for (const auto& [value, name] : { std::pair<double, const char*>{ options.normalWeight, "normal weight w" },
         { options.curvatureWeight, "curvature weight w*" } })
  {
    if (!std::isfinite(value) || value < 0.0)
    {
      throw Error(
        std::string("the metric's ") + name + " must be a finite non-negative number, not " + std::to_string(value));
    }
  }
}

double augmentedCurvature(double k, CurvatureAugmentation augmentation)
{
  if (k >= 0.0)
  {
    return k;
  }
  const double x = std::min(-k, AugmentationLimit);
  switch (augmentation)
  {
    case CurvatureAugmentation::Linear:
      return 3.0 * x;
    case CurvatureAugmentation::Square:
      return x * x;
    case CurvatureAugmentation::Exponential:
      break;
  }
  return std::expm1(x);
}

double normalCurvature(const SurfaceDescriptors& descriptors, int v, const Vector3& direction)
{
  // Euler's formula in the principal frame: k = k1 c1^2 + k2 c2^2 over c1^2 + c2^2.
  const double c1 = direction.dot(descriptors.maximumDirections[v]);
  const double c2 = direction.dot(descriptors.minimumDirections[v]);
  const double tangential = c1 * c1 + c2 * c2;
  if (!(tangential > 1e-24 * direction.squaredNorm()))
  {
    return descriptors.meanCurvature[v];
  }
  return (descriptors.maximumCurvature[v] * c1 * c1 + descriptors.minimumCurvature[v] * c2 * c2) / tangential;
}

double unitBoxScale(const TriangleMesh& mesh)
{
  Eigen::AlignedBox3d box;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (mesh.vertexComponent(v) >= 0)
    {
      box.extend(mesh.point(v));
    }
  }
  const double side = box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
  return side > 0.0 ? side : 1.0;
}

std::vector<double> isophoticEdgeLengths(
  const TriangleMesh& mesh, const SurfaceDescriptors& descriptors, const IsophoticMetricOptions& options)
{
  checkIsophoticMetricOptions(options);
  if (static_cast<int>(descriptors.normals.size()) != mesh.vertexCount())
  {
    throw Error("the surface descriptors do not belong to this mesh");
  }
  const double s = unitBoxScale(mesh);
  std::vector<double> lengths(static_cast<std::size_t>(mesh.edgeCount()));
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const auto [p, q] = mesh.edgeVertices(e);
    const Vector3 pq = mesh.point(q) - mesh.point(p);
    // Curvatures of the mesh scaled by 1/s are s times larger; normals do not change.
    const double k = 0.5 * s * (normalCurvature(descriptors, p, pq) + normalCurvature(descriptors, q, pq));
    const double chord = pq.norm() / s;
    const double unitLength = chord + options.normalWeight * (descriptors.normals[p] - descriptors.normals[q]).norm() +
      options.curvatureWeight * augmentedCurvature(k, options.augmentation) * (options.curvaturePerEdge ? 1.0 : chord);
    lengths[static_cast<std::size_t>(e)] = s * unitLength;
  }
  return lengths;
}

const std::vector<double>& surfaceIsophoticEdgeLengths(const Surface& surface, const IsophoticMetricOptions& options)
{
  checkIsophoticMetricOptions(options);
  return surface.derived<std::vector<double>>("isophotic-edge-lengths:" + cacheKey(options),
    [&surface, &options] { return isophoticEdgeLengths(surface.mesh(), surface.descriptors(), options); });
}

} // namespace kerf
