// Gradients of piecewise-linear fields on triangles.
#include "Numerics/FieldGradient.h"

#include "Mesh/MeshValidation.h"

#include <algorithm>
#include <cmath>

namespace kerf
{

Vector3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& field, int face)
{
  const Triangle& t = mesh.triangle(face);
  const Vector3& p0 = mesh.point(t[0]);
  const Vector3& p1 = mesh.point(t[1]);
  const Vector3& p2 = mesh.point(t[2]);
  // e_j is the edge opposite corner j, counter-clockwise; N = e_1 x e_2, |N| = 2A.
  const Vector3 e0 = p2 - p1;
  const Vector3 e1 = p0 - p2;
  const Vector3 e2 = p1 - p0;
  const Vector3 normal = e1.cross(e2);
  const double squaredTwiceArea = normal.squaredNorm();
  const double longest = std::max(std::max(e0.squaredNorm(), e1.squaredNorm()), e2.squaredNorm());
  if (isZeroArea(std::sqrt(squaredTwiceArea), longest))
  {
    return Vector3::Zero();
  }
  // ROI Scissor, section 4.2: sum_j f_j (n x e_j) / 2A = N x (sum_j f_j e_j) / |N|^2.
  return normal.cross(field[t[0]] * e0 + field[t[1]] * e1 + field[t[2]] * e2) * (1.0 / squaredTwiceArea);
}

std::vector<Vector3> computeFaceGradients(const TriangleMesh& mesh, const std::vector<double>& field)
{
  std::vector<Vector3> gradients(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    gradients[f] = faceGradient(mesh, field, f);
  }
  return gradients;
}

std::vector<double> faceGradientMagnitudes(
  const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<int>* faces)
{
  std::vector<double> magnitudes(static_cast<std::size_t>(mesh.faceCount()), 0.0);
  if (faces)
  {
    for (int f : *faces)
    {
      magnitudes[f] = faceGradient(mesh, field, f).norm();
    }
    return magnitudes;
  }
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    magnitudes[f] = faceGradient(mesh, field, f).norm();
  }
  return magnitudes;
}

} // namespace kerf
