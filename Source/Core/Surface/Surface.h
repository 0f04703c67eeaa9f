// A mesh bound to the data derived from it: each item computed on first use, kept while the mesh lives.
#pragma once

#include "CacheKey.h"
#include "Mesh/TriangleMesh.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace kerf
{

class ClosestPointLocator;
struct SurfaceDescriptors;
struct LaplacianWeightOptions;

/// Laplacian edge weights and the scale soft constraints are measured in.
struct LaplacianWeightSet
{
  std::vector<double> weights; ///< one per edge, as computeLaplacianWeights
  double meanDiagonal = 1.0;   ///< laplacianMeanDiagonal of the weights
};

/// The caching rule of every Kerf algorithm: expensive data derived from a surface lives here,
/// keyed by the options that made it, and is computed the first time it is asked for. A new
/// surface is a new object, so nothing derived from an earlier one can be reused by mistake;
/// an algorithm session (HarmonicCutSession, ...) holds a shared pointer to its surface and
/// keeps only the state of its own solver. Not thread-safe: one thread uses a surface at a time.
///
/// The mesh is fixed at construction; the object cannot be copied or moved, so the derived
/// data (a locator keeps a reference to the mesh) always refers to it.
class Surface
{
public:
  explicit Surface(TriangleMesh mesh);
  ~Surface();
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  const TriangleMesh& mesh() const { return this->Mesh; }

  /// A closest-point locator over the triangles.
  const ClosestPointLocator& locator() const;
  /// Vertex normals (computeVertexNormals).
  const std::vector<Vector3>& vertexNormals() const;
  /// Every surface descriptor (computeSurfaceDescriptors).
  const SurfaceDescriptors& descriptors() const;
  /// Laplacian weights for these options (the descriptors are computed when the weighting needs
  /// curvature).
  const LaplacianWeightSet& laplacianWeights(const LaplacianWeightOptions& options) const;

  /// Any other derived item: `compute()` runs the first time `key` is asked for, and its result is
  /// returned from then on. Keys name the item and every option it depends on (see cacheKey()).
  template <typename T>
  const T& derived(const std::string& key, const std::function<T()>& compute) const
  {
    auto found = this->Items.find(key);
    if (found == this->Items.end())
    {
      std::shared_ptr<void> item = std::make_shared<T>(compute());
      ++this->Computations;
      found = this->Items.emplace(key, std::move(item)).first;
    }
    return *static_cast<const T*>(found->second.get());
  }

  /// How many derived items were computed so far (observable caching, for tests).
  int computations() const { return this->Computations; }

private:
  const TriangleMesh Mesh;
  mutable std::map<std::string, std::shared_ptr<void>> Items;
  mutable int Computations = 0;
};

} // namespace kerf
