// Convex patches by flooding the dual graph (Kouhestani 2013, section 3.1), small patches merged.
#pragma once

#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

struct ConvexFloodingOptions
{
  /// epsilon in radians: an edge whose interior dihedral angle is at most pi + epsilon counts as
  /// convex, so shallow concavities (noise) do not stop a patch. Default 0.1 (about 6 degrees).
  double angleTolerance = 0.1;
  /// q: patches smaller than q times the total area are merged into their largest neighbour,
  /// smallest first. Default 0.01.
  double minimumAreaFraction = 0.01;
  /// When positive, patches keep being merged (smallest first, into the largest neighbour) until
  /// at most this many remain. Default 0: no limit.
  int segmentCount = 0;
};

struct ConvexFloodingResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int floodedPatches = 0;  ///< patches before merging
  int segmentCount = 0;
};

/// Flooding: the lowest-numbered face not yet in a patch seeds a new patch, which grows breadth
/// first across dual edges; a face joins when every dual edge it shares with the patch is convex
/// within the tolerance (a local test). Global failures (a patch convex at every edge that does not
/// lie on its convex hull, such as a helical strip) are not tested: the survey notes they are
/// rare and are what makes the problem NP-hard, and a closed convex surface stays one patch. Then
/// patches below q * A are merged into their largest neighbour (and down to segmentCount). Faces
/// joined to no other face by a manifold edge are patches of their own. Deterministic. Throws
/// kerf::Error for a negative or NaN tolerance, a fraction outside [0, 1], or a negative count.
ConvexFloodingResult segmentByConvexFlooding(const FaceGraph& graph, const ConvexFloodingOptions& options);

} // namespace kerf
