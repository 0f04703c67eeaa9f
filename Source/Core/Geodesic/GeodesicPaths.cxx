// Streamline tracing across triangles, shortest paths under either metric, and closed geodesic loops.
#include "Geodesic/GeodesicPaths.h"

#include "CacheKey.h"
#include "Error.h"
#include "Geodesic/SurfaceLocation.h"
#include "Geodesic/VectorDijkstra.h"
#include "Numerics/FieldGradient.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace kerf
{

std::vector<Vector3> descentDirections(
  const TriangleMesh& mesh, const std::vector<Vector3>& faceGradients, const AnisotropicMetric& metric)
{
  std::vector<Vector3> directions(mesh.vertexCount(), Vector3::Zero());
  std::vector<double> weight(mesh.vertexCount(), 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Vector3& g = faceGradients[f];
    if (!g.allFinite() || g.squaredNorm() == 0.0)
    {
      continue;
    }
    const Triangle& t = mesh.triangle(f);
    const double area = 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
    for (int v : t)
    {
      directions[v] += area * g;
      weight[v] += area;
    }
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (weight[v] > 0.0)
    {
      if (metric.isotropic)
      {
        directions[v] = -directions[v] / weight[v];
        continue;
      }
      // In the tangent plane: across a crease the mean gradient leans out of it, and M^-1 would
      // shrink its tangent part and leave that lean.
      const Vector3& normal = metric.normals[v];
      const Vector3 tangent = directions[v] - directions[v].dot(normal) * normal;
      const Vector3 descent = -(metric.inverses[v] * tangent) / weight[v];
      directions[v] = descent - descent.dot(normal) * normal;
    }
  }
  return directions;
}

std::vector<double> segmentLengths(const TriangleMesh& mesh, const SurfaceCurve& curve, const AnisotropicMetric& metric)
{
  const int segments = segmentCount(curve);
  std::vector<double> lengths(static_cast<std::size_t>(std::max(segments, 0)));
  for (int i = 0; i < segments; ++i)
  {
    const Vector3& a = curve.points[i];
    const Vector3& b = curve.points[(i + 1) % curve.points.size()];
    const Vector3 d = b - a;
    if (metric.isotropic)
    {
      lengths[i] = d.norm();
      continue;
    }
    const int f = curve.faces[i];
    const Eigen::Matrix3d tensor = metric.tensorAt(mesh, f, barycentricInFace(mesh, f, 0.5 * (a + b)));
    lengths[i] = std::sqrt(std::max(d.dot(tensor * d), 0.0));
  }
  return lengths;
}

double curveLength(const TriangleMesh& mesh, const SurfaceCurve& curve, const AnisotropicMetric& metric)
{
  double length = 0.0;
  for (double segment : segmentLengths(mesh, curve, metric))
  {
    length += segment;
  }
  return length;
}

namespace
{
constexpr double Tiny = 1e-12;
// A source point whose barycentric coordinate of a corner is within this of 1 is near the corner
// (a corner given in single precision is about 1e-7 from it).
constexpr double NearCorner = 1e-3;

// The plane of a triangle: unit normal and the gradients of the barycentric coordinates.
struct FaceFrame
{
  Vector3 normal = Vector3::Zero();
  std::array<Vector3, 3> barycentricGradients;
  double size = 0.0; // sqrt of twice the area
};

FaceFrame faceFrame(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  FaceFrame frame;
  const Vector3 cross = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0]));
  const double twiceArea = cross.norm();
  frame.size = std::sqrt(twiceArea);
  if (twiceArea <= 0.0)
  {
    frame.barycentricGradients.fill(Vector3::Zero());
    return frame;
  }
  frame.normal = cross / twiceArea;
  for (int k = 0; k < 3; ++k)
  {
    const Vector3 opposite = mesh.point(t[(k + 2) % 3]) - mesh.point(t[(k + 1) % 3]);
    frame.barycentricGradients[k] = frame.normal.cross(opposite) / twiceArea;
  }
  return frame;
}

int cornerOf(const Triangle& t, int v)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == v)
    {
      return k;
    }
  }
  return -1;
}

