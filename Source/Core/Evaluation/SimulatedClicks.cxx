// Simulated ROI Scissor clicks: each piece of a segmentation selected by a click and corrected by added and subtracted
// discs, the regions claimed in turn.
#include "Evaluation/SimulatedClicks.h"

#include "Error.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/SegmentSpines.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf
{

namespace
{
const double Infinity = std::numeric_limits<double>::infinity();

// The face of `inside` farthest from the set's border (its faces with a neighbour outside it),
// centroid to centroid through the set; a set without a border gives its lowest face.
int innermostFace(const FaceGraph& graph, const std::vector<char>& inside)
{
  std::vector<double> lengths(graph.edgeCount(), Infinity);
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const DualEdge& edge = graph.edge(e);
    if (inside[edge.faces[0]] && inside[edge.faces[1]])
    {
      lengths[e] = edge.centroidPath;
    }
  }
  std::vector<int> border;
  int first = -1;
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    if (!inside[f])
    {
      continue;
    }
    first = first < 0 ? f : first;
    for (int e : graph.faceEdges(f))
    {
      if (e < 0 || !inside[graph.opposite(e, f)])
      {
        border.push_back(f);
        break;
      }
    }
  }
  if (border.empty())
  {
    return first;
  }
  const std::vector<double> distance = dualDijkstra(graph, lengths, border).distance;
  int best = border.front();
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    if (inside[f] && distance[f] != Infinity && distance[f] > distance[best])
    {
      best = f;
    }
  }
  return best;
}

// The largest connected part (by area; ties to the lowest face) of the faces `inside`.
std::vector<char> largestPart(const FaceGraph& graph, const std::vector<char>& inside)
{
  const std::vector<int> parts = splitIntoConnectedSegments(graph, std::vector<int>(inside.begin(), inside.end()));
  std::vector<double> area(graph.faceCount(), 0.0);
  int best = -1;
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    if (inside[f])
    {
      area[parts[f]] += graph.area(f);
      best = best < 0 || area[parts[f]] > area[best] ? parts[f] : best;
    }
  }
  std::vector<char> part(inside.size(), 0);
  for (int f = 0; f < graph.faceCount(); ++f)
  {
    part[f] = inside[f] && parts[f] == best ? 1 : 0;
  }
  return part;
}

// The smallest (`nearest`) or largest distance over the vertices of the faces `inside`.
double extremeDistance(
  const TriangleMesh& mesh, const std::vector<double>& distance, const std::vector<char>& inside, bool nearest)
{
  double extreme = nearest ? Infinity : 0.0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    for (int v = 0; v < 3 && inside[f]; ++v)
    {
      const double d = distance[mesh.triangle(f)[v]];
      extreme = nearest ? std::min(extreme, d) : std::max(extreme, d);
    }
  }
  return extreme;
}

// The pieces to click in turn, all but `rest`: extremities (the fewest neighbours still
// unselected, the rest counted) or the smallest area first; ties to the smaller area, then to the
// lower piece (the lower first face).
std::vector<int> selectionOrder(const FaceGraph& graph, const std::vector<int>& pieceOf,
  const std::vector<double>& pieceArea, const std::vector<int>& clickable, int rest, SimulatedClickOrder rule)
{
  const RegionAdjacency adjacency(graph, pieceOf);
  std::vector<char> left(pieceArea.size(), 0);
  for (int p : clickable)
  {
    left[p] = 1;
  }
  std::vector<int> order;
  while (order.size() + 1 < clickable.size())
  {
    int best = -1, bestNeighbours = 0;
    for (int p : clickable)
    {
      if (!left[p] || p == rest)
      {
        continue;
      }
      int neighbours = 0;
      for (const auto& neighbour : adjacency.neighbours(p))
      {
        neighbours += rule == SimulatedClickOrder::Extremities && left[neighbour.first] ? 1 : 0;
      }
      if (best < 0 || neighbours < bestNeighbours || (neighbours == bestNeighbours && pieceArea[p] < pieceArea[best]))
      {
        best = p;
        bestNeighbours = neighbours;
      }
    }
    order.push_back(best);
    left[best] = 0;
  }
  return order;
}

// A piece's clicks and what they select.
struct Selection
{
  std::vector<ROIClick> added, subtracted;
  std::vector<char> region; // per face: selected and not claimed before
  double error = Infinity;  // the area of region xor target, over the target's area
  double missed = 0.0;      // the target's area outside the region, over the target's area
};

// One run of the simulated user over a surface: the regions claimed so far and the clicks made.
class ClickSession
{
public:
  ClickSession(
    const std::shared_ptr<const Surface>& surface, const SimulatedClickOptions& options, ClickedSegmentation& result)
    : SurfacePointer(surface)
    , Mesh(surface->mesh())
    , Graph(faceGraph(*surface))
    , Options(options)
    , Distances(surface)
    , Result(result)
    , Claimed(surface->mesh().faceCount(), -1)
  {
  }

