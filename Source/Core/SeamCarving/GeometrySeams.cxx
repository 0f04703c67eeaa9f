// Geometry seam carving's preprocessing (Dekkers and Kobbelt 2014, section 3.2).
#include "SeamCarving/GeometrySeams.h"

#include "Error.h"
#include "Geodesic/GraphDistance.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MinimumCut.h"
#include "Mesh/Submesh.h"
#include "Numerics/LaplacianWeights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace kerf
{
namespace
{

int regionOfValue(double value)
{
  return value == 0.0 ? 0 : value == 1.0 ? 1 : value == 2.0 ? 2 : -1;
}

std::string regionName(int label)
{
  return label == 2 ? "handle" : label == 1 ? "modeling" : "fixed";
}

// The per-vertex labels (-1 for points used by no triangle), checked.
std::vector<int> readRegions(const TriangleMesh& mesh, const std::vector<double>& region)
{
  if (static_cast<int>(region.size()) != mesh.vertexCount())
  {
    throw Error("the region array has " + std::to_string(region.size()) + " values for " +
      std::to_string(mesh.vertexCount()) + " points");
  }
  std::vector<int> labels(region.size(), -1);
  int counts[3] = { 0, 0, 0 };
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (mesh.vertexFaces(v).empty())
    {
      continue;
    }
    labels[v] = regionOfValue(region[v]);
    if (labels[v] < 0)
    {
      std::ostringstream value;
      value << region[v];
      throw Error("point " + std::to_string(v) + " has the region value " + value.str() +
        "; the values are 0 (fixed), 1 (modeling) and 2 (handle)");
    }
    ++counts[labels[v]];
  }
  if (counts[2] == 0)
  {
    throw Error("no point is in the handle region (region value 2)");
  }
  if (counts[0] == 0)
  {
    throw Error("no point is in the fixed region (region value 0)");
  }
  if (counts[1] == 0)
  {
    throw Error("no point is in the modeling region (region value 1)");
  }
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const auto& ends = mesh.edgeVertices(e);
    if (labels[ends[0]] + labels[ends[1]] == 2 && labels[ends[0]] != 1)
    {
      throw Error("handle point " + std::to_string(labels[ends[0]] == 2 ? ends[0] : ends[1]) + " and fixed point " +
        std::to_string(labels[ends[0]] == 2 ? ends[1] : ends[0]) +
        " share an edge: the modeling region must lie between the handle and the fixed region");
    }
  }
  return labels;
}

// The modeling region as a mesh of its own, with the maps back to the input mesh.
struct ModelingRegion
{
  Submesh sub;
  std::vector<int> edges; // input edge of each region edge
  std::vector<int> handleLoop, fixedLoop;
};

// The triangles with a modeling point, checked to form a ring (Dekkers and Kobbelt 2014, 3.1).
ModelingRegion makeModelingRegion(const TriangleMesh& mesh, const std::vector<int>& labels)
{
  std::vector<int> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    if (labels[t[0]] == 1 || labels[t[1]] == 1 || labels[t[2]] == 1)
    {
      faces.push_back(f);
    }
  }
  ModelingRegion region;
  region.sub = extractSubmesh(mesh, faces);
  const std::vector<int>& global = region.sub.globalVertex;
  const TriangleMesh& r = region.sub.mesh;
  if (r.componentCount() != 1)
  {
    throw Error("the modeling region (region value 1) has " + std::to_string(r.componentCount()) +
      " separate parts; it must be one ring between the handle and the fixed region");
  }
  std::vector<const std::vector<int>*> loops[3];
  for (const std::vector<int>& loop : r.boundaryLoops())
  {
    int kind = labels[global[loop.front()]];
    for (int v : loop)
    {
      if (labels[global[v]] == 1)
      {
        throw Error("the modeling region reaches the surface's border at point " + std::to_string(global[v]) +
          "; it must be surrounded by the handle and the fixed region");
      }
      kind = labels[global[v]];
    }
    loops[kind].push_back(&loop);
  }
  for (int kind : { 2, 0 })
  {
    if (loops[kind].size() != 1)
    {
      throw Error("the modeling region meets the " + regionName(kind) + " region along " +
        std::to_string(loops[kind].size()) + " boundary loops; a ring meets it along one");
    }
  }
  const int euler = r.vertexCount() - r.edgeCount() + r.faceCount();
  if (euler != 0)
  {
    throw Error(
      "the modeling region is not a ring: its Euler characteristic is " + std::to_string(euler) + " (a ring's is 0)");
  }
  region.handleLoop = *loops[2].front();
  region.fixedLoop = *loops[0].front();
  for (int e = 0; e < r.edgeCount(); ++e)
  {
    const auto& ends = r.edgeVertices(e);
    region.edges.push_back(edgeBetween(mesh, global[ends[0]], global[ends[1]]));
  }
  return region;
}