// The straight path from x in face g across its shared edge (a, b) to y in the neighbouring
// face, both laid out in the plane: the crossing point, if the segment meets the edge.
bool unfoldedCrossing(const Vector3& x, const Vector3& y, const Vector3& a, const Vector3& b, Vector3& crossing)
{
  const double ab = (b - a).norm();
  if (!(ab > 0.0))
  {
    return false;
  }
  const auto place = [ab](double fromA, double fromB, double side) {
    const double u = (ab * ab + fromA * fromA - fromB * fromB) / (2.0 * ab);
    return Eigen::Vector2d(u, side * std::sqrt(std::max(fromA * fromA - u * u, 0.0)));
  };
  const Eigen::Vector2d px = place((x - a).norm(), (x - b).norm(), 1.0);
  const Eigen::Vector2d py = place((y - a).norm(), (y - b).norm(), -1.0);
  const double height = px.y() - py.y();
  const double u = height > 0.0 ? px.x() + px.y() / height * (py.x() - px.x()) : px.x();
  if (u < 0.0 || u > ab)
  {
    return false;
  }
  crossing = a + (b - a) * (u / ab);
  return true;
}

// Where a traced path may end, looked up by triangle.
class SourceTargets
{
public:
  SourceTargets(const TriangleMesh& mesh, const GeodesicSource& source)
    : Mesh(mesh)
    , Source(source)
    , IsSourceVertex(mesh.vertexCount(), 0)
  {
    for (int v : source.vertices)
    {
      this->IsSourceVertex[v] = 1;
    }
    // A point on an edge or at a corner lies in every triangle there: a path arriving through any
    // of them ends on it. A point near a corner ends paths arriving around that corner through
    // the corner: there the field is a cone whose apex is the corner, the corner's descent
    // direction is meaningless, and a path circled it to find the point's own triangle.
    for (std::size_t i = 0; i < source.points.size(); ++i)
    {
      const SurfacePoint& point = source.points[i];
      const std::vector<int> holding = facesHolding(mesh, point);
      for (int f : holding)
      {
        this->PointFaces.emplace(f, static_cast<int>(i));
      }
      const Triangle& t = mesh.triangle(point.face);
      for (int k = 0; k < 3; ++k)
      {
        if (point.barycentric[k] < 1.0 - NearCorner)
        {
          continue;
        }
        for (int f : mesh.vertexFaces(t[k]))
        {
          if (!std::binary_search(holding.begin(), holding.end(), f))
          {
            this->CornerFaces.emplace(f, std::make_pair(static_cast<int>(i), t[k]));
          }
        }
      }
    }
    for (std::size_t c = 0; c < source.curves.size(); ++c)
    {
      const int segments = segmentCount(source.curves[c]);
      for (int i = 0; i < segments; ++i)
      {
        this->CurveFaces.emplace(source.curves[c].faces[i], std::make_pair(static_cast<int>(c), i));
      }
    }
  }

  // If the path at x in face f can end, appends its last points and returns true.
  bool finish(int f, const Vector3& x, SurfaceCurve& path) const
  {
    const Triangle& t = this->Mesh.triangle(f);
    for (int v : t)
    {
      if (this->IsSourceVertex[v])
      {
        append(path, this->Mesh.point(v), f);
        return true;
      }
    }
    const auto point = this->PointFaces.find(f);
    if (point != this->PointFaces.end())
    {
      append(path, surfacePosition(this->Mesh, this->Source.points[point->second]), f);
      return true;
    }
    const auto corner = this->CornerFaces.find(f);
    if (corner != this->CornerFaces.end())
    {
      const SurfacePoint& end = this->Source.points[corner->second.first];
      append(path, this->Mesh.point(corner->second.second), f);
      append(path, surfacePosition(this->Mesh, end), end.face);
      return true;
    }
    const auto range = this->CurveFaces.equal_range(f);
    if (range.first != range.second)
    {
      double best = std::numeric_limits<double>::infinity();
      Vector3 nearest = x;
      for (auto it = range.first; it != range.second; ++it)
      {
        const SurfaceCurve& curve = this->Source.curves[it->second.first];
        const int i = it->second.second;
        const Vector3& a = curve.points[i];
        const Vector3& b = curve.points[(i + 1) % curve.points.size()];
        const Vector3 d = b - a;
        const double s = d.squaredNorm() > 0.0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        const Vector3 q = a + s * d;
        if ((q - x).norm() < best)
        {
          best = (q - x).norm();
          nearest = q;
        }
      }
      append(path, nearest, f);
      return true;
    }
    // Straight across an edge into a source point's triangle.
    for (int k = 0; k < 3; ++k)
    {
      const int g = this->Mesh.faceNeighbor(f, k);
      const auto across = g >= 0 ? this->PointFaces.find(g) : this->PointFaces.end();
      if (across == this->PointFaces.end())
      {
        continue;
      }
      const Vector3 y = surfacePosition(this->Mesh, this->Source.points[across->second]);
      Vector3 crossing;
      if (unfoldedCrossing(x, y, this->Mesh.point(t[k]), this->Mesh.point(t[(k + 1) % 3]), crossing))
      {
        append(path, crossing, f);
        append(path, y, g);
        return true;
      }
    }
    return false;
  }

