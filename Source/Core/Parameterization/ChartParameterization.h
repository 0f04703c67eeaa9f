// Texture coordinates for a surface cut into charts: LSCM or LinABF per chart, distortion, overlap count, and their
// layout in the unit square (ChartPacking).
#pragma once

#include "Mesh/SplitAlongFaceLabels.h"
#include "Mesh/TriangleMesh.h"
#include "Parameterization/ChartPacking.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace kerf
{

/// How each chart is flattened (timings and distortion in Documentation/filters/ChartParameterization.md).
enum class ChartMethod
{
  /// Least-squares conformal map (leastSquaresConformalMap): one sparse solve per chart.
  LSCM,
  /// Linear angle based flattening (linearAngleBasedFlattening): the angles of LinABF, then the
  /// same least-squares solve with those angles.
  LinABF
};

/// How the least-squares system of the positions (LSCM's, and LinABF's reconstruction) is solved
/// (all exact; timings in Documentation/filters/ChartParameterization.md).
enum class ChartSolver
{
  /// The energy as a Hermitian form in z = u + i v: n complex unknowns with the Laplacian's
  /// pattern, CHOLMOD's L L^H (supernodal or simplicial, as CHOLMOD chooses; AMD ordering). The
  /// default. Without CHOLMOD, ComplexLDLT.
  ComplexCHOLMOD,
  /// The Hermitian form with Eigen's SimplicialLDLT.
  ComplexLDLT,
  /// The real form in (u, v): 2n unknowns, kerf::SparseCholesky (CHOLMOD, supernodal).
  RealCHOLMOD,
  /// The real form with Eigen's SimplicialLDLT.
  RealLDLT
};

/// Parameters of parameterizeCharts.
struct ChartParameterizationOptions
{
  /// Gap left between charts and between a chart and the border of the unit square, as a
  /// fraction of the square's side, in [0, 0.25]. Default 0.01.
  double margin = 0.01;
  /// LSCM, the default: LinABF costs more per chart (measured in
  /// Documentation/filters/ChartParameterization.md).
  ChartMethod method = ChartMethod::LSCM;
  ChartSolver solver = ChartSolver::ComplexCHOLMOD;
  /// Side, in texels, of the grid on which countChartOverlaps samples the layout. Default 1024.
  int overlapResolution = 1024;
  /// Charts that are connected, manifold and consistently oriented but not disks (closed, with
  /// several boundary loops or with handles) are cut into disks by cutToDisk; when false they are
  /// refused like the other charts that are not disks. Default true.
  bool cutToDisks = true;
  /// Seams added to each chart where its map is worst, at most this many (cut augmentation, Gu,
  /// Gortler and Hoppe 2002, section 3.2): while the chart's L2 stretch (the inverse map's,
  /// Sander et al. 2001, whatever the triangles' orientation, capped at 1000) is above
  /// seamStretchTarget, the chart is cut from the vertex farthest from its boundary among the
  /// triangles with at least a tenth of the worst stretch, along the shortest edge path to the boundary,
  /// and flattened again (with `method`); a seam that does not lower the stretch is dropped and ends the search.
  /// Default 0: no seam.
  int maximumSeams = 0;
  double seamStretchTarget = 1.2;
};

/// Distortion of the map from a triangle to its texture image.
struct FaceDistortion
{
  double stretch = 1.0; ///< sqrt((s1^2 + s2^2) / 2) (Sander et al. 2001, section 3)
  double shear = 1.0;   ///< s1 / s2 (infinite for a triangle collapsed in the texture)
  /// sqrt((1 / s1^2 + 1 / s2^2) / 2): the stretch of the inverse map, from the texture to the
  /// surface, which Sander et al. 2001 (section 3) average (infinite for a collapsed triangle)
  double inverseStretch = 1.0;
  bool flipped = false; ///< the texture image has the opposite orientation
};

/// Area-weighted means (weights: the triangles' 3D areas) and maxima of the distortion.
struct DistortionSummary
{
  double meanStretch = 0.0;
  /// The L2 stretch of the whole surface, Sander et al. 2001 (section 3): sqrt(sum A_f
  /// inverseStretch_f^2 / sum A_f). With the texture area equal to the 3D area it is at least 1,
  /// and 1 only for an isometry (the mean of stretch is below 1 for a conformal map that scales).
  double surfaceStretch = 0.0;
  double maxStretch = 0.0;
  double meanShear = 0.0;
  double maxShear = 0.0;
  int flippedFaces = 0;
  double area = 0.0; ///< 3D area of the triangles summarized
};

/// One chart of the result: a connected piece of the faces of one label.
struct ChartSummary
{
  int label = 0; ///< a label whose faces form several pieces has one chart per piece
  int faceCount = 0;
  int vertexCount = 0;
  DistortionSummary distortion;
  double rotation = 0.0; ///< radians the chart was turned by before it was packed
  /// For a chart that was not a disk: what it was ("2 boundary loops and genus 1"), the number
  /// of its edges cut by cutToDisk and their total length; empty and 0 for a disk.
  std::string cutFrom;
  int cutEdgeCount = 0;
  double cutLength = 0.0;
  int seams = 0;           ///< seams added (options.maximumSeams)
  double seamLength = 0.0; ///< their total length
};

/// The result of parameterizeCharts.
struct ChartParameterizationResult
{
  SplitMesh split;                   ///< the surface cut open along the chart borders
  std::vector<Vector2> uv;           ///< per vertex of split.mesh, inside [margin, 1 - margin]^2
  std::vector<FaceDistortion> faces; ///< per face of split.mesh
  std::vector<ChartSummary> charts;  ///< in increasing label order, then piece order
  DistortionSummary distortion;      ///< all charts
  int overlappingChartPairs = 0;     ///< countChartOverlaps of the packed layout
  int cutCharts = 0;                 ///< charts cut into disks (ChartSummary::cutFrom)
  double texelScale = 0.0;           ///< texture length per unit of 3D length, equal for every chart
};

/// An empty string if `chart` is a topological disk (one connected piece, manifold, consistently
/// oriented, one boundary loop, genus 0, no zero-area triangle), else a sentence naming what it
/// is instead (its boundary loops and genus, for example).
std::string chartTopologyProblem(const TriangleMesh& chart);

/// Least-squares conformal map of a disk (Levy et al. 2002, section 3), its energy written as
/// E = E_Dirichlet - A(u, v) (Mullen et al. 2008, section 3), with the two boundary vertices farthest apart (two
/// sweeps) pinned at (0, 0) and (d, 0), d their 3D distance. Returns one point per vertex. Throws
/// kerf::Error for a chart that is not a disk or a system the solver cannot factor.
std::vector<Vector2> leastSquaresConformalMap(
  const TriangleMesh& chart, ChartSolver solver = ChartSolver::ComplexCHOLMOD);

/// Linear angle based flattening of a disk: the planar angles of LinABF (linearAngleBasedAngles,
/// Zayer, Lévy and Seidel 2007), then the positions that fit them best, by the least-squares
/// reconstruction of ABF++ (Sheffer et al. 2005): per triangle (p1, p2, p3) with angles a1, a2, a3,
/// p3 - p1 = (sin a2 / sin a3) R(a1) (p2 - p1), the residual weighted by sin a3 / (4 sin a1 sin a2)
/// so that it is the triangle's conformal energy relative to a triangle with those angles and
/// does not depend on which corner is p1. The sum is LSCM's energy with cot(alpha) in place of
/// the 3D cotangents, solved the same way, with the same two pinned vertices: LSCM is the case
/// alpha = the 3D angles. Returns one point per vertex. Throws kerf::Error for a chart that is not
/// a disk or a system that cannot be factored.
std::vector<Vector2> linearAngleBasedFlattening(
  const TriangleMesh& chart, ChartSolver solver = ChartSolver::ComplexCHOLMOD);

/// Distortion of the affine map from triangle (p0, p1, p2) to (t0, t1, t2): the singular values
/// s1 >= s2 of its Jacobian.
FaceDistortion faceDistortion(
  const Vector3& p0, const Vector3& p1, const Vector3& p2, const Vector2& t0, const Vector2& t1, const Vector2& t2);

/// Cuts the mesh open along the borders of faceLabels and at pinched vertices
/// (splitAlongFaceLabels with LabelFans::Separate); each connected piece of a label is a chart
/// (a label in several pieces gives several charts). Cuts the charts that are not disks but can
/// be made disks by cutToDisk (options.cutToDisks; the copies of the vertices along these cuts
/// are appended to result.split's vertices). Flattens each chart with
/// leastSquaresConformalMap or linearAngleBasedFlattening (options.method), scales each so its texture area equals its
/// 3D area, measures the distortion, turns each chart to its minimal bounding box and packs them into the unit square
/// with one scale for all (equal texel density). Throws kerf::Error listing every chart that is not a disk and was not
/// cut (by label, and piece if the label has several, with what it is: boundary loops and genus, non-manifold edges,
/// zero-area triangles), for a label count other than the face count, an empty mesh or a margin outside [0, 0.25].
ChartParameterizationResult parameterizeCharts(
  const TriangleMesh& mesh, const std::vector<int>& faceLabels, const ChartParameterizationOptions& options = {});

} // namespace kerf
