// Curves on a surface turned into mesh edges: SeamCut's scissor, snap and inverse-snap export operators.
#pragma once

#include "Geodesic/SurfacePoint.h"
#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// The three export operators (SeamCut, section 4).
enum class CurveExportMode
{
  Scissor = 0,    ///< triangles split along the exact curves (new vertices, more triangles)
  Snap = 1,       ///< geometry and connectivity kept; curves become edge chains of nearest vertices
  InverseSnap = 2 ///< connectivity kept; the nearest vertices moved onto the curves
};

struct CurveExportOptions
{
  CurveExportMode mode = CurveExportMode::Scissor;
  /// A curve point whose barycentric coordinate is within this of 0 lies on the edge opposite
  /// that corner (within it of 1: on the corner). Default 1e-7.
  double locationTolerance = 1e-7;
};

/// Where a curve point lies on the input mesh.
struct CurvePointLocation
{
  enum Kind
  {
    Vertex,
    Edge,
    Face
  };
  Kind kind = Face;
  int index = -1;                        ///< the vertex, the edge or the face
  double t = 0.0;                        ///< on an edge: from edgeVertices(index)[0] (0) to [1] (1)
  Vector3 barycentric = Vector3::Zero(); ///< in a face: w.r.t. its corners
};

/// Locates every point of every curve: on a vertex, on an edge at parameter t, or inside a face.
/// Each point is taken in the triangle of its segments (SurfaceCurve::faces; a point off the
/// surface is projected onto that triangle's plane); coordinates within `tolerance` of 0 or 1
/// put it on the edge or the corner. A point between two segments in different triangles is
/// put on what the triangles share (their edge, at the nearest parameter, or their vertex).
/// Throws kerf::Error naming the curve and point for curves whose faces disagree with their
/// points (out of range, or two consecutive segments in triangles that do not touch).
std::vector<std::vector<CurvePointLocation>> locateCurvePoints(
  const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, double tolerance);

/// An exported mesh and the edges the curves became.
///
/// Snap leaves the mesh as it is: `mesh` stays empty and the output is the input mesh (so a snap
/// copies nothing of it). The index maps are filled by Scissor only; elsewhere they are the
/// identity and stay empty.
struct CurveExportResult
{
  TriangleMesh mesh;          ///< Scissor: the split mesh; InverseSnap: the moved mesh; Snap: empty
  std::vector<char> cutEdges; ///< per edge of the output mesh: 1 where a curve runs along it
  std::vector<int> charts;    ///< per face: connected components across uncut edges
  int chartCount = 0;
  std::vector<int> originalPointIds;           ///< Scissor, per vertex: the input vertex, -1 for a new one
  std::vector<SurfacePoint> pointOrigins;      ///< Scissor, per vertex: where it lies on the input mesh
  std::vector<int> originalFaces;              ///< Scissor, per face: the input triangle it lies in
  std::vector<std::vector<int>> curveVertices; ///< per curve: its vertices in order (closed: first not repeated)
  int movedVertices = 0;                       ///< inverse snap: vertices moved onto a curve point
  int droppedPoints = 0;                       ///< snap modes: points whose nearest vertex went to a nearer point
  int refusedFlips = 0;                        ///< inverse snap: moves refused because a triangle would flip
};

/// The output mesh of an export of `input`: result.mesh, or `input` itself after a snap.
inline const TriangleMesh& exportedMesh(const CurveExportResult& result, const TriangleMesh& input)
{
  return result.mesh.empty() ? input : result.mesh;
}

/// Exports curves on a mesh as mesh edges (SeamCut, section 4):
///
/// - Scissor: a new vertex at each curve point on an edge (shared by both triangles of the edge)
///   or inside a triangle, and where two curves cross inside a triangle; every triangle touched
///   is re-triangulated so that each curve segment is a chain of edges and the curve points keep
///   their exact positions. Total area and the untouched triangles are unchanged.
/// - Snap: the mesh unchanged; each curve point goes to the nearest corner of its triangle and
///   consecutive vertices are joined by the shortest edge path (Dijkstra by edge length).
/// - InverseSnap: as Snap, then the nearest vertex of each point is moved onto it. When several
///   points share one nearest vertex, the nearest point wins (ties: the earlier curve, then point)
///   and the others count as droppedPoints. A move that would turn a triangle around the vertex
///   against its original normal (or make it degenerate) is refused and counted in refusedFlips;
///   moves are tried in increasing vertex order.
///
/// Charts number the faces by connected components across edges that are not cut, in order of
/// their lowest face. Throws kerf::Error (naming curve and point or triangle) for curves whose
/// points and faces disagree (locateCurvePoints), scissor curves through zero-area triangles or
/// across non-manifold edges, and a curve segment through a point of another curve inside a
/// triangle.
CurveExportResult exportCurves(
  const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, const CurveExportOptions& options);

/// Per-face chart labels: faces joined across manifold edges whose flag in `cutEdges` is 0,
/// numbered in order of their lowest face. Returns the number of charts.
int labelCharts(const TriangleMesh& mesh, const std::vector<char>& cutEdges, std::vector<int>& charts);

} // namespace kerf