void checkOptions(const GeometrySeamsOptions& options)
{
  auto checkCount = [](int value, int most, const char* name) {
    if (value < 1 || value > most)
    {
      throw Error(std::string("the ") + name + " is " + std::to_string(value) + "; it must lie in [1, " +
        std::to_string(most) + "]");
    }
  };
  checkCount(options.ringCount, 100000, "number of rings");
  checkCount(options.isoContourCount, 10000, "number of iso-contours");
  checkCount(options.sectorCount, 10000, "number of sectors");
  for (double weight : { options.alpha, options.beta, options.gamma })
  {
    if (!std::isfinite(weight) || weight < 0.0)
    {
      throw Error("the edge-cost weights alpha, beta and gamma must be finite and >= 0 (got " +
        std::to_string(options.alpha) + ", " + std::to_string(options.beta) + ", " + std::to_string(options.gamma) +
        ")");
    }
  }
  if (options.alpha + options.beta + options.gamma <= 0.0)
  {
    throw Error("the edge-cost weights alpha, beta and gamma are all 0; at least one must be positive");
  }
}

// Maps values linearly to [0, 1] (all 0 when they are equal), as the paper normalises each term.
void normalise(std::vector<double>& values)
{
  if (values.empty())
  {
    return;
  }
  const auto range = std::minmax_element(values.begin(), values.end());
  const double low = *range.first, span = *range.second - *range.first;
  for (double& value : values)
  {
    value = span > 0.0 ? (value - low) / span : 0.0;
  }
}

// Divides positive values by their maximum, into (0, 1], which keeps their ratios. mu(e) is
// scaled so, not shifted: on a tube with a knob the iso-contours differ in length by a few
// percent only, and shifted to start at 0 that difference became the term's whole range, making
// the edges of the longest contour, the one across the knob, the cheapest of the region.
void scaleToMaximum(std::vector<double>& values)
{
  const double high = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
  for (double& value : values)
  {
    value = high > 0.0 ? value / high : 0.0;
  }
}

double polylineLength(const TriangleMesh& mesh, const std::vector<int>& vertices, bool closed)
{
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i)
  {
    length += (mesh.point(vertices[i + 1]) - mesh.point(vertices[i])).norm();
  }
  if (closed && vertices.size() > 1)
  {
    length += (mesh.point(vertices.front()) - mesh.point(vertices.back())).norm();
  }
  return length;
}

SeamContour vertexContour(
  const TriangleMesh& mesh, const std::vector<int>& vertices, bool closed, SeamContour::Kind kind, int index)
{
  SeamContour contour;
  contour.kind = kind;
  contour.index = index;
  contour.closed = closed;
  for (int v : vertices)
  {
    contour.points.push_back(mesh.point(v));
  }
  contour.length = polylineLength(mesh, vertices, closed);
  return contour;
}

// A minimum cut of the region's edge graph with the given capacities (kerf::minimumCut);
// `sources` and `sinks` are tied to the terminals with capacity `terminal`.
MinimumCut minimumCut(const TriangleMesh& mesh, const std::vector<double>& capacity, const std::vector<int>& sources,
  const std::vector<int>& sinks, double terminal)
{
  std::vector<std::array<int, 2>> edges(static_cast<std::size_t>(mesh.edgeCount()));
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    edges[e] = mesh.edgeVertices(e);
  }
  return kerf::minimumCut(mesh.vertexCount(), edges, capacity, sources, sinks, terminal);
}

