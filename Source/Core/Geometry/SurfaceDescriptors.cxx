// Rusinkiewicz 2004 curvature tensors, Max 1999 normals, concavity flags and normal-cone angles.
#include "Geometry/SurfaceDescriptors.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <string>

namespace kerf
{

namespace
{
// Rotates the orthonormal frame (u, v) about the axis u x v so that its normal becomes n.
void rotateFrame(const Vector3& u, const Vector3& v, const Vector3& n, Vector3& newU, Vector3& newV)
{
  newU = u;
  newV = v;
  const Vector3 oldNormal = u.cross(v);
  const double ndot = oldNormal.dot(n);
  if (ndot <= -1.0)
  {
    newU = -newU;
    newV = -newV;
    return;
  }
  const Vector3 perpOld = n - ndot * oldNormal;
  const Vector3 dperp = (oldNormal + n) / (1.0 + ndot);
  newU -= dperp * newU.dot(perpOld);
  newV -= dperp * newV.dot(perpOld);
}

// Re-expresses the symmetric tensor [ku kuv; kuv kv] given in frame (oldU, oldV) in (newU, newV).
void projectTensor(const Vector3& oldU, const Vector3& oldV, double ku, double kuv, double kv, const Vector3& newU,
  const Vector3& newV, double& outKu, double& outKuv, double& outKv)
{
  Vector3 rotatedU, rotatedV;
  rotateFrame(newU, newV, oldU.cross(oldV), rotatedU, rotatedV);
  const double u1 = rotatedU.dot(oldU);
  const double v1 = rotatedU.dot(oldV);
  const double u2 = rotatedV.dot(oldU);
  const double v2 = rotatedV.dot(oldV);
  outKu = ku * u1 * u1 + kuv * (2.0 * u1 * v1) + kv * v1 * v1;
  outKuv = ku * u1 * u2 + kuv * (u1 * v2 + u2 * v1) + kv * v1 * v2;
  outKv = ku * u2 * u2 + kuv * (2.0 * u2 * v2) + kv * v2 * v2;
}

// Any unit vector perpendicular to n.
Vector3 anyPerpendicular(const Vector3& n)
{
  const Vector3 axis = std::abs(n.x()) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
  return n.cross(axis).normalized();
}
} // namespace

std::vector<Vector3> computeVertexNormals(const TriangleMesh& mesh)
{
  std::vector<Vector3> normals(mesh.vertexCount(), Vector3::Zero());
  for (const Triangle& t : mesh.triangles())
  {
    const Vector3& p0 = mesh.point(t[0]);
    const Vector3& p1 = mesh.point(t[1]);
    const Vector3& p2 = mesh.point(t[2]);
    const Vector3 a = p0 - p1;
    const Vector3 b = p1 - p2;
    const Vector3 c = p2 - p0;
    const double la = a.squaredNorm();
    const double lb = b.squaredNorm();
    const double lc = c.squaredNorm();
    if (la == 0.0 || lb == 0.0 || lc == 0.0)
    {
      continue;
    }
    const Vector3 faceNormal = a.cross(b);
    normals[t[0]] += faceNormal * (1.0 / (la * lc));
    normals[t[1]] += faceNormal * (1.0 / (lb * la));
    normals[t[2]] += faceNormal * (1.0 / (lc * lb));
  }
  for (Vector3& n : normals)
  {
    const double length = n.norm();
    if (length > 0.0)
    {
      n /= length;
    }
  }
  return normals;
}

std::vector<std::array<double, 3>> computeCornerAreas(const TriangleMesh& mesh)
{
  std::vector<std::array<double, 3>> corner(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    // e[j] is the edge opposite corner j.
    const Vector3 e[3] = { mesh.point(t[2]) - mesh.point(t[1]), mesh.point(t[0]) - mesh.point(t[2]),
      mesh.point(t[1]) - mesh.point(t[0]) };
    const double area = 0.5 * e[0].cross(e[1]).norm();
    const double l2[3] = { e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm() };
    const double longest = std::max({ l2[0], l2[1], l2[2] });
    std::array<double, 3>& c = corner[f];
    if (isZeroArea(2.0 * area, longest))
    {
      c = { 0.0, 0.0, 0.0 };
      continue;
    }
    // Barycentric weights of the circumcentre, l_j^2 (l_j1^2 + l_j2^2 - l_j^2), written with the
    // dot product of the corner's edges (l_j1^2 + l_j2^2 - l_j^2 = -2 e_j1 . e_j2): the sum of
    // squared lengths cancels catastrophically on needle triangles. A negative one marks an
    // obtuse corner; a right angle (0) belongs to the circumcentre case.
    const double ew[3] = { -2.0 * l2[0] * e[1].dot(e[2]), -2.0 * l2[1] * e[2].dot(e[0]),
      -2.0 * l2[2] * e[0].dot(e[1]) };
    bool obtuse = false;
    for (int j = 0; j < 3 && !obtuse; ++j)
    {
      if (ew[j] < 0.0)
      {
        const int j1 = (j + 1) % 3;
        const int j2 = (j + 2) % 3;
        c[j1] = -0.25 * l2[j2] * area / e[j].dot(e[j2]);
        c[j2] = -0.25 * l2[j1] * area / e[j].dot(e[j1]);
        c[j] = area - c[j1] - c[j2];
        if (!std::isfinite(c[j]))
        {
          // Rounding of very unequal squared lengths made a right angle elsewhere look obtuse
          // here, and a cosine of zero divided the area: use the mixed area instead (Meyer et
          // al. 2003, Section 3.3: half for the obtuse corner, a quarter for each other).
          c[j] = 0.5 * area;
          c[j1] = c[j2] = 0.25 * area;
        }
        obtuse = true;
      }
    }
    if (!obtuse)
    {
      const double scale = 0.5 * area / (ew[0] + ew[1] + ew[2]);
      for (int j = 0; j < 3; ++j)
      {
        c[j] = scale * (ew[(j + 1) % 3] + ew[(j + 2) % 3]);
      }
    }
  }
  return corner;
}

SurfaceDescriptors computeSurfaceDescriptors(const TriangleMesh& mesh)
{
  const int n = mesh.vertexCount();
  SurfaceDescriptors out;
  out.normals = computeVertexNormals(mesh);
  const std::vector<std::array<double, 3>> cornerAreas = computeCornerAreas(mesh);
  std::vector<double> pointAreas(n, 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    for (int j = 0; j < 3; ++j)
    {
      pointAreas[mesh.triangle(f)[j]] += cornerAreas[f][j];
    }
  }

  // Initial tangent frame per vertex.
  std::vector<Vector3> frameU(n), frameV(n);
  for (int v = 0; v < n; ++v)
  {
    const Vector3& normal = out.normals[v];
    if (normal.squaredNorm() == 0.0)
    {
      frameU[v] = Vector3::UnitX();
      frameV[v] = Vector3::UnitY();
      continue;
    }
    frameU[v] = anyPerpendicular(normal);
    frameV[v] = normal.cross(frameU[v]);
  }

  // Second fundamental form per triangle from normal differences along its edges, projected
  // into each corner's frame and averaged with Voronoi weights.
  std::vector<double> ku(n, 0.0), kuv(n, 0.0), kv(n, 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    if (cornerAreas[f][0] + cornerAreas[f][1] + cornerAreas[f][2] == 0.0)
    {
      continue;
    }
    const Vector3 e[3] = { mesh.point(t[2]) - mesh.point(t[1]), mesh.point(t[0]) - mesh.point(t[2]),
      mesh.point(t[1]) - mesh.point(t[0]) };
    const Vector3 tangent = e[0].normalized();
    const Vector3 faceNormal = e[0].cross(e[1]);
    const Vector3 binormal = faceNormal.cross(tangent).normalized();
    double m[3] = { 0.0, 0.0, 0.0 };
    double w00 = 0.0, w01 = 0.0, w22 = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      const double u = e[j].dot(tangent);
      const double v = e[j].dot(binormal);
      w00 += u * u;
      w01 += u * v;
      w22 += v * v;
      const Vector3 dn = out.normals[t[(j + 2) % 3]] - out.normals[t[(j + 1) % 3]];
      const double dnu = dn.dot(tangent);
      const double dnv = dn.dot(binormal);
      m[0] += dnu * u;
      m[1] += dnu * v + dnv * u;
      m[2] += dnv * v;
    }
    // Normal equations of the 6 x 3 least-squares problem for (e, f, g).
    Eigen::Matrix3d w;
    w << w00, w01, 0.0, w01, w00 + w22, w01, 0.0, w01, w22;
    const Eigen::Vector3d rhs(m[0], m[1], m[2]);
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(w);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive())
    {
      continue;
    }
    const Eigen::Vector3d II = ldlt.solve(rhs);
    if (!II.allFinite())
    {
      continue;
    }
    for (int j = 0; j < 3; ++j)
    {
      const int vj = t[j];
      if (pointAreas[vj] <= 0.0)
      {
        continue;
      }
      double c1, c12, c2;
      projectTensor(tangent, binormal, II[0], II[1], II[2], frameU[vj], frameV[vj], c1, c12, c2);
      const double weight = cornerAreas[f][j] / pointAreas[vj];
      ku[vj] += weight * c1;
      kuv[vj] += weight * c12;
      kv[vj] += weight * c2;
    }
  }

  out.maximumCurvature.assign(n, 0.0);
  out.minimumCurvature.assign(n, 0.0);
  out.maximumDirections.assign(n, Vector3::Zero());
  out.minimumDirections.assign(n, Vector3::Zero());
  out.meanCurvature.assign(n, 0.0);
  out.gaussianCurvature.assign(n, 0.0);
  for (int v = 0; v < n; ++v)
  {
    const Vector3& normal = out.normals[v];
    if (normal.squaredNorm() == 0.0)
    {
      continue;
    }
    // Jacobi rotation diagonalizing the 2 x 2 tensor.
    double c = 1.0, s = 0.0, tt = 0.0;
    if (kuv[v] != 0.0)
    {
      const double h = 0.5 * (kv[v] - ku[v]) / kuv[v];
      tt = (h < 0.0) ? 1.0 / (h - std::sqrt(1.0 + h * h)) : 1.0 / (h + std::sqrt(1.0 + h * h));
      c = 1.0 / std::sqrt(1.0 + tt * tt);
      s = tt * c;
    }
    double k1 = ku[v] - tt * kuv[v];
    double k2 = kv[v] + tt * kuv[v];
    Vector3 direction1 = c * frameU[v] - s * frameV[v];
    if (k2 > k1)
    {
      std::swap(k1, k2);
      direction1 = s * frameU[v] + c * frameV[v];
    }
    out.maximumCurvature[v] = k1;
    out.minimumCurvature[v] = k2;
    out.maximumDirections[v] = direction1.normalized();
    out.minimumDirections[v] = normal.cross(out.maximumDirections[v]);
    out.meanCurvature[v] = 0.5 * (k1 + k2);
    out.gaussianCurvature[v] = k1 * k2;
  }

  // Concavity (ROI Scissor, Eq. 3) from the one-ring centroid.
  out.concave.assign(n, 0);
  for (int v = 0; v < n; ++v)
  {
    const IndexRange ring = mesh.vertexNeighbors(v);
    if (ring.empty())
    {
      continue;
    }
    Vector3 centroid = Vector3::Zero();
    for (int w : ring)
    {
      centroid += mesh.point(w);
    }
    centroid /= static_cast<double>(ring.size());
    out.concave[v] = (centroid - mesh.point(v)).dot(out.normals[v]) > 0.0 ? 1 : 0;
  }

  // Normal-cone angle (Dekkers and Kobbelt 2014, Eq. 4): the widest pair of face normals.
  std::vector<Vector3> faceNormals(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const double twiceArea = cornerAreas[f][0] + cornerAreas[f][1] + cornerAreas[f][2];
    faceNormals[f] = twiceArea > 0.0
      ? Vector3((mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).normalized())
      : Vector3(Vector3::Zero());
  }
  out.normalConeAngle.assign(n, 0.0);
  for (int v = 0; v < n; ++v)
  {
    const IndexRange faces = mesh.vertexFaces(v);
    double smallestDot = 1.0;
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
      const Vector3& a = faceNormals[faces[i]];
      if (a.squaredNorm() == 0.0)
      {
        continue;
      }
      for (std::size_t j = i + 1; j < faces.size(); ++j)
      {
        const Vector3& b = faceNormals[faces[j]];
        if (b.squaredNorm() != 0.0)
        {
          smallestDot = std::min(smallestDot, a.dot(b));
        }
      }
    }
    out.normalConeAngle[v] = std::acos(std::clamp(smallestDot, -1.0, 1.0));
  }

  // Never NaN output: a value that could not be computed is refused, naming its vertex.
  for (int v = 0; v < n; ++v)
  {
    if (!std::isfinite(out.maximumCurvature[v]) || !std::isfinite(out.minimumCurvature[v]) ||
      !out.normals[v].allFinite() || !out.maximumDirections[v].allFinite() || !out.minimumDirections[v].allFinite())
    {
      throw Error("the curvature at vertex " + std::to_string(v) +
        " is not a finite number (its triangles are too degenerate to estimate it)");
    }
  }
  return out;
}

} // namespace kerf
