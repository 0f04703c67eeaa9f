// Multi-label random walks from labelled seed vertices: each vertex and face to the label a walk from it most likely
// reaches first.
#pragma once

#include "Mesh/TriangleMesh.h"
#include "Segmentation/SegmentSpines.h"

#include <vector>

namespace kerf
{

/// A labelling by random walks.
struct RandomWalkLabelling
{
  /// The distinct seed labels, ascending.
  std::vector<int> labels;
  /// Per vertex, the label of largest probability; -1 in a component without seeds and on points
  /// no triangle uses.
  std::vector<int> vertexLabels;
  /// Per vertex, that label's probability, in [0, 1]; 0 where the label is -1.
  std::vector<double> vertexProbabilities;
  /// Per vertex, the label of second largest probability (ties to the smaller label), and its
  /// probability; -1 and 0 where there is no second label.
  std::vector<int> secondLabels;
  std::vector<double> secondProbabilities;
  /// Per face, the label whose probabilities summed over the three corners are largest; -1 in a
  /// component without seeds.
  std::vector<int> faceLabels;
};

/// Multi-label random walks (Grady 2006, section 2; Lai et al. 2009, section 3): the probability that a
/// random walk from vertex v, stepping along edges in proportion to their weights, reaches a seed
/// of label l before any other seed is the harmonic field that is 1 on l's seeds and 0 on the
/// others' (L_FF p_F = -L_FS p_S). Every vertex takes the label of largest probability, and every
/// face the label whose corner probabilities sum highest (a face is labelled by its own area
/// rather than by one corner; ties go to the smaller label). One factorization serves all labels
/// (kerf::HarmonicFieldSolver, its hard set unchanged), and one field is held at a time: beyond
/// the factorization, memory does not grow with the number of labels. Components without seeds
/// are held at 0 (disconnected, they change nothing elsewhere) and labelled -1. `edgeWeights` are
/// one finite, non-negative weight per mesh edge (kerf::computeLaplacianWeights). Throws
/// kerf::Error for seeds off the mesh, negative labels, a seed given two labels, weights of
/// another mesh or negative or not finite, or no seed.
RandomWalkLabelling randomWalkLabels(const TriangleMesh& mesh, const std::vector<double>& edgeWeights,
  const std::vector<int>& seedVertices, const std::vector<int>& seedLabels);

/// A segmentation redrawn by random walks from its segments' spines.
struct SpineWalk
{
  std::vector<int> faceLabels; ///< the walks' labels, or the input's where they were not applied
  int changedFaces = 0;        ///< faces whose label the walks changed
  bool applied = false;        ///< false when a segment had no seed or would have lost every face
};

/// Redraws a per-face segmentation by random walks seeded on its segments' spines
/// (kerf::segmentSpines): the corners of a spine's faces are its seeds, and a vertex the spines of
/// two segments share seeds neither; every face then takes its most probable segment
/// (kerf::randomWalkLabels). The walks never remove a segment: where a segment of `faceLabels` has
/// no spine, a spine is left without a seed, or a segment's seeds would win no face, the input's
/// labels are returned unchanged (not applied; so too for a labelling without segments). Throws
/// kerf::Error for labels or weights of another mesh, a negative spine label, or a spine's face
/// outside its segment.
SpineWalk walkFromSpines(const TriangleMesh& mesh, const std::vector<double>& edgeWeights,
  const std::vector<SegmentSpine>& spines, const std::vector<int>& faceLabels);

} // namespace kerf