  // Selects `piece` (its faces where pieceOf is it) and claims its region.
  void selectPiece(int piece, const std::vector<int>& pieceOf)
  {
    const int faces = this->Mesh.faceCount();
    this->Target.assign(faces, 0);
    this->TargetArea = 0.0;
    for (int f = 0; f < faces; ++f)
    {
      if (pieceOf[f] == piece && this->Claimed[f] < 0)
      {
        this->Target[f] = 1;
        this->TargetArea += this->Graph.area(f);
      }
    }
    if (!(this->TargetArea > 0.0))
    {
      this->Result.pieceErrors[piece] = this->Result.pieceMissed[piece] = 1.0; // earlier regions took it all
      return;
    }
    this->Holding = this->Target;
    if (this->Options.includeClaimed)
    {
      this->addHangingRegions();
    }
    Selection current;
    current.added.push_back(this->adding(this->Holding));
    this->select(current);
    this->Result.clicks.push_back({ piece, current.added.back(), false, true, current.error });
    // Corrections: the larger error first; a correction that does not help is undone and not
    // made again.
    std::vector<std::pair<ROIClick, bool>> made{ { current.added.back(), false } };
    for (int clicks = 1; clicks < this->Options.clicksPerPiece && this->needsCorrection(current); ++clicks)
    {
      std::vector<char> missed(faces, 0), spilled(faces, 0);
      double missedArea = 0.0, spilledArea = 0.0;
      for (int f = 0; f < faces; ++f)
      {
        missed[f] = this->Target[f] && !current.region[f];
        spilled[f] = current.region[f] && !this->Target[f];
        missedArea += missed[f] ? this->Graph.area(f) : 0.0;
        spilledArea += spilled[f] ? this->Graph.area(f) : 0.0;
      }
      bool found = false;
      std::pair<ROIClick, bool> correction;
      for (const bool subtract : { spilledArea > missedArea, !(spilledArea > missedArea) })
      {
        if (!found && (subtract ? spilledArea : missedArea) > 0.0)
        {
          const std::vector<char> part = largestPart(this->Graph, subtract ? spilled : missed);
          correction = { subtract ? this->subtracting(part) : this->adding(part), subtract };
          found = std::none_of(made.begin(), made.end(), [&](const std::pair<ROIClick, bool>& other) {
            return other.second == subtract && other.first.position == correction.first.position &&
              other.first.radius == correction.first.radius;
          });
        }
      }
      if (!found)
      {
        break; // every correction in sight was made already
      }
      made.push_back(correction);
      Selection corrected = current;
      (correction.second ? corrected.subtracted : corrected.added).push_back(correction.first);
      this->select(corrected);
      this->Result.clicks.push_back({ piece, correction.first, correction.second, true, corrected.error });
      if (corrected.error < current.error)
      {
        current = std::move(corrected);
      }
      else
      {
        this->Result.clicks.back().kept = false;
      }
    }
    if (!(current.error < 1.0))
    {
      current.region.assign(faces, 0); // worse than no region: undone
      current.error = current.missed = 1.0;
    }
    this->Result.pieceErrors[piece] = current.error;
    this->Result.pieceMissed[piece] = current.missed;
    for (int f = 0; f < faces; ++f)
    {
      this->Claimed[f] = current.region[f] ? piece : this->Claimed[f];
    }
  }