  static void append(SurfaceCurve& path, const Vector3& p, int face)
  {
    if ((p - path.points.back()).squaredNorm() > 0.0)
    {
      path.faces.push_back(face);
      path.points.push_back(p);
    }
  }

private:
  const TriangleMesh& Mesh;
  const GeodesicSource& Source;
  std::vector<char> IsSourceVertex;
  std::multimap<int, int> PointFaces;
  std::multimap<int, std::pair<int, int>> CornerFaces; // face -> (source point, the corner it is near)
  std::multimap<int, std::pair<int, int>> CurveFaces;
};

// The streamline integrator's state: a point in a face.
struct Tracer
{
  const TriangleMesh& mesh;
  const std::vector<Vector3>& directions;
  int face = -1;
  Vector3 barycentric = Vector3::Zero();
  Vector3 position = Vector3::Zero();

  Vector3 directionIn(int f, const Vector3& b, const FaceFrame& frame) const
  {
    const Triangle& t = this->mesh.triangle(f);
    Vector3 w = b[0] * this->directions[t[0]] + b[1] * this->directions[t[1]] + b[2] * this->directions[t[2]];
    w -= w.dot(frame.normal) * frame.normal;
    return w;
  }
};
} // namespace

SurfacePath traceToSource(const TriangleMesh& mesh, const std::vector<Vector3>& directions, const SurfacePoint& start,
  const GeodesicSource& source, const AnisotropicMetric& metric)
{
  checkSurfacePoint(mesh, start, "the path's start");
  checkGeodesicSource(mesh, source);
  if (static_cast<int>(directions.size()) != mesh.vertexCount())
  {
    throw Error("the path's direction field needs one vector per vertex");
  }
  const SourceTargets targets(mesh, source);
  SurfacePath result;
  SurfaceCurve& path = result.curve;
  Tracer tracer{ mesh, directions, start.face, start.barycentric, surfacePosition(mesh, start) };
  path.points.push_back(tracer.position);

  const long long limit = 10LL * mesh.faceCount() + 1000;
  int previousFace = -1; // the face we just came from, to detect a field converging onto an edge
  for (long long step = 0; step < limit; ++step)
  {
    const int f = tracer.face;
    if (targets.finish(f, tracer.position, path))
    {
      std::reverse(path.points.begin(), path.points.end());
      std::reverse(path.faces.begin(), path.faces.end());
      result.length = curveLength(mesh, path, metric);
      return result;
    }
    const Triangle& t = mesh.triangle(f);
    const FaceFrame frame = faceFrame(mesh, f);
    Vector3 w = tracer.directionIn(f, tracer.barycentric, frame);
    const double scale = std::max({ directions[t[0]].norm(), directions[t[1]].norm(), directions[t[2]].norm() });
    // At a vertex (one coordinate ~1) leave through the triangle whose corner holds the vertex's
    // own direction.
    int atCorner = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (tracer.barycentric[k] > 1.0 - 1e-9)
      {
        atCorner = k;
      }
    }
    if (atCorner >= 0)
    {
      const int v = t[atCorner];
      const Vector3& wv = directions[v];
      int chosen = -1;
      double bestScore = -std::numeric_limits<double>::infinity();
      for (int g : mesh.vertexFaces(v))
      {
        if (targets.finish(g, tracer.position, path))
        {
          std::reverse(path.points.begin(), path.points.end());
          std::reverse(path.faces.begin(), path.faces.end());
          result.length = curveLength(mesh, path, metric);
          return result;
        }
        const Triangle& u = mesh.triangle(g);
        const int kv = cornerOf(u, v);
        const FaceFrame gf = faceFrame(mesh, g);
        const Vector3 wp = wv - wv.dot(gf.normal) * gf.normal;
        // Rates of the other two coordinates along wp: both >= 0 inside the corner.
        const double r1 = gf.barycentricGradients[(kv + 1) % 3].dot(wp);
        const double r2 = gf.barycentricGradients[(kv + 2) % 3].dot(wp);
        const double score = std::min(r1, r2) * gf.size;
        if (score > bestScore)
        {
          bestScore = score;
          chosen = g;
        }
      }
      if (chosen < 0 || wv.squaredNorm() == 0.0)
      {
        throw Error("the geodesic path stopped at a vertex where the distance field has no descent direction");
      }
      if (bestScore < -1e-9 * wv.norm())
      {
        // No triangle holds the direction (a boundary vertex or a saddle): follow the edge that
        // points most along it.
        int next = -1;
        double bestCosine = 0.0;
        for (int u : mesh.vertexNeighbors(v))
        {
          const Vector3 e = mesh.point(u) - mesh.point(v);
          const double cosine = e.dot(wv) / (e.norm() * wv.norm());
          if (cosine > bestCosine)
          {
            bestCosine = cosine;
            next = u;
          }
        }
        if (next < 0)
        {
          throw Error("the geodesic path stopped at a vertex where the distance field has no descent direction");
        }
        int edgeFace = -1;
        for (int g : mesh.vertexFaces(v))
        {
          if (cornerOf(mesh.triangle(g), next) >= 0)
          {
            edgeFace = g;
            break;
          }
        }
        SourceTargets::append(path, mesh.point(next), edgeFace);
        tracer.face = edgeFace;
        tracer.position = mesh.point(next);
        tracer.barycentric = Vector3::Zero();
        tracer.barycentric[cornerOf(mesh.triangle(edgeFace), next)] = 1.0;
        previousFace = -1;
        continue;
      }
      if (chosen != f)
      {
        tracer.face = chosen;
        tracer.barycentric = Vector3::Zero();
        tracer.barycentric[cornerOf(mesh.triangle(chosen), v)] = 1.0;
        previousFace = -1;
        // Nudge off the corner along the vertex direction within the chosen triangle.
        const FaceFrame gf = faceFrame(mesh, chosen);
        w = wv - wv.dot(gf.normal) * gf.normal;
        const Vector3 d = w.normalized();
        Vector3 rates;
        for (int k = 0; k < 3; ++k)
        {
          rates[k] = gf.barycentricGradients[k].dot(d);
        }
        double exit = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k)
        {
          if (rates[k] < -Tiny && tracer.barycentric[k] > 0.0)
          {
            exit = std::min(exit, -tracer.barycentric[k] / rates[k]);
          }
        }
        const double stepLength = std::min(gf.size / 3.0, 0.5 * exit);
        tracer.position += stepLength * d;
        tracer.barycentric += stepLength * rates;
        SourceTargets::append(path, tracer.position, chosen);
        continue;
      }
    }
    if (w.norm() <= 1e-12 * scale || scale == 0.0)
    {
      throw Error("the geodesic path stopped at a critical point of the distance field");
    }
    const Vector3 d = w.normalized();
    Vector3 rates;
    for (int k = 0; k < 3; ++k)
    {
      rates[k] = frame.barycentricGradients[k].dot(d);
    }
    double exit = std::numeric_limits<double>::infinity();
    int exitCorner = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (rates[k] < -Tiny)
      {
        const double s = std::max(tracer.barycentric[k], 0.0) / -rates[k];
        if (s < exit)
        {
          exit = s;
          exitCorner = k;
        }
      }
    }
    const double stepLength = frame.size / 3.0;
    if (exitCorner < 0)
    {
      throw Error("the geodesic path left its triangle in no direction (a degenerate triangle)");
    }
    if (exit > stepLength)
    {
      tracer.position += stepLength * d;
      tracer.barycentric += stepLength * rates;
      SourceTargets::append(path, tracer.position, f);
      previousFace = -1;
      continue;
    }
    // Exit through the edge opposite exitCorner (edge (exitCorner + 1) % 3).
    tracer.position += exit * d;
    tracer.barycentric += exit * rates;
    tracer.barycentric[exitCorner] = 0.0;
    tracer.barycentric = tracer.barycentric.cwiseMax(0.0);
    tracer.barycentric /= tracer.barycentric.sum();
    SourceTargets::append(path, tracer.position, f);
    const int edge = (exitCorner + 1) % 3;
    const int g = mesh.faceNeighbor(f, edge);
    const int a = t[edge], b = t[(edge + 1) % 3];
    const double ba = tracer.barycentric[edge], bb = tracer.barycentric[(edge + 1) % 3];
    // Continue in g unless the field there points back into f (it converges onto the edge), or
    // there is no g: then slide along the edge to the end the direction favours.
    bool slide = g < 0;
    Vector3 inG = Vector3::Zero();
    if (g >= 0)
    {
      const Triangle& u = mesh.triangle(g);
      inG[cornerOf(u, a)] = ba;
      inG[cornerOf(u, b)] = bb;
      const FaceFrame gf = faceFrame(mesh, g);
      const Vector3 wg = tracer.directionIn(g, inG, gf);
      const int opposite = 3 - cornerOf(u, a) - cornerOf(u, b);
      slide = gf.barycentricGradients[opposite].dot(wg) <= 0.0 || g == previousFace;
    }
    if (!slide)
    {
      previousFace = f;
      tracer.face = g;
      tracer.barycentric = inG;
      continue;
    }
    const int end = (mesh.point(b) - mesh.point(a)).dot(d) >= 0.0 ? b : a;
    SourceTargets::append(path, mesh.point(end), f);
    tracer.position = mesh.point(end);
    tracer.barycentric = Vector3::Zero();
    tracer.barycentric[cornerOf(t, end)] = 1.0;
    previousFace = -1;
  }
  throw Error("the geodesic path did not reach the source");
}

