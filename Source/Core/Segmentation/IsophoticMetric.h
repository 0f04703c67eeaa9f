// The improved isophotic metric of Easy Mesh Cutting: edge lengths that grow with normal variation and curvature.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <string>
#include <vector>

namespace kerf
{

class Surface;
struct SurfaceDescriptors;

/// The augmentation g of negative curvature (Ji et al. 2006, section 3): g(|k|) replaces a
/// concave normal curvature k < 0.
enum class CurvatureAugmentation
{
  Exponential = 0, ///< g(x) = e^x - 1, the paper's choice
  Linear = 1,      ///< g(x) = 3x
  Square = 2       ///< g(x) = x^2
};

/// "exponential", "linear" or "square"; throws kerf::Error naming the word for anything else.
CurvatureAugmentation parseCurvatureAugmentation(const std::string& name);

/// Parameters of the metric (Ji et al. 2006, sections 3 and 6).
struct IsophoticMetricOptions
{
  double normalWeight = 5.0;    ///< w, the weight of the normal variation |n_p - n_q|
  double curvatureWeight = 5.0; ///< w*, the weight of the curvature term f(k_pq)
  CurvatureAugmentation augmentation = CurvatureAugmentation::Exponential;
  /// The curvature term as printed in the paper's discrete formula, w* f(k_pq) per edge, instead of
  /// w* f(k_pq) |p - q|, the discretization of its continuous definition w* int f(k_D) ds. Per edge,
  /// the term counts edges rather than length (it makes up nearly all of d on meshes of 10k
  /// vertices) and a concave crease crossed by edges oblique to it costs little, so parts leak into
  /// each other (see Documentation/filters/EasyMeshCutting.md). Default off.
  bool curvaturePerEdge = false;
};

/// A key naming the options exactly (for kerf::Surface::derived).
std::string cacheKey(const IsophoticMetricOptions& options);

/// Throws kerf::Error unless both weights are finite and non-negative.
void checkIsophoticMetricOptions(const IsophoticMetricOptions& options);

/// f(k): k for k >= 0, g(|k|) for k < 0 (Ji et al. 2006, section 3). The argument of g is capped
/// at AugmentationLimit, so e^x - 1 stays below 1e130 and sums of lengths never overflow.
double augmentedCurvature(double k, CurvatureAugmentation augmentation);
constexpr double AugmentationLimit = 300.0;

/// The normal curvature at vertex v in the direction `direction` projected onto its tangent
/// plane, by Euler's formula k = k1 cos^2(phi) + k2 sin^2(phi) with phi the angle to the maximum
/// principal direction; the mean curvature where the projection vanishes.
double normalCurvature(const SurfaceDescriptors& descriptors, int v, const Vector3& direction);

/// The side of the axis-aligned bounding box of the referenced vertices that is longest: the
/// metric measures the mesh scaled by its inverse into a unit bounding box (Ji et al. 2006,
/// section 6). 1 for an empty or point-like mesh.
double unitBoxScale(const TriangleMesh& mesh);

/// The metric's length of every edge (indexed as mesh edges), in the input's units:
///   d(p, q) = |p - q| + w |n_p - n_q| + w* f(k_pq) |p - q|        (Ji et al. 2006, section 3)
/// (without the last factor |p - q| with options.curvaturePerEdge), evaluated on the mesh scaled into a unit bounding
/// box (lengths divided and curvatures multiplied by s = unitBoxScale) and multiplied by s again, so that where the
/// surface is flat the length is the Euclidean one. k_pq, the normal curvature along pq, is the mean of Euler's formula
/// at p and at q (so d(p, q) = d(q, p)). Throws kerf::Error for invalid options.
std::vector<double> isophoticEdgeLengths(
  const TriangleMesh& mesh, const SurfaceDescriptors& descriptors, const IsophoticMetricOptions& options);

/// isophoticEdgeLengths of the surface and its cached descriptors, computed once per surface and
/// options.
const std::vector<double>& surfaceIsophoticEdgeLengths(const Surface& surface, const IsophoticMetricOptions& options);

} // namespace kerf
