// Per-vertex surface descriptors: normals, curvature tensor, concavity and normal-cone angle.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>
#include <vector>

namespace kerf
{

/// Per-vertex normals weighted as in Max 1999 ("Weights for computing vertex normals from facet
/// normals"): each triangle contributes its normal times sin(angle) / (|e1| |e2|) at a corner,
/// which is exact on a sphere. Unreferenced vertices get a zero normal.
std::vector<Vector3> computeVertexNormals(const TriangleMesh& mesh);

/// Mixed Voronoi corner areas (Meyer et al. 2003): for every triangle, the part of its area
/// closest to each corner, with obtuse triangles split by halves. They sum to the triangle area.
std::vector<std::array<double, 3>> computeCornerAreas(const TriangleMesh& mesh);

/// Per-vertex descriptors. Curvature signs: positive where the surface bends away from its
/// normal (a sphere with outward normals has k1 = k2 = 1/R).
struct SurfaceDescriptors
{
  std::vector<Vector3> normals;
  std::vector<double> maximumCurvature;   ///< k1, the larger principal curvature
  std::vector<double> minimumCurvature;   ///< k2 <= k1
  std::vector<Vector3> maximumDirections; ///< unit tangent direction of k1
  std::vector<Vector3> minimumDirections; ///< unit tangent direction of k2 (normal x max dir)
  std::vector<double> meanCurvature;      ///< (k1 + k2) / 2
  std::vector<double> gaussianCurvature;  ///< k1 * k2
  /// 1 where (p_hat - p) . n > 0 with p_hat the centroid of the one-ring (ROI Scissor, Eq. 3).
  std::vector<unsigned char> concave;
  /// Largest angle in radians between the normals of two triangles around the vertex
  /// (Dekkers and Kobbelt 2014, Eq. 4).
  std::vector<double> normalConeAngle;
};

/// Computes every descriptor. The curvature tensor is estimated per triangle from the variation
/// of vertex normals along its edges and averaged at vertices with Voronoi corner weights
/// (Rusinkiewicz 2004, "Estimating curvatures and their derivatives on triangle meshes").
/// Zero-area triangles contribute nothing. Vertices used by no triangle get zeros.
SurfaceDescriptors computeSurfaceDescriptors(const TriangleMesh& mesh);

} // namespace kerf