int countSelfCrossings(const TriangleMesh& mesh, const SurfaceCurve& curve)
{
  const int segments = segmentCount(curve);
  std::multimap<int, int> byFace;
  for (int i = 0; i < segments; ++i)
  {
    byFace.emplace(curve.faces[i], i);
  }
  const int count = static_cast<int>(curve.points.size());
  int crossings = 0;
  for (auto first = byFace.begin(); first != byFace.end();)
  {
    auto last = byFace.upper_bound(first->first);
    const FaceFrame frame = faceFrame(mesh, first->first);
    const Vector3 origin = mesh.point(mesh.triangle(first->first)[0]);
    const Vector3 axisX = (mesh.point(mesh.triangle(first->first)[1]) - origin).normalized();
    const Vector3 axisY = frame.normal.cross(axisX);
    const auto flat = [&](
                        const Vector3& p) { return Eigen::Vector2d((p - origin).dot(axisX), (p - origin).dot(axisY)); };
    const auto orientation = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
      const Eigen::Vector2d u = b - a, v = c - a;
      return u.x() * v.y() - u.y() * v.x();
    };
    for (auto i = first; i != last; ++i)
    {
      for (auto j = std::next(i); j != last; ++j)
      {
        const int s = i->second, r = j->second;
        if (std::abs(s - r) == 1 || (curve.closed && std::abs(s - r) == segments - 1))
        {
          continue;
        }
        const Eigen::Vector2d a = flat(curve.points[s]), b = flat(curve.points[(s + 1) % count]);
        const Eigen::Vector2d c = flat(curve.points[r]), d = flat(curve.points[(r + 1) % count]);
        const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
        const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
        if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
        {
          ++crossings;
        }
      }
    }
    first = last;
  }
  return crossings;
}