// The sector contours (Dekkers and Kobbelt 2014, 3.2.1): from equally spaced points of the
// handle boundary, the shortest edge path to the next iso-contour's vertices, iso-contour after
// iso-contour, up to the fixed boundary; loops removed.
std::vector<std::vector<int>> traceSectorContours(
  const ModelingRegion& region, const std::vector<std::vector<int>>& isoVertices, int sectorCount)
{
  const TriangleMesh& mesh = region.sub.mesh;
  std::vector<std::vector<double>> distance;
  for (std::size_t j = 1; j < isoVertices.size(); ++j)
  {
    distance.push_back(edgeGraphDistances(mesh, isoVertices[j]));
  }
  const std::vector<int>& loop = region.handleLoop;
  std::vector<double> arc(loop.size() + 1, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
  {
    arc[i + 1] = arc[i] + (mesh.point(loop[(i + 1) % loop.size()]) - mesh.point(loop[i])).norm();
  }
  std::vector<int> starts;
  for (int k = 0; k < sectorCount; ++k)
  {
    const double target = arc.back() * k / sectorCount;
    std::size_t best = 0;
    for (std::size_t i = 1; i < loop.size(); ++i)
    {
      best = std::abs(arc[i] - target) < std::abs(arc[best] - target) ? i : best;
    }
    if (std::find(starts.begin(), starts.end(), loop[best]) == starts.end())
    {
      starts.push_back(loop[best]);
    }
  }
  std::vector<char> onHandle(mesh.vertexCount(), 0), onFixed(mesh.vertexCount(), 0);
  for (int v : region.handleLoop)
  {
    onHandle[v] = 1;
  }
  for (int v : region.fixedLoop)
  {
    onFixed[v] = 1;
  }
  std::vector<std::vector<int>> contours;
  for (int start : starts)
  {
    std::vector<int> path{ start };
    for (const std::vector<double>& d : distance)
    {
      int current = path.back();
      while (d[current] > 0.0)
      {
        int next = -1;
        double nextValue = std::numeric_limits<double>::infinity();
        for (int u : mesh.vertexNeighbors(current))
        {
          const double value = d[u] + (mesh.point(u) - mesh.point(current)).norm();
          if (d[u] < d[current] && (value < nextValue || (value == nextValue && u < next)))
          {
            next = u;
            nextValue = value;
          }
        }
        if (next < 0)
        {
          break;
        }
        path.push_back(next);
        current = next;
      }
    }
    // Loops removed; then from the last handle point to the first fixed point after it.
    std::vector<int> simple;
    std::vector<int> position(mesh.vertexCount(), -1);
    for (int v : path)
    {
      if (position[v] >= 0)
      {
        for (std::size_t i = static_cast<std::size_t>(position[v]) + 1; i < simple.size(); ++i)
        {
          position[simple[i]] = -1;
        }
        simple.resize(static_cast<std::size_t>(position[v]) + 1);
        continue;
      }
      position[v] = static_cast<int>(simple.size());
      simple.push_back(v);
    }
    std::size_t first = 0;
    for (std::size_t i = 0; i < simple.size(); ++i)
    {
      first = onHandle[simple[i]] ? i : first;
    }
    std::size_t last = first;
    while (last < simple.size() && !onFixed[simple[last]])
    {
      ++last;
    }
    if (last == simple.size())
    {
      continue; // cannot happen on a connected ring; kept safe
    }
    contours.emplace_back(
      simple.begin() + static_cast<std::ptrdiff_t>(first), simple.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  }
  return contours;
}

// Sector index per region triangle: the triangles connected without crossing a sector contour,
// numbered in order of their first triangle.
std::vector<int> labelSectors(const TriangleMesh& mesh, const std::vector<std::vector<int>>& contours)
{
  std::vector<char> onContour(mesh.edgeCount(), 0);
  for (const std::vector<int>& contour : contours)
  {
    for (std::size_t i = 0; i + 1 < contour.size(); ++i)
    {
      onContour[edgeBetween(mesh, contour[i], contour[i + 1])] = 1;
    }
  }
  std::vector<int> label(mesh.faceCount(), -1);
  int count = 0;
  for (int seed = 0; seed < mesh.faceCount(); ++seed)
  {
    if (label[seed] >= 0)
    {
      continue;
    }
    std::vector<int> stack{ seed };
    label[seed] = count;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && label[g] < 0 && !onContour[mesh.faceEdge(f, k)])
        {
          label[g] = count;
          stack.push_back(g);
        }
      }
    }
    ++count;
  }
  return label;
}

} // namespace

