// Closest points on a triangle mesh: a bounding-volume hierarchy over its triangles.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// Finds the point of a mesh nearest to a query point. Built once per mesh: the faces sorted in
/// the Morton order of their centroids, a binary tree of boxes over that order.
/// Each query visits the boxes that can hold a point at least as near; ties go to the lower face
/// index, so results are deterministic and do not depend on the tree's shape.
class ClosestPointLocator
{
public:
  explicit ClosestPointLocator(const TriangleMesh& mesh);

  struct Hit
  {
    int face = -1;
    Vector3 barycentric = Vector3::Zero(); ///< w.r.t. the face's corners 0, 1, 2
    Vector3 position = Vector3::Zero();
    double distance = 0.0;
  };

  /// The nearest point; face -1 for an empty mesh.
  Hit closest(const Vector3& query) const;

private:
  struct Node
  {
    Eigen::AlignedBox3d box;
    int first = 0;  // leaves: start in FaceOrder; inner nodes: the left child
    int count = 0;  // leaves: number of faces; 0 for inner nodes
    int right = -1; // inner nodes: the right child
  };
  int build(int first, int count);
  void search(int node, const Vector3& query, Hit& best) const;

  const TriangleMesh& Mesh;
  std::vector<int> FaceOrder;
  std::vector<Node> Nodes;
};

/// The vertex a surface point snaps to: the corner of its triangle with the largest barycentric
/// coordinate (the first such corner on ties).
int snapToVertex(const TriangleMesh& mesh, const ClosestPointLocator::Hit& hit);

/// The point of triangle (a, b, c) nearest to p, with its barycentric coordinates.
Vector3 closestPointOnTriangle(
  const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c, Vector3& barycentric);

} // namespace kerf