const AnisotropicMetric& anisotropicMetric(const Surface& surface, const AnisotropicMetricOptions& options)
{
  const std::string key = "anisotropic-metric: gamma=" + cacheKey(options.gamma) +
    " measure=" + (options.measure == AnisotropyMeasure::Normalized ? "normalized" : "difference") +
    " umbilic=" + cacheKey(options.umbilicRegularization);
  return surface.derived<AnisotropicMetric>(key, [&surface, &options] {
    if (options.gamma == 0.0)
    {
      // The Euclidean metric needs no curvature.
      AnisotropicMetric metric;
      metric.isotropic = true;
      metric.lambda1.assign(surface.mesh().vertexCount(), 1.0);
      return metric;
    }
    return computeAnisotropicMetric(surface.mesh(), surface.descriptors(), options);
  });
}

GeodesicDistance geodesicDistance(const Surface& surface, const GeodesicSource& source,
  const GeodesicPathOptions& options, const std::vector<int>& targets)
{
  if (!(options.metric.gamma >= 0.0) || !std::isfinite(options.metric.gamma))
  {
    throw Error("the anisotropy gamma must be a finite number >= 0, got " + std::to_string(options.metric.gamma));
  }
  if (options.metric.gamma == 0.0 && !options.vectorDijkstra)
  {
    return HeatGeodesics::of(surface, options.heat).compute(source);
  }
  const TriangleMesh& mesh = surface.mesh();
  VectorDijkstraOptions dijkstra;
  dijkstra.depth = options.depth;
  dijkstra.targets = targets;
  GeodesicDistance result;
  result.distance =
    shortTermVectorDijkstra(mesh, anisotropicMetric(surface, options.metric), source, dijkstra).distance;
  result.faceGradients = computeFaceGradients(mesh, result.distance);
  return result;
}

