// ROI Scissor's candidate discs, boundary constraints, field on the region, feature points and geodesic boundary.
#include "Geodesic/ROIScissor.h"

#include "CacheKey.h"
#include "Error.h"
#include "Geodesic/SurfaceLocation.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Mesh/Submesh.h"
#include "Numerics/FieldGradient.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <string>

namespace kerf
{

SurfacePoint projectClick(const Surface& surface, const Vector3& position, double tolerance)
{
  return projectOntoSurface(surface, position, tolerance * surface.mesh().boundingBoxDiagonal(), "a click");
}

namespace
{
// The segments [a, b] and [c, d] of one plane cross (proper crossing, or touching at b or d).
bool crosses(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d)
{
  const auto orientation = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const Eigen::Vector2d u = q - p, v = r - p;
    return u.x() * v.y() - u.y() * v.x();
  };
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  // Half-open rules, so that a curve through a shared point is counted once.
  return ((o1 > 0.0) != (o2 > 0.0)) && ((o3 > 0.0) != (o4 > 0.0));
}
} // namespace

std::vector<int> labelCurveSides(const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, int seedFace)
{
  // Curve segments by face.
  std::multimap<int, std::pair<Vector3, Vector3>> segments;
  for (const SurfaceCurve& curve : curves)
  {
    const int count = segmentCount(curve);
    for (int i = 0; i < count; ++i)
    {
      segments.emplace(curve.faces[i], std::make_pair(curve.points[i], curve.points[(i + 1) % curve.points.size()]));
    }
  }
  // Crossings of [from, to] (inside `face`) with the curve segments in that face, in its plane.
  const auto crossings = [&](int face, const Vector3& from, const Vector3& to) {
    const auto range = segments.equal_range(face);
    if (range.first == range.second)
    {
      return 0;
    }
    const Triangle& t = mesh.triangle(face);
    const Vector3 origin = mesh.point(t[0]);
    const Vector3 axisX = (mesh.point(t[1]) - origin).normalized();
    const Vector3 normal = axisX.cross(mesh.point(t[2]) - origin).normalized();
    const Vector3 axisY = normal.cross(axisX);
    const auto flat = [&](
                        const Vector3& p) { return Eigen::Vector2d((p - origin).dot(axisX), (p - origin).dot(axisY)); };
    int count = 0;
    for (auto it = range.first; it != range.second; ++it)
    {
      count += crosses(flat(from), flat(to), flat(it->second.first), flat(it->second.second)) ? 1 : 0;
    }
    return count;
  };
  const auto centroid = [&](int f) {
    const Triangle& t = mesh.triangle(f);
    return Vector3((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
  };
  std::vector<int> labels(mesh.faceCount(), -1);
  std::deque<int> queue;
  labels[seedFace] = 1;
  queue.push_back(seedFace);
  while (!queue.empty())
  {
    const int f = queue.front();
    queue.pop_front();
    const Triangle& t = mesh.triangle(f);
    for (int k = 0; k < 3; ++k)
    {
      const int g = mesh.faceNeighbor(f, k);
      if (g < 0 || labels[g] >= 0)
      {
        continue;
      }
      const Vector3 midpoint = 0.5 * (mesh.point(t[k]) + mesh.point(t[(k + 1) % 3]));
      const int parity = (crossings(f, centroid(f), midpoint) + crossings(g, midpoint, centroid(g))) % 2;
      labels[g] = parity ? 1 - labels[f] : labels[f];
      queue.push_back(g);
    }
  }
  for (int& label : labels)
  {
    label = std::max(label, 0);
  }
  return labels;
}

namespace
{
// The weight of each submesh edge: the whole surface's weight of the same vertex pair.
std::vector<double> submeshWeights(const TriangleMesh& mesh, const Submesh& sub, const std::vector<double>& weights)
{
  std::vector<double> local(sub.mesh.edgeCount(), 0.0);
  for (int e = 0; e < sub.mesh.edgeCount(); ++e)
  {
    const int a = sub.globalVertex[sub.mesh.edgeVertices(e)[0]];
    const int b = sub.globalVertex[sub.mesh.edgeVertices(e)[1]];
    local[e] = weights[edgeBetween(mesh, a, b)];
  }
  return local;
}

void checkRadius(double radius)
{
  if (!std::isfinite(radius) || radius <= 0.0)
  {
    throw Error("a click's radius must be positive and finite, got " + std::to_string(radius));
  }
}
} // namespace

ClickDistances::ClickDistances(std::shared_ptr<const Surface> surface)
  : SurfacePointer(std::move(surface))
{
  if (!this->SurfacePointer)
  {
    throw Error("click distances need a surface");
  }
}

std::shared_ptr<const std::vector<double>> ClickDistances::from(
  const SurfacePoint& point, const HeatGeodesicOptions& options)
{
  const std::string key = cacheKey(options);
  for (const Field& field : this->Fields)
  {
    if (field.point.face == point.face && field.point.barycentric == point.barycentric && field.options == key)
    {
      return field.distance;
    }
  }
  GeodesicSource source;
  source.points = { point };
  auto distance =
    std::make_shared<const std::vector<double>>(HeatGeodesics::of(this->surface(), options).compute(source).distance);
  ++this->Computations;
  this->Fields.push_back({ point, key, distance });
  if (this->Fields.size() > MaximumFields)
  {
    this->Fields.pop_front();
  }
  return distance;
}

GeodesicDiscs geodesicDiscs(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted, double clickTolerance, const HeatGeodesicOptions& heat,
  ClickDistances* cache)
{
  const TriangleMesh& mesh = surface.mesh();
  if (added.empty())
  {
    throw Error("geodesic discs need at least one click that adds a disc");
  }
  GeodesicDiscs discs;
  discs.addedCount = added.size();
  int component = -1;
  for (const std::vector<ROIClick>* clicks : { &added, &subtracted })
  {
    for (const ROIClick& click : *clicks)
    {
      checkRadius(click.radius);
      const SurfacePoint point = projectClick(surface, click.position, clickTolerance);
      const int c = mesh.faceComponent(point.face);
      if (component >= 0 && c != component)
      {
        throw Error("the clicks lie on different connected components of the mesh");
      }
      component = c;
      discs.clicks.push_back(point);
      discs.radii.push_back(click.radius);
      if (cache)
      {
        discs.distances.push_back(cache->from(point, heat));
      }
      else
      {
        GeodesicSource source;
        source.points = { point };
        discs.distances.push_back(
          std::make_shared<const std::vector<double>>(HeatGeodesics::of(surface, heat).compute(source).distance));
      }
    }
  }
  // Zhuang et al. 2014, section 4.1: inside the union of the added discs and outside every
  // subtracted one, at distances d.
  const auto inside = [&](const std::function<double(std::size_t)>& d) {
    bool in = false;
    for (std::size_t i = 0; i < discs.addedCount; ++i)
    {
      in = in || d(i) < discs.radii[i];
    }
    for (std::size_t j = discs.addedCount; j < discs.radii.size(); ++j)
    {
      in = in && !(d(j) < discs.radii[j]);
    }
    return in;
  };
  const int n = mesh.vertexCount();
  discs.vertices.assign(n, 0);
  discs.nearestAdded.assign(n, std::numeric_limits<double>::infinity());
  bool any = false;
  for (int v = 0; v < n; ++v)
  {
    discs.vertices[v] = inside([&](std::size_t i) { return (*discs.distances[i])[v]; }) ? 1 : 0;
    any = any || discs.vertices[v];
    for (std::size_t i = 0; i < discs.addedCount; ++i)
    {
      discs.nearestAdded[v] = std::min(discs.nearestAdded[v], (*discs.distances[i])[v]);
    }
  }
  if (!any)
  {
    throw Error("the discs hold no vertex: the radius is smaller than the distance from the click to its nearest "
                "vertex, or every added click lies inside a subtracted disc");
  }
  bool border = false;
  for (int e = 0; e < mesh.edgeCount() && !border; ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    border = discs.vertices[ev[0]] != discs.vertices[ev[1]];
  }
  if (!border)
  {
    throw Error("the clicks' discs cover their whole component: the radius is larger than the mesh");
  }
  discs.faces.assign(mesh.faceCount(), 0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    discs.faces[f] = inside([&](std::size_t i) {
      const std::vector<double>& d = *discs.distances[i];
      return (d[t[0]] + d[t[1]] + d[t[2]]) / 3.0;
    })
      ? 1
      : 0;
    const double area = 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
    discs.surfaceArea += area;
    discs.area += discs.faces[f] ? area : 0.0;
  }
  return discs;
}

GeodesicDiscRegion geodesicDiscRegion(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted, const ROIScissorOptions& options, ClickDistances* cache)
{
  const TriangleMesh& mesh = surface.mesh();
  if (!(options.innerFraction > 0.0 && options.innerFraction < 1.0))
  {
    throw Error("ROI Scissor's inner fraction must be in (0, 1)");
  }
  const GeodesicDiscs discs =
    geodesicDiscs(surface, added, subtracted, options.clickTolerance, options.paths.heat, cache);
  GeodesicDiscRegion region;
  region.clicks = discs.clicks;
  region.candidate = discs.vertices;
  region.candidateFaces = discs.faces;
  const int n = mesh.vertexCount();
  const std::size_t addedCount = discs.addedCount;
  std::vector<char> one(n, 0), zero(n, 0);
  for (int v = 0; v < n; ++v)
  {
    for (std::size_t i = 0; i < addedCount; ++i)
    {
      if ((*discs.distances[i])[v] < options.innerFraction * discs.radii[i])
      {
        one[v] = 1;
      }
    }
  }
  for (std::size_t i = 0; i < addedCount; ++i)
  {
    // At least the corner nearest to the click.
    const SurfacePoint& p = region.clicks[i];
    int nearest = 0;
    p.barycentric.maxCoeff(&nearest);
    one[mesh.triangle(p.face)[nearest]] = 1;
  }
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    if (region.candidate[ev[0]] != region.candidate[ev[1]])
    {
      zero[ev[0]] = zero[ev[1]] = 1;
    }
  }
  for (int v = 0; v < n; ++v)
  {
    if (one[v] && !region.candidate[v])
    {
      one[v] = 0; // a click inside a subtracted disc
    }
    if (one[v] && zero[v])
    {
      throw Error("a click's inner vertices reach the border of its region: the radius is too small for the mesh");
    }
    if (one[v])
    {
      region.oneVertices.push_back(v);
    }
    if (zero[v])
    {
      region.zeroVertices.push_back(v);
    }
  }
  if (region.oneVertices.empty())
  {
    throw Error("every added click lies inside a subtracted disc");
  }
  return region;
}

ROIScissorResult roiScissor(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted, const ROIScissorOptions& options, ClickDistances* distances)
{
  const TriangleMesh& mesh = surface.mesh();
  if (options.isolineCount < 1 || !(options.segmentFraction > 0.0))
  {
    throw Error("ROI Scissor's isoline count and segment fraction must be positive");
  }
  ROIScissorResult result;
  const int n = mesh.vertexCount();
  GeodesicDiscRegion region = geodesicDiscRegion(surface, added, subtracted, options, distances);
  result.clicks = std::move(region.clicks);
  result.candidate = std::move(region.candidate);
  result.oneVertices = std::move(region.oneVertices);
  result.zeroVertices = std::move(region.zeroVertices);

  // The field on the region's faces only (a submesh), weights from the whole surface.
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    if (result.candidate[t[0]] || result.candidate[t[1]] || result.candidate[t[2]])
    {
      result.regionFaces.push_back(f);
    }
  }
  const Submesh sub = extractSubmesh(mesh, result.regionFaces);
  const std::vector<double> weights = submeshWeights(mesh, sub, surface.laplacianWeights(options.weights).weights);
  FieldConstraints constraints;
  for (int v : result.oneVertices)
  {
    constraints.dirichletVertices.push_back(sub.localVertex[v]);
    constraints.dirichletValues.push_back(1.0);
  }
  for (int v : result.zeroVertices)
  {
    constraints.dirichletVertices.push_back(sub.localVertex[v]);
    constraints.dirichletValues.push_back(0.0);
  }
  HarmonicFieldSolver solver;
  const std::vector<double> field = solver.solve(sub.mesh, weights, constraints).field;
  result.field.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t local = 0; local < sub.globalVertex.size(); ++local)
  {
    result.field[sub.globalVertex[local]] = field[local];
  }

  // Section 4.2: the best-scored isoline.
  const std::vector<double> magnitudes = faceGradientMagnitudes(sub.mesh, field);
  const std::vector<IsovalueScore> scores = scoreIsovalues(sub.mesh, field, magnitudes, options.isolineCount);
  if (scores.empty())
  {
    throw Error("ROI Scissor's field is constant on its region");
  }
  const auto best = std::max_element(
    scores.begin(), scores.end(), [](const IsovalueScore& a, const IsovalueScore& b) { return a.score < b.score; });
  result.isovalue = best->value;
  result.score = best->score;

  // Section 4.3: feature points on each closed component, joined by anisotropic geodesics.
  const SurfaceDescriptors& descriptors = surface.descriptors();
  for (const Isoline& isoline : extractIsolines(sub.mesh, field, result.isovalue))
  {
    if (!isoline.closed || isoline.faces.size() < 3)
    {
      continue;
    }
    SurfaceCurve curve;
    curve.closed = true;
    curve.points = isoline.points;
    for (int f : isoline.faces)
    {
      curve.faces.push_back(sub.globalFace[f]);
    }
    const int crossed = static_cast<int>(curve.faces.size());
    const int parts = std::max(3, static_cast<int>(std::lround(options.segmentFraction * crossed)));
    std::vector<int> bestFace(parts, -1);
    std::vector<double> bestConcavity(parts, -std::numeric_limits<double>::infinity());
    double arc = 0.0;
    for (int i = 0; i < crossed; ++i)
    {
      const double segment = (curve.points[(i + 1) % crossed] - curve.points[i]).norm();
      const double middle = arc + 0.5 * segment;
      arc += segment;
      const int part = std::min(parts - 1, static_cast<int>(middle / isoline.length * parts));
      const Triangle& t = mesh.triangle(curve.faces[i]);
      // Mean curvature at the centroid, positive where concave (section 3.1's H).
      const double concavity =
        -(descriptors.meanCurvature[t[0]] + descriptors.meanCurvature[t[1]] + descriptors.meanCurvature[t[2]]) / 3.0;
      if (concavity > bestConcavity[part])
      {
        bestConcavity[part] = concavity;
        bestFace[part] = curve.faces[i];
      }
    }
    std::vector<SurfacePoint> features;
    for (int f : bestFace)
    {
      if (f >= 0)
      {
        SurfacePoint p;
        p.face = f;
        p.barycentric = Vector3::Constant(1.0 / 3.0);
        features.push_back(p);
      }
    }
    if (features.size() < 3)
    {
      continue;
    }
    result.boundaries.push_back(geodesicLoop(surface, features, options.paths));
    result.featurePoints.push_back(std::move(features));
    result.isolines.push_back(std::move(curve));
  }
  if (result.boundaries.empty())
  {
    throw Error("ROI Scissor's best isoline has no closed component to bound a region");
  }
  std::vector<SurfaceCurve> loops;
  for (const GeodesicLoop& loop : result.boundaries)
  {
    loops.push_back(loop.path.curve);
  }
  result.faceLabels = labelCurveSides(mesh, loops, result.clicks.front().face);
  // The boundary lies in the candidate region, so the side holding the click does too. A loop
  // that the side labels cross without separating (a loop within a few triangles, around the
  // inner constraints) leaves the click's side spreading past the region: the region is then the
  // best isoline's side instead, the faces of the region at or above the isovalue that are
  // connected to the click's face.
  const long inside = std::count(result.faceLabels.begin(), result.faceLabels.end(), 1);
  if (inside > static_cast<long>(result.regionFaces.size()))
  {
    result.boundaryEncloses = false;
    std::vector<int> localFace(mesh.faceCount(), -1);
    for (std::size_t local = 0; local < sub.globalFace.size(); ++local)
    {
      localFace[sub.globalFace[local]] = static_cast<int>(local);
    }
    const auto above = [&](int local) {
      const Triangle& t = sub.mesh.triangle(local);
      return (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0 >= result.isovalue;
    };
    std::fill(result.faceLabels.begin(), result.faceLabels.end(), 0);
    const int seed = localFace[result.clicks.front().face];
    if (seed >= 0)
    {
      std::vector<int> stack{ seed };
      result.faceLabels[sub.globalFace[seed]] = 1;
      while (!stack.empty())
      {
        const int f = stack.back();
        stack.pop_back();
        for (int k = 0; k < 3; ++k)
        {
          const int g = sub.mesh.faceNeighbor(f, k);
          if (g >= 0 && !result.faceLabels[sub.globalFace[g]] && above(g))
          {
            result.faceLabels[sub.globalFace[g]] = 1;
            stack.push_back(g);
          }
        }
      }
    }
  }
  return result;
}

} // namespace kerf
