// Geometry seam carving's editing: weighted Laplace deformation of the modeling region with ring seams split or
// collapsed per sector.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace kerf
{

/// Parameters of the editing (Dekkers and Kobbelt 2014, 3.3).
struct SeamCarvingOptions
{
  double stiffnessScale = 10.0;  ///< s of Eq. 7 (the paper's octopus and seahorse use 10)
  double stiffnessEpsilon = 0.1; ///< epsilon of Eq. 7, keeps flat vertices' springs positive
  bool plastic = true;           ///< execute ring seams; false gives the plain elastic result
  /// A ring segment is not executed in its sector when one of its triangles has a corner whose
  /// ang(v) (Eq. 4), scaled linearly to [0, 1] over the modeling region's points, exceeds this:
  /// a ring forced across a feature leaves it alone there (Dekkers and Kobbelt 2014, 3.3.1).
  /// In [0, 1]; 1 executes every segment.
  double salientThreshold = 0.5;
};

/// The preprocessed surface the editing starts from: the rest mesh, the painted regions and what
/// computeGeometrySeams found (GeometrySeams.h), one value per vertex or per triangle.
struct SeamCarvingInput
{
  const TriangleMesh* mesh = nullptr;
  std::vector<double> region;          ///< per vertex: 0 fixed, 1 modeling, 2 handle
  std::vector<int> faceRing;           ///< per triangle: ring seam index, -1 outside every ring
  std::vector<int> faceSector;         ///< per triangle: sector of a modeling triangle, -1 elsewhere
  std::vector<double> faceCost;        ///< per triangle: mean normalised edge cost kappa, -1 elsewhere
  std::vector<double> normalConeAngle; ///< per vertex: ang(v) of Eq. 4
};

/// One deformed, re-meshed surface.
struct SeamCarvingResult
{
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  std::vector<int> pointOrigin; ///< input vertex of each point, -1 for a point a split made
  std::vector<int> faceRing;    ///< ring of each triangle (split halves keep their ring), -1 outside
  std::vector<int> faceSector;  ///< sector of each triangle, -1 outside the modeling region
  /// Per sector: rings executed, positive when split, negative when collapsed (the tuple (k, b)
  /// of section 3.3.1 as one signed count).
  std::vector<int> sectorState;
  std::vector<double> sectorDistortion; ///< per sector: d(A_j) of Eq. 5 against the current rest area
  int splitSegments = 0;                ///< ring segments split
  int collapsedSegments = 0;            ///< ring segments collapsed
  int skippedOperations = 0;            ///< edge collapses refused by the link condition (left as they are)
  int solves = 0;                       ///< Laplace solves of the last deform()
  int factorizations = 0;               ///< factorizations of the last deform()
};

/// An editing session on one preprocessed surface (Dekkers and Kobbelt 2014, 3.3). deform()
/// moves the handle region by an affine transform, keeps the fixed region, solves the weighted
/// Laplace editing problem on the modeling region, and executes (splits or collapses) ring
/// segments per sector when the sector's area change exceeds the next segment's area; with the
/// inverse sign the last executed segment is undone. The mesh is a function of the per-sector
/// counts alone (every state is rebuilt from the rest mesh on OpenMesh's half-edge structure), so
/// returning the handle to the identity undoes every operation and returns the input mesh.
class GeometrySeamCarving
{
public:
  /// Checks the regions (checkSeamRegions) and the per-triangle arrays, builds the rest state.
  /// Throws kerf::Error naming the problem.
  GeometrySeamCarving(const SeamCarvingInput& input, const SeamCarvingOptions& options);
  ~GeometrySeamCarving();
  GeometrySeamCarving(const GeometrySeamCarving&) = delete;
  GeometrySeamCarving& operator=(const GeometrySeamCarving&) = delete;

  /// Deforms with the handle moved by `handleTransform` (an affine 4 x 4 matrix applied to the
  /// rest positions of the handle points), starting from the seam state the previous call left.
  /// Throws kerf::Error for a matrix that is not finite, not affine or singular.
  const SeamCarvingResult& deform(const Eigen::Matrix4d& handleTransform);

  int sectorCount() const;
  int ringCount() const;
  /// Per sector, the rings in the order they are executed there (increasing Eq. 6 error); the
  /// salient segments (SeamCarvingOptions::salientThreshold) are left out.
  const std::vector<std::vector<int>>& executionOrder() const;
  /// Ring segments left out of the execution orders as salient, over all sectors.
  int salientSegmentCount() const;

private:
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};

} // namespace kerf