namespace
{
// The corners of a surface point's triangle.
std::vector<int> cornersOf(const TriangleMesh& mesh, const SurfacePoint& p)
{
  const Triangle& t = mesh.triangle(p.face);
  return { t[0], t[1], t[2] };
}

// The distance field from `from` and its descent directions.
std::vector<Vector3> descentFrom(const Surface& surface, const SurfacePoint& from, const SurfacePoint& to,
  const GeodesicPathOptions& options, const AnisotropicMetric& metric)
{
  GeodesicSource source;
  source.points = { from };
  const GeodesicDistance distance = geodesicDistance(surface, source, options, cornersOf(surface.mesh(), to));
  return descentDirections(surface.mesh(), distance.faceGradients, metric);
}
} // namespace

SurfacePath shortestPath(
  const Surface& surface, const SurfacePoint& from, const SurfacePoint& to, const GeodesicPathOptions& options)
{
  const TriangleMesh& mesh = surface.mesh();
  checkSurfacePoint(mesh, from, "the path's start");
  checkSurfacePoint(mesh, to, "the path's end");
  if (mesh.faceComponent(from.face) != mesh.faceComponent(to.face))
  {
    throw Error("the path's two points lie on different connected components of the mesh; no path joins them");
  }
  const AnisotropicMetric& metric = anisotropicMetric(surface, options.metric);
  const std::vector<Vector3> directions = descentFrom(surface, from, to, options, metric);
  GeodesicSource source;
  source.points = { from };
  return traceToSource(mesh, directions, to, source, metric);
}

