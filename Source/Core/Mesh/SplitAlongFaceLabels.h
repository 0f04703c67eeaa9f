// Cutting a triangle mesh open where faces of different labels meet, so each label is its own piece.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A mesh cut open along the borders between face labels.
struct SplitMesh
{
  TriangleMesh mesh;              ///< the cut mesh: no vertex is shared by faces of two labels
  std::vector<int> originalPoint; ///< per vertex of `mesh`: the vertex of the input it copies
  std::vector<int> faceLabel;     ///< per face of `mesh` (faces keep the input's order)
};

/// What splitAlongFaceLabels does where faces of one label meet at a vertex without sharing an
/// edge there (a pinch: the vertex's faces of that label form several fans).
enum class LabelFans
{
  Keep,    ///< one copy per label: each label stays one piece where it was connected
  Separate ///< one copy per fan: no vertex is pinched, a label connected only through a vertex
           ///< falls into pieces joined by edges
};

/// Duplicates every vertex used by faces of several labels, one copy per label (or per fan of a
/// label, see LabelFans), so that faces of different labels share no vertex and no edge. Faces
/// keep their order and orientation; the vertices are numbered by input vertex, then by label
/// (ascending), then by the fan's first face; input vertices used by no face are dropped.
/// Deterministic. Throws kerf::Error when `faceLabels` does not hold one label per face.
SplitMesh splitAlongFaceLabels(
  const TriangleMesh& mesh, const std::vector<int>& faceLabels, LabelFans fans = LabelFans::Keep);

} // namespace kerf