std::vector<int> checkSeamRegions(const TriangleMesh& mesh, const std::vector<double>& region)
{
  return makeModelingRegion(mesh, readRegions(mesh, region)).sub.globalFace;
}

GeometrySeamsResult computeGeometrySeams(const TriangleMesh& mesh, const std::vector<double>& region,
  const std::vector<double>& normalConeAngle, const GeometrySeamsOptions& options)
{
  checkOptions(options);
  if (static_cast<int>(normalConeAngle.size()) != mesh.vertexCount())
  {
    throw Error("the normal-cone angles have " + std::to_string(normalConeAngle.size()) + " values for " +
      std::to_string(mesh.vertexCount()) + " points");
  }
  const std::vector<int> labels = readRegions(mesh, region);
  const ModelingRegion modeling = makeModelingRegion(mesh, labels);
  const TriangleMesh& r = modeling.sub.mesh;
  GeometrySeamsResult result;

  // Harmonic field with the uniform Laplacian, 0 on the handle and 1 on the fixed region
  // (Dekkers and Kobbelt 2014, Eq. 1-2).
  FieldConstraints constraints;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (labels[v] == 0 || labels[v] == 2)
    {
      constraints.dirichletVertices.push_back(v);
      constraints.dirichletValues.push_back(labels[v] == 0 ? 1.0 : 0.0);
    }
  }
  LaplacianWeightOptions uniform;
  uniform.weighting = LaplacianWeighting::Uniform;
  HarmonicFieldSolver solver;
  result.harmonicField = solver.solve(mesh, computeLaplacianWeights(mesh, uniform), constraints).field;
  // The field is clamped to [0, 1] (the maximum principle, up to rounding) and rounded to
  // multiples of 2^-32: the factorization routes differ in the last bits (about 1e-15), and on
  // regular meshes many rings cost nearly the same, so that unrounded the last bits would choose
  // between them. 2^-32 is far below the field's meaningful accuracy on any mesh Kerf handles.
  for (double& value : result.harmonicField)
  {
    value = std::ldexp(std::nearbyint(std::ldexp(std::min(1.0, std::max(0.0, value)), 32)), -32);
  }
  std::vector<double> field(r.vertexCount()), angle(r.vertexCount());
  for (int v = 0; v < r.vertexCount(); ++v)
  {
    field[v] = result.harmonicField[modeling.sub.globalVertex[v]];
    angle[v] = normalConeAngle[modeling.sub.globalVertex[v]];
    if (!std::isfinite(angle[v]))
    {
      throw Error(
        "the normal-cone angle of point " + std::to_string(modeling.sub.globalVertex[v]) + " is not a number");
    }
  }

  // Iso-contours I_j at H = j / m (3.2.1): I_0 and I_m are the region's boundaries; the others
  // are the isolines, with the vertices below each crossed edge as their embedding.
  const int m = options.isoContourCount;
  std::vector<double> isoLength(m + 1, 0.0);
  std::vector<std::vector<int>> isoVertices(m + 1);
  isoVertices[0] = modeling.handleLoop;
  isoVertices[m] = modeling.fixedLoop;
  result.contours.push_back(vertexContour(r, modeling.handleLoop, true, SeamContour::Kind::Iso, 0));
  isoLength[0] = result.contours.back().length;
  for (int j = 1; j < m; ++j)
  {
    const double value = static_cast<double>(j) / m;
    for (const Isoline& line : extractIsolines(r, field, value))
    {
      SeamContour contour;
      contour.index = j;
      contour.points = line.points;
      contour.closed = line.closed;
      contour.length = line.length;
      isoLength[j] += line.length;
      result.contours.push_back(std::move(contour));
    }
    std::vector<char> below(r.vertexCount(), 0);
    for (int e = 0; e < r.edgeCount(); ++e)
    {
      const auto& ends = r.edgeVertices(e);
      const int low = field[ends[0]] <= field[ends[1]] ? ends[0] : ends[1];
      const int high = low == ends[0] ? ends[1] : ends[0];
      if (field[low] <= value && value < field[high] && !below[low])
      {
        below[low] = 1;
        isoVertices[j].push_back(low);
      }
    }
    std::sort(isoVertices[j].begin(), isoVertices[j].end());
  }
  result.contours.push_back(vertexContour(r, modeling.fixedLoop, true, SeamContour::Kind::Iso, m));
  isoLength[m] = result.contours.back().length;

  // mu(v): len_max / len(I_j), interpolated linearly in H between neighbouring iso-contours (3.2.2).
  const double longest = *std::max_element(isoLength.begin(), isoLength.end());
  std::vector<double> mu(r.vertexCount());
  for (int v = 0; v < r.vertexCount(); ++v)
  {
    const int j = std::min(m - 1, static_cast<int>(std::floor(field[v] * m)));
    const double t = field[v] * m - j;
    const double low = isoLength[j] > 0.0 ? longest / isoLength[j] : 1.0;
    const double high = isoLength[j + 1] > 0.0 ? longest / isoLength[j + 1] : 1.0;
    mu[v] = (1.0 - t) * low + t * high;
  }

  // The edge terms of Eq. 3, each normalised to [0, 1] (Dekkers and Kobbelt 2014, 3.2.2): ang(e)
  // and h(e) mapped linearly onto [0, 1], mu(e) >= 1 divided by its maximum (scaleToMaximum).
  std::vector<double> saliency(r.edgeCount()), length(r.edgeCount()), harmonic(r.edgeCount());
  double meanDifference = 0.0;
  for (int e = 0; e < r.edgeCount(); ++e)
  {
    meanDifference += std::abs(field[r.edgeVertices(e)[0]] - field[r.edgeVertices(e)[1]]);
  }
  meanDifference /= std::max(1, r.edgeCount());
  // epsilon of h(e): a tenth of the mean |H(v_i) - H(v_j)|, so that the term does not depend on
  // the mesh's resolution.
  const double epsilon = std::max(0.1 * meanDifference, 1e-12);
  for (int e = 0; e < r.edgeCount(); ++e)
  {
    const int a = r.edgeVertices(e)[0], b = r.edgeVertices(e)[1];
    saliency[e] = 0.5 * (angle[a] + angle[b]);
    length[e] = 0.5 * (mu[a] + mu[b]);
    harmonic[e] = 1.0 / (std::abs(field[a] - field[b]) + epsilon);
  }
  normalise(saliency);
  scaleToMaximum(length);
  normalise(harmonic);
  const double weightSum = options.alpha + options.beta + options.gamma;
  std::vector<double> kappa(r.edgeCount());
  result.saliencyTerm.assign(mesh.edgeCount(), -1.0);
  result.lengthTerm.assign(mesh.edgeCount(), -1.0);
  result.harmonicTerm.assign(mesh.edgeCount(), -1.0);
  result.edgeCost.assign(mesh.edgeCount(), -1.0);
  for (int e = 0; e < r.edgeCount(); ++e)
  {
    kappa[e] = options.alpha * saliency[e] + options.beta * length[e] + options.gamma * harmonic[e];
    const int input = modeling.edges[e];
    result.saliencyTerm[input] = saliency[e];
    result.lengthTerm[input] = length[e];
    result.harmonicTerm[input] = harmonic[e];
    result.edgeCost[input] = kappa[e] / weightSum;
  }
  result.faceCost.assign(mesh.faceCount(), -1.0);
  for (int f = 0; f < r.faceCount(); ++f)
  {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      sum += kappa[r.faceEdge(f, k)] / weightSum;
    }
    result.faceCost[modeling.sub.globalFace[f]] = sum / 3.0;
  }

  // Sector contours and sectors; L is the contour of least integrated saliency (3.2.3).
  const std::vector<std::vector<int>> sectors = traceSectorContours(modeling, isoVertices, options.sectorCount);
  double leastSaliency = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sectors.size(); ++i)
  {
    result.contours.push_back(vertexContour(r, sectors[i], false, SeamContour::Kind::Sector, static_cast<int>(i)));
    double sum = 0.0;
    for (int v : sectors[i])
    {
      sum += angle[v];
    }
    if (sum < leastSaliency)
    {
      leastSaliency = sum;
      result.cutContour = sectors[i];
    }
  }
  const std::vector<int> faceSector = labelSectors(r, sectors);
  result.sector.assign(mesh.vertexCount(), -1);
  result.faceSector.assign(mesh.faceCount(), -1);
  for (int f = 0; f < r.faceCount(); ++f)
  {
    result.faceSector[modeling.sub.globalFace[f]] = faceSector[f];
  }
  for (int v = 0; v < r.vertexCount(); ++v)
  {
    if (labels[modeling.sub.globalVertex[v]] == 1)
    {
      int sector = std::numeric_limits<int>::max();
      for (int f : r.vertexFaces(v))
      {
        sector = std::min(sector, faceSector[f]);
      }
      result.sector[modeling.sub.globalVertex[v]] = sector;
    }
  }
  if (result.cutContour.size() < 2)
  {
    throw Error("no sector contour joins the handle to the fixed region");
  }

  // Ring seams by minimum cuts (3.2.3, Fig. 4). A small floor keeps every capacity positive, so
  // that each cut's two sides are connected and its triangles form one closed strip.
  const double floor = 1e-6 * weightSum;
  std::vector<double> capacity(r.edgeCount());
  double total = 0.0;
  for (int e = 0; e < r.edgeCount(); ++e)
  {
    capacity[e] = kappa[e] + floor;
    total += capacity[e];
  }
  const double infinite = 1.0 + 2.0 * total; // blocked edges and terminal links
  const std::vector<int>& path = result.cutContour;
  std::vector<int> pathEdges;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
  {
    pathEdges.push_back(edgeBetween(r, path[i], path[i + 1]));
  }
  result.ring.assign(mesh.faceCount(), -1);
  auto crossesOnce = [&](const MinimumCut& cut) {
    int changes = 0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
      changes += cut.sourceSide[path[i]] != cut.sourceSide[path[i + 1]] ? 1 : 0;
    }
    return changes == 1;
  };
  for (int k = 0; k < options.ringCount; ++k)
  {
    MinimumCut best;
    best.flow = infinite;
    bool found = false;
    if (options.search == RingCandidateSearch::GlobalCutFirst)
    {
      MinimumCut global = minimumCut(r, capacity, modeling.handleLoop, modeling.fixedLoop, infinite);
      ++result.maxFlowCount;
      if (global.flow < 0.5 * infinite && crossesOnce(global))
      {
        best = std::move(global);
        found = true;
      }
    }
    if (!found)
    {
      for (std::size_t i = 0; i < pathEdges.size(); ++i)
      {
        if (capacity[pathEdges[i]] >= infinite)
        {
          continue;
        }
        std::vector<int> sources = modeling.handleLoop, sinks = modeling.fixedLoop;
        sources.insert(sources.end(), path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        sinks.insert(sinks.end(), path.begin() + static_cast<std::ptrdiff_t>(i) + 1, path.end());
        MinimumCut candidate = minimumCut(r, capacity, sources, sinks, infinite);
        ++result.maxFlowCount;
        if (candidate.flow < 0.5 * infinite && candidate.flow < best.flow)
        {
          best = std::move(candidate);
          found = true;
        }
      }
    }
    if (!found)
    {
      break; // no further ring fits between the rings found
    }
    // The ring: the triangles the cut passes through; their edges are blocked from now on.
    for (int f = 0; f < r.faceCount(); ++f)
    {
      const Triangle& t = r.triangle(f);
      if (best.sourceSide[t[0]] != best.sourceSide[t[1]] || best.sourceSide[t[0]] != best.sourceSide[t[2]])
      {
        result.ring[modeling.sub.globalFace[f]] = k;
        for (int j = 0; j < 3; ++j)
        {
          capacity[r.faceEdge(f, j)] = infinite;
        }
      }
    }
    result.ringCost.push_back(best.flow);
    if (options.ringDone)
    {
      options.ringDone(k + 1);
    }
  }
  for (int& v : result.cutContour)
  {
    v = modeling.sub.globalVertex[v];
  }
  return result;
}

} // namespace kerf