GeodesicPolyline geodesicPolyline(const Surface& surface, const std::vector<SurfacePoint>& points, bool closed,
  const GeodesicPathOptions& options, GeodesicLegCache* cache)
{
  const TriangleMesh& mesh = surface.mesh();
  const std::size_t minimum = closed ? 3 : 2;
  if (points.size() < minimum)
  {
    throw Error(std::string(closed ? "a closed geodesic loop" : "a geodesic path") + " needs at least " +
      std::to_string(minimum) + " points, got " + std::to_string(points.size()));
  }
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const std::string name = "path point " + std::to_string(i);
    checkSurfacePoint(mesh, points[i], name.c_str());
    if (mesh.faceComponent(points[i].face) != mesh.faceComponent(points[0].face))
    {
      throw Error(name + " lies on another connected component of the mesh than path point 0; no path joins them");
    }
  }
  const std::size_t legs = closed ? points.size() : points.size() - 1;
  for (std::size_t i = 0; i < legs; ++i)
  {
    const std::size_t j = (i + 1) % points.size();
    if (surfacePosition(mesh, points[i]) == surfacePosition(mesh, points[j]))
    {
      throw Error("path points " + std::to_string(i) + " and " + std::to_string(j) +
        " are the same point of the surface; give each point once");
    }
  }
  GeodesicPolyline result;
  SurfaceCurve& curve = result.path.curve;
  curve.closed = closed;
  // A leg's key: its two points exactly and every option the path depends on.
  const std::string optionsKey = "gamma=" + cacheKey(options.metric.gamma) +
    (options.metric.measure == AnisotropyMeasure::Normalized ? " normalized" : " difference") +
    " umbilic=" + cacheKey(options.metric.umbilicRegularization) + " depth=" + std::to_string(options.depth) +
    (options.vectorDijkstra ? " vector" : " heat") + " " + cacheKey(options.heat);
  const auto pointKey = [](const SurfacePoint& p) {
    return std::to_string(p.face) + ":" + cacheKey(p.barycentric.x()) + "," + cacheKey(p.barycentric.y()) + "," +
      cacheKey(p.barycentric.z());
  };
  std::vector<std::pair<std::string, SurfacePath>> kept;
  if (cache)
  {
    if (cache->Owner != &surface)
    {
      cache->Legs.clear();
      cache->Owner = &surface;
    }
    cache->Computed = 0;
    cache->Reused = 0;
  }
  for (std::size_t i = 0; i < legs; ++i)
  {
    const SurfacePoint& from = points[i];
    const SurfacePoint& to = points[(i + 1) % points.size()];
    SurfacePath leg;
    if (cache)
    {
      const std::string key = pointKey(from) + " " + pointKey(to) + " " + optionsKey;
      const auto found =
        std::find_if(cache->Legs.begin(), cache->Legs.end(), [&key](const auto& entry) { return entry.first == key; });
      if (found != cache->Legs.end())
      {
        leg = found->second;
        ++cache->Reused;
      }
      else
      {
        leg = shortestPath(surface, from, to, options);
        ++cache->Computed;
      }
      kept.emplace_back(key, leg);
    }
    else
    {
      leg = shortestPath(surface, from, to, options);
    }
    // Each leg starts where the previous one ended: keep its first point only for the first leg.
    const std::size_t first = curve.points.empty() ? 0 : 1;
    result.waypoints.push_back(curve.points.empty() ? 0 : static_cast<int>(curve.points.size()) - 1);
    curve.points.insert(curve.points.end(), leg.curve.points.begin() + first, leg.curve.points.end());
    curve.faces.insert(curve.faces.end(), leg.curve.faces.begin(), leg.curve.faces.end());
  }
  if (cache)
  {
    cache->Legs.swap(kept);
  }
  if (closed)
  {
    // The last leg ends on the first point: drop the repeat, its face closes the loop.
    curve.points.pop_back();
  }
  else
  {
    result.waypoints.push_back(static_cast<int>(curve.points.size()) - 1);
  }
  const std::vector<double> lengths = segmentLengths(mesh, curve, anisotropicMetric(surface, options.metric));
  result.arcLength.assign(curve.points.size(), 0.0);
  for (std::size_t i = 0; i < lengths.size(); ++i)
  {
    result.path.length += lengths[i];
    if (i + 1 < curve.points.size())
    {
      result.arcLength[i + 1] = result.path.length;
    }
  }
  result.selfCrossings = countSelfCrossings(mesh, curve);
  return result;
}

GeodesicLoop geodesicLoop(
  const Surface& surface, const std::vector<SurfacePoint>& points, const GeodesicPathOptions& options)
{
  GeodesicPolyline loop = geodesicPolyline(surface, points, true, options);
  return GeodesicLoop{ std::move(loop.path), loop.selfCrossings };
}

} // namespace kerf
