// Intrinsic triangulations: a mesh's connectivity with edge lengths, flipped to intrinsic Delaunay.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace kerf
{

/// A triangulation of a mesh's surface given by connectivity and edge lengths only, on the same
/// vertices: edge flips change which vertex pairs are joined, never the surface's metric
/// (Bobenko and Springborn 2007). Flipped edges are geodesic segments across the two triangles
/// they replace; their lengths come from laying the pair out in the plane, as Sharp, Soliman and
/// Crane 2019 flip edges, so no triangle inequality is lost to cancellation. Edge k of
/// triangle f joins corner k to corner k+1; its "halfedge" is 3 f + k. Two triangles may share
/// two edges, and an edge may join a vertex to itself, as intrinsic triangulations allow.
/// Boundary edges and edges of more than two triangles (or of two oppositely oriented ones) are
/// never flipped.
class IntrinsicTriangulation
{
public:
  /// The mesh's own triangles with their Euclidean edge lengths.
  explicit IntrinsicTriangulation(const TriangleMesh& mesh);

  /// Flips edges until every flippable one is Delaunay (the angles opposite it sum to at most
  /// pi, up to a relative 1e-12): the intrinsic Delaunay triangulation. Returns the number of
  /// flips. Terminates (Bobenko and Springborn 2007); a bound of 50 flips per edge guards
  /// against rounding.
  int flipToDelaunay();

  int vertexCount() const { return this->VertexCount; }
  int faceCount() const { return static_cast<int>(this->Corners.size()); }
  const Triangle& triangle(int f) const { return this->Corners[f]; }
  const std::vector<Triangle>& triangles() const { return this->Corners; }
  /// Length of edge k of triangle f.
  double length(int f, int k) const { return this->Lengths[f][k]; }
  /// The halfedge across halfedge h (3 f + k), or -1 where the edge cannot be flipped.
  int twin(int h) const { return this->Twins[h / 3][h % 3]; }

  /// Area of triangle f (Heron's formula in Kahan's stable form; 0 if degenerate).
  double area(int f) const;
  /// Cotangent of the angle at corner k of triangle f, clamped to +-CotangentLimit.
  double cotangent(int f, int k) const;
  /// Triangle f laid out in the plane: corner 0 at the origin, corner 1 on the positive x axis,
  /// corner 2 above it.
  std::array<Eigen::Vector2d, 3> layout(int f) const;
  /// True if the edge of halfedge h is Delaunay or cannot be flipped.
  bool isDelaunay(int h) const;

  /// A Laplacian weight on a vertex pair (i < j): the cotangent weights of every edge joining
  /// them summed.
  struct PairWeight
  {
    int i = 0;
    int j = 0;
    double weight = 0.0;
  };
  /// w_ij = (cot alpha + cot beta) / 2 summed per vertex pair, sorted by (i, j); pairs joined
  /// only by self-loops are left out. Negative sums (possible only on edges that cannot be
  /// flipped, such as boundary edges with an obtuse opposite angle) become 0.
  std::vector<PairWeight> cotangentWeights() const;
  /// A third of each triangle's area at each of its corners (lumped mass).
  std::vector<double> vertexAreas() const;

private:
  int VertexCount = 0;
  std::vector<Triangle> Corners;
  std::vector<std::array<double, 3>> Lengths;
  std::vector<std::array<int, 3>> Twins;

  void flip(int h);
};

/// The intrinsic Delaunay Laplacian in the form kerf::HarmonicFieldSolver takes: a mesh on the
/// input's points whose triangles are the intrinsic triangles (their corner indices; a flipped
/// triangle is not flat in space, only its vertex pairs matter to the Laplacian), and one weight
/// per edge of that mesh. Nonnegative, and linearly precise on planar meshes (a harmonic field
/// with linear boundary values is that linear function), as the cotangent Laplacian is only on
/// Delaunay meshes.
struct IntrinsicDelaunayLaplacian
{
  TriangleMesh mesh;
  std::vector<double> weights;
  int flips = 0;
};

/// Builds the intrinsic Delaunay triangulation of `mesh` and its Laplacian.
IntrinsicDelaunayLaplacian intrinsicDelaunayLaplacian(const TriangleMesh& mesh);

} // namespace kerf
