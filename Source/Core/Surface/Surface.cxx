// The surface cache: locator, normals, descriptors and Laplacian weights computed on first use.
#include "Surface/Surface.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Numerics/LaplacianWeights.h"

namespace kerf
{

Surface::Surface(TriangleMesh mesh)
  : Mesh(std::move(mesh))
{
}

Surface::~Surface() = default;

const ClosestPointLocator& Surface::locator() const
{
  // The locator is not copyable (it refers to the mesh): hold it through a pointer.
  return *this->derived<std::shared_ptr<const ClosestPointLocator>>(
    "locator", [this] { return std::make_shared<const ClosestPointLocator>(this->Mesh); });
}

const std::vector<Vector3>& Surface::vertexNormals() const
{
  return this->derived<std::vector<Vector3>>("vertex-normals", [this] { return computeVertexNormals(this->Mesh); });
}

const SurfaceDescriptors& Surface::descriptors() const
{
  return this->derived<SurfaceDescriptors>("descriptors", [this] { return computeSurfaceDescriptors(this->Mesh); });
}

const LaplacianWeightSet& Surface::laplacianWeights(const LaplacianWeightOptions& options) const
{
  return this->derived<LaplacianWeightSet>("laplacian-weights:" + cacheKey(options), [this, &options] {
    LaplacianWeightSet set;
    set.weights = computeLaplacianWeights(
      this->Mesh, options, needsDescriptors(options.weighting) ? &this->descriptors() : nullptr);
    set.meanDiagonal = laplacianMeanDiagonal(this->Mesh, set.weights);
    return set;
  });
}

} // namespace kerf
