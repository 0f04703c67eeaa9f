// Gradients of piecewise-linear fields: one constant vector per triangle.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// The constant gradient of the piecewise-linear field on each triangle,
/// grad f_T = (1 / 2A) sum_j f_j (n x e_j) with e_j the edge opposite corner j (ROI Scissor,
/// section 4.2). Zero on zero-area triangles.
std::vector<Vector3> computeFaceGradients(const TriangleMesh& mesh, const std::vector<double>& field);

/// The gradient of the field on one triangle (as computeFaceGradients).
Vector3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& field, int face);

/// The gradients' magnitudes |grad f_T|, on every face or, with `faces`, only on those (0
/// elsewhere).
std::vector<double> faceGradientMagnitudes(
  const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<int>* faces = nullptr);

} // namespace kerf