  const std::vector<int>& claimed() const { return this->Claimed; }

private:
  // The claimed faces joined to the target through claimed faces join what the first click holds.
  void addHangingRegions()
  {
    std::vector<int> queue;
    for (int f = 0; f < this->Mesh.faceCount(); ++f)
    {
      if (this->Target[f])
      {
        queue.push_back(f);
      }
    }
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      for (int e : this->Graph.faceEdges(queue[i]))
      {
        const int g = e >= 0 ? this->Graph.opposite(e, queue[i]) : -1;
        if (g >= 0 && !this->Holding[g] && this->Claimed[g] >= 0)
        {
          this->Holding[g] = 1;
          queue.push_back(g);
        }
      }
    }
  }

  // The distance field of a click at face f's centroid (kept for ROI Scissor's run).
  const std::vector<double>& clickAt(int f, ROIClick& click)
  {
    click.position = this->Graph.centroid(f);
    return *this->Distances.from(
      projectClick(*this->SurfacePointer, click.position, this->Options.scissor.clickTolerance),
      this->Options.scissor.paths.heat);
  }

  // An adding click inside `part`, whose disc holds the part with the radius margin.
  ROIClick adding(const std::vector<char>& part)
  {
    int face = innermostFace(this->Graph, part);
    if (this->Options.placement == SimulatedClickPlacement::SpineMiddle)
    {
      std::vector<int> labels(part.size(), -1);
      for (std::size_t f = 0; f < part.size(); ++f)
      {
        labels[f] = part[f] ? 0 : -1;
      }
      const std::vector<SegmentSpine> spines = segmentSpines(this->Mesh, labels, this->Options.spineDepth);
      face =
        spines.empty() || spines.front().faces.empty() ? face : spines.front().faces[spines.front().faces.size() / 2];
    }
    ROIClick click;
    const std::vector<double>& d = this->clickAt(face, click);
    double farthest = 0.0;
    for (double value : d)
    {
      farthest = value != Infinity ? std::max(farthest, value) : farthest;
    }
    const double holding = extremeDistance(this->Mesh, d, part, false);
    click.radius = std::min(this->Options.radiusMargin * holding, 0.5 * (holding + farthest));
    return click;
  }

  // A subtracting click at the innermost face of `part`, its disc stopping at what the first
  // click holds.
  ROIClick subtracting(const std::vector<char>& part)
  {
    ROIClick click;
    click.radius =
      extremeDistance(this->Mesh, this->clickAt(innermostFace(this->Graph, part), click), this->Holding, true);
    return click;
  }

  // ROI Scissor's region for the selection's clicks, less the faces claimed already, and its error.
  void select(Selection& selection)
  {
    const int faces = this->Mesh.faceCount();
    selection.region.assign(faces, 0);
    try
    {
      const std::vector<int> labels = roiScissor(
        *this->SurfacePointer, selection.added, selection.subtracted, this->Options.scissor, &this->Distances)
                                        .faceLabels;
      for (int f = 0; f < faces; ++f)
      {
        selection.region[f] = labels[f] == 1 && this->Claimed[f] < 0 ? 1 : 0;
      }
    }
    catch (const Error&)
    {
      ++this->Result.refused; // no region from these clicks
    }
    double wrong = 0.0, missed = 0.0;
    for (int f = 0; f < faces; ++f)
    {
      wrong += selection.region[f] != this->Target[f] ? this->Graph.area(f) : 0.0;
      missed += this->Target[f] && !selection.region[f] ? this->Graph.area(f) : 0.0;
    }
    selection.error = wrong / this->TargetArea;
    selection.missed = missed / this->TargetArea;
  }

  bool needsCorrection(const Selection& selection) const
  {
    return selection.error > this->Options.correctionThreshold &&
      selection.error * this->TargetArea > this->Options.surfaceThreshold * this->Graph.totalArea();
  }

  std::shared_ptr<const Surface> SurfacePointer;
  const TriangleMesh& Mesh;
  const FaceGraph& Graph;
  const SimulatedClickOptions& Options;
  ClickDistances Distances;
  ClickedSegmentation& Result;
  std::vector<int> Claimed;  // per face: the piece whose region took it
  std::vector<char> Target;  // the piece's faces no region claimed
  std::vector<char> Holding; // what the first click holds: the target and the regions hanging from it
  double TargetArea = 0.0;
};
} // namespace

ClickedSegmentation selectByClicks(
  const std::shared_ptr<const Surface>& surface, const std::vector<int>& intended, const SimulatedClickOptions& options)
{
  const int faces = surface->mesh().faceCount();
  if (static_cast<int>(intended.size()) != faces)
  {
    throw Error("the segmentation must have one label per face");
  }
  if (!(options.radiusMargin > 1.0 && std::isfinite(options.radiusMargin)) || options.clicksPerPiece < 1 ||
    !(options.correctionThreshold >= 0.0) || !(options.surfaceThreshold >= 0.0) ||
    !(options.spineDepth > 0.0 && options.spineDepth <= 1.0))
  {
    throw Error("the simulated clicks need a radius margin above 1, at least one click per piece, thresholds of at "
                "least 0 and a spine depth in (0, 1]");
  }
  const FaceGraph& graph = faceGraph(*surface);
  ClickedSegmentation result;
  result.labels = intended;
  const std::vector<int> pieceOf = splitIntoConnectedSegments(graph, intended);
  const int pieceCount = faces > 0 ? *std::max_element(pieceOf.begin(), pieceOf.end()) + 1 : 0;
  std::vector<double> pieceArea(pieceCount, 0.0);
  result.pieceLabels.assign(pieceCount, -1);
  for (int f = 0; f < faces; ++f)
  {
    pieceArea[pieceOf[f]] += graph.area(f);
    result.pieceLabels[pieceOf[f]] = intended[f];
  }
  result.pieceErrors.assign(pieceCount, 0.0);
  result.pieceMissed.assign(pieceCount, 0.0);
  std::vector<int> clickable;
  for (int p = 0; p < pieceCount; ++p)
  {
    if (result.pieceLabels[p] >= 0)
    {
      clickable.push_back(p);
      result.restPiece = result.restPiece < 0 || pieceArea[p] > pieceArea[result.restPiece] ? p : result.restPiece;
    }
  }
  if (clickable.size() < 2)
  {
    return result; // one segment: nothing to select
  }
  result.order = selectionOrder(graph, pieceOf, pieceArea, clickable, result.restPiece, options.order);
  ClickSession session(surface, options, result);
  for (int piece : result.order)
  {
    session.selectPiece(piece, pieceOf);
  }
  const std::vector<int>& claimed = session.claimed();
  for (int f = 0; f < faces; ++f)
  {
    if (intended[f] >= 0 || claimed[f] >= 0)
    {
      result.labels[f] = result.pieceLabels[claimed[f] >= 0 ? claimed[f] : result.restPiece];
    }
  }
  return result;
}

} // namespace kerf
