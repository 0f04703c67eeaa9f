// A mesh bound to the data derived from it: each item computed on first use, kept while the mesh lives.
#pragma once

#include "CacheKey.h"
#include "Mesh/TriangleMesh.h"

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
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
/// keeps only the state of its own solver. Several threads may ask for derived items at once (the
/// members of an ensemble do, on Kerf's threads): each item is computed once, by the first thread
/// that asks for it, while the others that ask for the same item wait for it. An item is then
/// read-only, except where its type says otherwise (consensus cuts' candidates, found lazily, are
/// for one thread at a time).
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
  /// A compute() that throws leaves the item absent, to be computed again on the next request.
  template <typename T>
  const T& derived(const std::string& key, const std::function<T()>& compute) const
  {
    Slot* slot = nullptr;
    {
      const std::lock_guard<std::mutex> lock(this->ItemsMutex);
      std::unique_ptr<Slot>& held = this->Items[key];
      if (!held)
      {
        held = std::make_unique<Slot>();
      }
      slot = held.get(); // slots are never removed while the surface lives
    }
    const std::lock_guard<std::mutex> computing(slot->mutex);
    if (!slot->item)
    {
      slot->item = std::make_shared<T>(compute());
      ++this->Computations;
    }
    return *static_cast<const T*>(slot->item.get());
  }

  /// How many derived items were computed so far (observable caching, for tests).
  int computations() const { return this->Computations; }

private:
  // A derived item, computed once.
  struct Slot
  {
    std::mutex mutex; // held while the item is computed
    std::shared_ptr<void> item;
  };
  const TriangleMesh Mesh;
  mutable std::mutex ItemsMutex; // guards the map, not the items' computations
  mutable std::map<std::string, std::unique_ptr<Slot>> Items;
  mutable std::atomic<int> Computations{ 0 };
};

} // namespace kerf
