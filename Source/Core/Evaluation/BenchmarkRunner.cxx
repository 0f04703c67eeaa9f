// The benchmark runner: loading models, the methods, scoring, worker processes and the CSV files.
#include "Evaluation/BenchmarkRunner.h"

#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Evaluation/SimulatedClicks.h"
#include "Evaluation/SimulatedStrokes.h"
#include "Harmonic/HarmonicCutSession.h"
#include "IO/MeshFormats.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/SurfaceConversion.h"
#include "Segmentation/ConsensusCutSegmentation.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/EasyMeshCut.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Segmentation/KMeansSegmentation.h"
#include "Segmentation/SpectralSegmentation.h"
#include "Segmentation/WatershedSegmentation.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace kerf
{

BenchmarkCase loadBenchmarkCase(const BenchmarkModel& model)
{
  BenchmarkCase loaded;
  loaded.model = model;
  ConvertedPolygons converted = convertPolygons(readOFF(model.meshFile));
  if (!converted.allTriangles)
  {
    throw Error("the benchmark's meshes are triangle meshes, but " + model.meshFile + " has other polygons");
  }
  // The metrics need no manifold: benchmark meshes may have any defect but NaN coordinates.
  MeshRequirements requirements;
  requirements.manifold = false;
  requirements.consistentOrientation = false;
  const std::string problems = describeProblems(inspectMesh(converted.mesh), requirements);
  if (!problems.empty())
  {
    throw Error(model.meshFile + " is not accepted: " + problems);
  }
  loaded.surface = std::make_shared<const Surface>(std::move(converted.mesh));
  for (const std::string& file : model.humanSegmentations)
  {
    loaded.humans.push_back(readSegmentation(file));
  }
  if (loaded.humans.size() < 2)
  {
    throw Error("it has " + std::to_string(loaded.humans.size()) +
      " human segmentations; the protocol needs at least 2");
  }
  return loaded;
}

MethodParameters::MethodParameters(const std::string& text, const std::vector<std::string>& known)
{
  std::size_t start = 0;
  while (start < text.size())
  {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string pair = text.substr(start, end - start);
    start = end + 1;
    if (pair.empty())
    {
      continue;
    }
    const std::size_t equals = pair.find('=');
    const std::string name = pair.substr(0, equals);
    if (equals == std::string::npos || std::find(known.begin(), known.end(), name) == known.end())
    {
      throw Error("unknown or malformed method parameter '" + pair + "'");
    }
    this->Values[name] = pair.substr(equals + 1);
  }
}

double MethodParameters::number(const std::string& name, double fallback) const
{
  const auto found = this->Values.find(name);
  if (found == this->Values.end())
  {
    return fallback;
  }
  try
  {
    std::size_t used = 0;
    const double value = std::stod(found->second, &used);
    if (used == found->second.size() && std::isfinite(value))
    {
      return value;
    }
  }
  catch (const std::exception&)
  {
  }
  throw Error("method parameter " + name + " must be a number, got '" + found->second + "'");
}

double MethodParameters::positive(const std::string& name, double fallback) const
{
  const double value = this->number(name, fallback);
  if (this->Values.count(name) && !(value > 0.0))
  {
    throw Error("method parameter " + name + " must be a positive number, got '" + this->text(name, "") + "'");
  }
  return value;
}

std::string MethodParameters::text(const std::string& name, const std::string& fallback) const
{
  const auto found = this->Values.find(name);
  return found == this->Values.end() ? fallback : found->second;
}

namespace
{
// The benchmark's metrics (Chen et al. 2009) in results.csv's order.
const char* const MetricNames[] = { "CutDiscrepancy", "HammingDistance", "MissingRate", "FalseAlarmRate",
  "RandIndexError", "GlobalConsistencyError", "LocalConsistencyError" };

// Sums the metrics of comparisons, to be averaged.
struct MetricSums
{
  std::map<std::string, double> sums;
  int comparisons = 0;

  void add(const SegmentationScores& s, const SegmentationScores* reverse)
  {
    const double values[] = { s.cutDiscrepancy, s.hammingDistance,
      reverse ? 0.5 * (s.missingRate + reverse->missingRate) : s.missingRate,
      reverse ? 0.5 * (s.falseAlarmRate + reverse->falseAlarmRate) : s.falseAlarmRate, s.randIndexError,
      s.globalConsistencyError, s.localConsistencyError };
    for (std::size_t m = 0; m < std::size(MetricNames); ++m)
    {
      this->sums[MetricNames[m]] += values[m];
    }
    ++this->comparisons;
  }

  ModelScores scores(double segments, double seconds) const
  {
    ModelScores result;
    for (const char* name : MetricNames)
    {
      const auto found = this->sums.find(name);
      result.values[name] = this->comparisons > 0 && found != this->sums.end() ? found->second / this->comparisons : 0.0;
    }
    result.values["Comparisons"] = this->comparisons;
    result.values["Segments"] = segments;
    result.values["Seconds"] = seconds;
    return result;
  }
};

// The benchmark's human baseline: every unordered pair of human segmentations.
ModelScores scoreHumans(const BenchmarkCase& c)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  std::vector<PreparedSegmentation> humans;
  double segments = 0.0;
  for (const std::vector<int>& labels : c.humans)
  {
    humans.push_back(evaluator.prepare(labels));
    segments += humans.back().segmentCount;
  }
  MetricSums sums;
  for (std::size_t a = 0; a < humans.size(); ++a)
  {
    for (std::size_t b = a + 1; b < humans.size(); ++b)
    {
      const SegmentationScores forward = evaluator.compare(humans[a], humans[b]);
      const SegmentationScores backward = evaluator.compare(humans[b], humans[a]);
      sums.add(forward, &backward);
    }
  }
  ModelScores result = sums.scores(segments / static_cast<double>(humans.size()), 0.0);
  for (const char* column : { "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" })
  {
    result.values[column] = std::numeric_limits<double>::quiet_NaN();
  }
  result.shownMethod = c.humans[0];
  result.shownHuman = c.humans[1];
  return result;
}

// Automatic methods: the mesh and the number of segments only, scored against every human.
ModelScores scoreAutomatic(const BenchmarkCase& c, const SegmentationMethod& method, const MethodParameters& parameters)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  const auto start = std::chrono::steady_clock::now();
  const MethodOutput output = method.segment(c, nullptr, parameters);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PreparedSegmentation prepared = evaluator.prepare(output.labels);
  MetricSums sums;
  for (const std::vector<int>& human : c.humans)
  {
    sums.add(evaluator.compare(prepared, evaluator.prepare(human)), nullptr);
  }
  ModelScores result = sums.scores(prepared.segmentCount, seconds);
  for (const char* column : { "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" })
  {
    result.values[column] = std::numeric_limits<double>::quiet_NaN();
  }
  result.shownMethod = output.labels;
  result.shownHuman = c.humans[0];
  return result;
}

// Interactive methods: every human in turn gives the input, the others are the references.
ModelScores scoreInteractive(const BenchmarkCase& c, const SegmentationMethod& method, const MethodParameters& parameters)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  std::vector<PreparedSegmentation> humans;
  for (const std::vector<int>& labels : c.humans)
  {
    humans.push_back(evaluator.prepare(labels));
  }
  MetricSums sums;
  double segments = 0.0, seconds = 0.0, inputs = 0.0, fidelity = 0.0, fidelityHamming = 0.0, matched = 0.0;
  ModelScores result;
  for (std::size_t input = 0; input < c.humans.size(); ++input)
  {
    const auto start = std::chrono::steady_clock::now();
    const MethodOutput output = method.segment(c, &c.humans[input], parameters);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const PreparedSegmentation prepared = evaluator.prepare(output.labels);
    for (std::size_t h = 0; h < humans.size(); ++h)
    {
      if (h != input)
      {
        sums.add(evaluator.compare(prepared, humans[h]), nullptr);
      }
    }
    const SegmentationScores self = evaluator.compare(prepared, humans[input]);
    fidelity += self.randIndexError;
    fidelityHamming += self.hammingDistance;
    segments += prepared.segmentCount;
    inputs += output.inputs;
    matched += prepared.segmentCount == humans[input].segmentCount ? 1.0 : 0.0;
    if (input == 0)
    {
      result.shownMethod = output.labels;
      result.shownHuman = c.humans[0];
    }
  }
  const double runs = static_cast<double>(c.humans.size());
  ModelScores scores = sums.scores(segments / runs, seconds / runs);
  scores.values["Fidelity"] = fidelity / runs;
  scores.values["FidelityHamming"] = fidelityHamming / runs;
  scores.values["Inputs"] = inputs / runs;
  scores.values["InputSegmentsMatched"] = matched / runs;
  scores.shownMethod = std::move(result.shownMethod);
  scores.shownHuman = std::move(result.shownHuman);
  return scores;
}

// SeamCut's harmonic cuts with simulated strokes: one stroke along each boundary between two
// segments of the input human, one field and cut per stroke, and the segments the strokes
// intend (labelStrokeCuts).
MethodOutput segmentWithHarmonicCuts(
  const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters)
{
  const TriangleMesh& mesh = c.surface->mesh();
  HarmonicFieldOptions fieldOptions;
  fieldOptions.weights.weighting = parseLaplacianWeighting(parameters.text("weighting", "cotangent"));
  fieldOptions.softWeight = parameters.positive("weight", 1.0);
  const double diagonal = mesh.boundingBoxDiagonal();
  StrokeOptions strokeOptions;
  strokeOptions.samplesPerSegment = static_cast<int>(parameters.positive("samples", 4));
  strokeOptions.offset = parameters.positive("offset", 0.005) * diagonal;
  strokeOptions.offsetLengthFraction = parameters.number("offset-length", 0.05);
  strokeOptions.maximumDistance = 0.05 * diagonal;
  fieldOptions.formulation = parseSoftConstraintFormulation(parameters.text("formulation", "least-squares"));
  const double spacing = parameters.positive("spacing", 0.03) * diagonal;
  const double support = parameters.positive("support", 3.0) * strokeOptions.offset;

  HarmonicCutSession session(c.surface);
  const std::vector<BoundaryStroke> strokes = boundaryStrokes(mesh, *input, spacing);
  std::vector<HarmonicCutSession::StrokeCut> strokeCuts;
  strokeCuts.reserve(strokes.size());
  std::vector<CutWithStroke> cuts;
  for (const BoundaryStroke& stroke : strokes)
  {
    strokeCuts.push_back(session.cutFromStroke({ stroke.points }, strokeOptions, fieldOptions));
    const HarmonicCutSession::StrokeCut& cut = strokeCuts.back();
    if (cut.chosen >= 0)
    {
      CutWithStroke withStroke;
      withStroke.cut = { &cut.field, strokeOptions.isoValue, { &cut.isolines[static_cast<std::size_t>(cut.chosen)] } };
      withStroke.stroke = stroke.points;
      withStroke.sideFaces = cut.sideFaces;
      cuts.push_back(std::move(withStroke));
    }
  }
  MethodOutput output;
  output.labels = labelStrokeCuts(mesh, cuts, support);
  output.inputs = static_cast<int>(strokes.size());
  return output;
}

// Automatic methods: the mesh and k = nSeg-ByModel.txt's count for the model.
int requestedSegments(const BenchmarkCase& c)
{
  if (c.model.requestedSegments < 1)
  {
    throw Error("model " + std::to_string(c.model.id) + " has no segment count in nSeg-ByModel.txt");
  }
  return std::min(c.model.requestedSegments, c.surface->mesh().faceCount());
}

MethodOutput segmentByFlooding(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  ConvexFloodingOptions options;
  options.angleTolerance = parameters.positive("epsilon", options.angleTolerance);
  options.minimumAreaFraction = parameters.positive("q", options.minimumAreaFraction);
  options.segmentCount = requestedSegments(c);
  return { segmentByConvexFlooding(FaceGraph(c.surface->mesh()), options).labels, 0 };
}

MethodOutput segmentWithWatershed(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  WatershedOptions options;
  options.depthThreshold = parameters.positive("depth", options.depthThreshold);
  options.segmentCount = requestedSegments(c);
  return { segmentByWatershed(FaceGraph(c.surface->mesh()), options).labels, 0 };
}

MethodOutput segmentByFaceClustering(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  HierarchicalClusteringOptions options;
  options.directionWeight = parameters.positive("a1", options.directionWeight);
  options.shapeWeight = parameters.positive("a2", options.shapeWeight);
  options.exactClusterCount = static_cast<int>(std::min(parameters.positive("exact", options.exactClusterCount), 2147483647.0));
  options.blockSize = static_cast<int>(std::min(parameters.positive("block", options.blockSize), 2147483647.0));
  return { cutHierarchyAtCount(faceClusterHierarchy(*c.surface, options), requestedSegments(c)), 0 };
}

MethodOutput segmentWithKMeans(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  KMeansSegmentationOptions options;
  options.physicalWeight = parameters.positive("delta", options.physicalWeight);
  return { segmentByKMeans(FaceGraph(c.surface->mesh()), requestedSegments(c), options).labels, 0 };
}

MethodOutput segmentWithSpectralClustering(
  const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  SpectralSegmentationOptions options;
  options.geodesicWeight = parameters.positive("delta", options.geodesicWeight);
  options.convexAngleWeight = parameters.positive("eta", options.convexAngleWeight);
  options.patchCount = static_cast<int>(parameters.positive("patches", options.patchCount));
  return { segmentSpectrally(FaceGraph(c.surface->mesh()), requestedSegments(c), options).labels, 0 };
}

MethodOutput segmentWithConsensusCuts(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  ConsensusCutOptions options;
  options.weighting = parseLaplacianWeighting(parameters.text("weighting", laplacianWeightingName(options.weighting)));
  options.extraFeaturePoints = static_cast<int>(parameters.positive("extra", options.extraFeaturePoints));
  options.maximumFeaturePoints = static_cast<int>(parameters.positive("points", options.maximumFeaturePoints));
  options.isovaluesPerField = static_cast<int>(parameters.positive("isovalues", options.isovaluesPerField));
  options.clipQuantile = parameters.positive("clip", options.clipQuantile);
  options.sameCutTolerance = parameters.positive("same", options.sameCutTolerance);
  options.minimumSegmentArea = parameters.positive("area", options.minimumSegmentArea);
  options.voteExponent = parameters.number("votes", options.voteExponent);
  options.lengthExponent = parameters.number("length", options.lengthExponent);
  options.areaExponent = parameters.number("sizes", options.areaExponent);
  options.peaksPerField = static_cast<int>(parameters.positive("peaks", options.peaksPerField));
  options.walkDepth = parameters.number("walk-depth", options.walkDepth);
  return { segmentByConsensusCuts(*c.surface, requestedSegments(c), options).labels, 0 };
}

MethodOutput segmentWithEnsemble(const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  EnsembleSegmentationOptions options;
  options.consensusCutsWeight = parameters.number("cuts", options.consensusCutsWeight);
  options.spectralWeight = parameters.number("spectral", options.spectralWeight);
  options.convexFloodingWeight = parameters.number("flooding", options.convexFloodingWeight);
  options.kMeansWeight = parameters.number("k-means", options.kMeansWeight);
  options.watershedWeight = parameters.number("watershed", options.watershedWeight);
  options.faceClusteringWeight = parameters.number("clustering", options.faceClusteringWeight);
  options.areaWeighted = parameters.number("area-weighted", options.areaWeighted ? 1.0 : 0.0) != 0.0;
  options.refinement.bandWidth = parameters.number("band", options.refinement.bandWidth);
  options.refinement.convexWeight = parameters.number("convex-weight", options.refinement.convexWeight);
  options.consensusCuts.walkDepth = parameters.number("walk-depth", options.consensusCuts.walkDepth);
  options.consensusCuts.maximumFeaturePoints =
    static_cast<int>(parameters.positive("points", options.consensusCuts.maximumFeaturePoints));
  return { segmentByEnsemble(*c.surface, requestedSegments(c), options).labels, 0 };
}

// A method parameter that counts something: a whole number below 1000.
int wholeNumber(const MethodParameters& parameters, const std::string& name, int fallback)
{
  const std::string text = parameters.text(name, std::to_string(fallback));
  return text.find_first_not_of("0123456789") == std::string::npos && !text.empty() && text.size() < 4
    ? std::stoi(text)
    : throw Error("the method parameter '" + name + "' must be a whole number below 1000, not '" + text + "'");
}

// A method parameter in [0, 1): the whole text a number.
double fraction(const MethodParameters& parameters, const std::string& name, double fallback)
{
  const std::string text = parameters.text(name, "");
  if (text.empty())
  {
    return fallback;
  }
  std::size_t used = 0;
  double value = -1.0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || !(value >= 0.0 && value < 1.0))
  {
    throw Error("the method parameter '" + name + "' must be a number in [0, 1), not '" + text + "'");
  }
  return value;
}

// Easy Mesh Cutting (Ji et al. 2006) with a simulated user: one stroke per segment of the input
// human along its innermost faces, then `corrections` rounds in which a stroke is added inside
// the wrongly labelled faces of each segment (through their innermost ones), as a user corrects
// what the growing got wrong; the boundaries are refined as snakes at the end when asked, then
// edited by override strokes when asked.
MethodOutput segmentWithRegionGrowing(
  const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters, bool snakes)
{
  EasyMeshCutOptions options;
  IsophoticMetricOptions& metric = options.growing.metric;
  metric.normalWeight = parameters.positive("normal-weight", metric.normalWeight);
  metric.curvatureWeight = parameters.positive("curvature-weight", metric.curvatureWeight);
  metric.augmentation = parseCurvatureAugmentation(parameters.text("augmentation", "exponential"));
  metric.curvaturePerEdge = parameters.text("curvature-term", "per-length") == "per-edge";
  options.growing.placement =
    parseBoundaryPlacement(parameters.text("placement", boundaryPlacementName(options.growing.placement)));
  if (!parameters.text("cut-band", "").empty() && options.growing.placement == BoundaryPlacement::Fronts)
  {
    throw Error("the method parameter 'cut-band' applies to placement=minimum-cut and random-walks only");
  }
  options.growing.cutPlacement.band = fraction(parameters, "cut-band", options.growing.cutPlacement.band);
  const double depth = parameters.positive("depth", 0.2);
  const int corrections = wholeNumber(parameters, "corrections", 3);
  const TriangleMesh& mesh = c.surface->mesh();
  std::vector<LabelledStroke> strokes;
  auto addStrokes = [&strokes](const std::vector<SegmentStroke>& simulated) {
    for (const SegmentStroke& stroke : simulated)
    {
      strokes.push_back({ stroke.label, stroke.points });
    }
  };
  addStrokes(innermostStrokes(mesh, *input, depth));
  MethodOutput output;
  if (strokes.size() < 2)
  {
    output.inputs = static_cast<int>(strokes.size());
    output.labels = *input; // one segment: nothing to cut
    return output;
  }
  options.refine = false;
  output.labels = easyMeshCut(c.surface, strokes, options).faceLabels;
  for (int round = 0; round < corrections; ++round)
  {
    std::vector<int> wrong(input->size(), -1);
    bool anyWrong = false;
    for (std::size_t f = 0; f < wrong.size(); ++f)
    {
      if ((*input)[f] >= 0 && output.labels[f] != (*input)[f])
      {
        wrong[f] = (*input)[f];
        anyWrong = true;
      }
    }
    if (!anyWrong)
    {
      break;
    }
    addStrokes(innermostStrokes(mesh, wrong, depth));
    output.labels = easyMeshCut(c.surface, strokes, options).faceLabels;
  }
  if (snakes)
  {
    options.refine = true;
    output.labels = easyMeshCut(c.surface, strokes, options).faceLabels;
  }
  output.inputs = static_cast<int>(strokes.size());
  // Boundary editing (Ji et al. 2006, section 5.2): `overrides` rounds in which the user draws
  // override strokes along the input human's boundaries where faces are still wrong (each
  // boundary stroke that passes within the override radius plus the stroke spacing of a wrongly
  // labelled face). An override the snake refuses (no boundary of the result within the radius)
  // changes nothing and is not counted, as a stroke with no effect would be retracted.
  const int overrideRounds = wholeNumber(parameters, "overrides", 0);
  const double diagonal = mesh.boundingBoxDiagonal();
  EasyMeshCutOptions editing;
  editing.refine = false;
  editing.overrideRadius = parameters.positive("override-radius", 0.02) * diagonal;
  const double spacing = parameters.positive("spacing", 0.03) * diagonal;
  const std::vector<BoundaryStroke> humanBoundaries =
    overrideRounds > 0 ? boundaryStrokes(mesh, *input, spacing) : std::vector<BoundaryStroke>();
  for (int round = 0; round < overrideRounds; ++round)
  {
    std::vector<Vector3> wrong; // centroids of the wrongly labelled faces
    for (std::size_t f = 0; f < input->size(); ++f)
    {
      if ((*input)[f] >= 0 && output.labels[f] != (*input)[f])
      {
        const Triangle& t = mesh.triangle(static_cast<int>(f));
        wrong.push_back((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
      }
    }
    if (wrong.empty())
    {
      break;
    }
    const double reach = editing.overrideRadius + spacing;
    for (const BoundaryStroke& stroke : humanBoundaries)
    {
      const bool nearWrong = std::any_of(stroke.points.begin(), stroke.points.end(), [&](const Vector3& p) {
        return std::any_of(wrong.begin(), wrong.end(), [&](const Vector3& w) { return (w - p).norm() <= reach; });
      });
      if (!nearWrong)
      {
        continue;
      }
      editing.overrides = { stroke.points };
      try
      {
        output.labels = refineBoundaries(c.surface, output.labels, editing).faceLabels;
        ++output.inputs;
      }
      catch (const Error&)
      {
        // Refused: the result has no boundary near this part of the human's.
      }
    }
  }
  return output;
}

// ROI Scissor with a simulated user (kerf::selectByClicks): each connected piece of the input
// human's segments but the largest selected in turn, extremities first, by a click at the middle
// of its spine with a radius that holds it, then corrected by added or subtracted discs while the
// region is wrong; each region cut from what earlier regions left, the largest piece the rest.
MethodOutput segmentWithRoiScissor(const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters)
{
  SimulatedClickOptions options;
  options.radiusMargin = parameters.positive("margin", options.radiusMargin);
  options.clicksPerPiece = wholeNumber(parameters, "clicks", options.clicksPerPiece);
  options.correctionThreshold = parameters.number("threshold", options.correctionThreshold);
  options.surfaceThreshold = parameters.number("surface-threshold", options.surfaceThreshold);
  options.spineDepth = parameters.positive("depth", options.spineDepth);
  const std::string placement = parameters.text("placement", "spine-middle");
  const std::string order = parameters.text("order", "extremities");
  if ((placement != "spine-middle" && placement != "innermost") || (order != "extremities" && order != "smallest"))
  {
    throw Error("the method parameters 'placement' (spine-middle, innermost) and 'order' (extremities, smallest) "
                "got '" + placement + "' and '" + order + "'");
  }
  options.placement = placement == "innermost" ? SimulatedClickPlacement::Innermost : SimulatedClickPlacement::SpineMiddle;
  options.order = order == "smallest" ? SimulatedClickOrder::SmallestFirst : SimulatedClickOrder::Extremities;
  options.includeClaimed = wholeNumber(parameters, "hanging", 1) != 0;
  const ClickedSegmentation selected = selectByClicks(c.surface, *input, options);
  return { selected.labels, static_cast<int>(selected.clicks.size()) };
}

std::string quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + "\"";
}

// Splits one CSV line (fields may be quoted, with "" for a quote).
std::vector<std::string> splitCsv(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool inQuotes = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (c == '"')
    {
      if (inQuotes && i + 1 < line.size() && line[i + 1] == '"')
      {
        field += '"';
        ++i;
      }
      else
      {
        inQuotes = !inQuotes;
      }
    }
    else if (c == ',' && !inQuotes)
    {
      fields.push_back(field);
      field.clear();
    }
    else
    {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}
} // namespace

const std::vector<SegmentationMethod>& segmentationMethods()
{
  static const std::vector<SegmentationMethod> methods = {
    { "human", "every pair of the model's human segmentations (the benchmark's human baseline)", {},
      SegmentationMethod::Protocol::HumanBaseline, nullptr },
    { "harmonic-cuts",
      "SeamCut's cuts from simulated strokes along the input human's boundaries, one field per stroke",
      { "weighting", "samples", "offset", "offset-length", "spacing", "weight", "support", "formulation" }, SegmentationMethod::Protocol::Interactive,
      segmentWithHarmonicCuts },
    { "convex-flooding",
      "convex patches flooded on the dual graph, small ones merged (Kouhestani 2013, section 3.1), down to k",
      { "epsilon", "q" }, SegmentationMethod::Protocol::Automatic, segmentByFlooding },
    { "watershed", "edge watershed of 1 - cos(dihedral angle), basins merged by depth down to k",
      { "depth" }, SegmentationMethod::Protocol::Automatic, segmentWithWatershed },
    { "face-clustering", "Garland et al. 2001's hierarchical face clustering cut at k clusters",
      { "a1", "a2", "exact", "block" }, SegmentationMethod::Protocol::Automatic, segmentByFaceClustering },
    { "k-means", "Shlafman et al. 2002's k-means face clustering on the dual graph",
      { "delta" }, SegmentationMethod::Protocol::Automatic, segmentWithKMeans },
    { "spectral", "Liu and Zhang 2004's spectral clustering on a coarsened patch graph",
      { "delta", "eta", "patches" }, SegmentationMethod::Protocol::Automatic, segmentWithSpectralClustering },
    { "consensus-cuts",
      "cuts that many concavity-aware harmonic fields between feature points agree on, k - 1 of them",
      { "weighting", "extra", "points", "isovalues", "clip", "same", "area", "votes", "length", "sizes", "peaks",
        "walk-depth" },
      SegmentationMethod::Protocol::Automatic, segmentWithConsensusCuts },
    { "ensemble",
      "the partition that consensus cuts, spectral clustering, convex flooding, k-means and the watershed agree on most (evidence accumulation, Fred and Jain 2005)",
      { "cuts", "spectral", "flooding", "k-means", "watershed", "clustering", "area-weighted", "band", "convex-weight",
        "walk-depth", "points" },
      SegmentationMethod::Protocol::Automatic, segmentWithEnsemble },
    { "region-growing",
      "Easy Mesh Cutting's region growing from one simulated stroke per segment along its innermost faces, then strokes inside the wrongly labelled faces and, when asked, override strokes along its boundaries",
      { "normal-weight", "curvature-weight", "augmentation", "curvature-term", "placement", "cut-band", "depth",
        "corrections",
        "overrides", "override-radius", "spacing" },
      SegmentationMethod::Protocol::Interactive,
      [](const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters) {
        return segmentWithRegionGrowing(c, input, parameters, false);
      } },
    { "region-growing+snakes", "region growing as region-growing, then its boundaries refined as snakes",
      { "normal-weight", "curvature-weight", "augmentation", "curvature-term", "placement", "cut-band", "depth",
        "corrections",
        "overrides", "override-radius", "spacing" },
      SegmentationMethod::Protocol::Interactive,
      [](const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters) {
        return segmentWithRegionGrowing(c, input, parameters, true);
      } },
    { "roi-scissor",
      "ROI Scissor from simulated clicks: each piece of the input human but the largest, extremities first, by a click at the middle of its spine, corrected by added or subtracted discs; each region cut from what the earlier left",
      { "margin", "clicks", "threshold", "surface-threshold", "placement", "order", "hanging", "depth" },
      SegmentationMethod::Protocol::Interactive, segmentWithRoiScissor },
  };
  return methods;
}

const SegmentationMethod& findSegmentationMethod(const std::string& name)
{
  std::string names;
  for (const SegmentationMethod& method : segmentationMethods())
  {
    if (method.name == name)
    {
      return method;
    }
    names += (names.empty() ? "" : ", ") + method.name;
  }
  throw Error("unknown method '" + name + "'; the methods are: " + names);
}

const std::vector<std::string>& benchmarkMetricColumns()
{
  static const std::vector<std::string> columns = { "Comparisons", "CutDiscrepancy", "HammingDistance",
    "MissingRate", "FalseAlarmRate", "RandIndexError", "GlobalConsistencyError", "LocalConsistencyError",
    "Segments", "Seconds", "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" };
  return columns;
}

const std::vector<std::string>& benchmarkSummaryColumns()
{
  static const std::vector<std::string> columns = { "CutDiscrepancy", "HammingDistance", "RandIndexError",
    "GlobalConsistencyError", "LocalConsistencyError", "Fidelity", "InputSegmentsMatched", "Seconds" };
  return columns;
}

BenchmarkRow runBenchmarkModel(const BenchmarkCase& benchmarkCase, const SegmentationMethod& method,
  const std::string& parameters, ModelScores* scores)
{
  const MethodParameters parsed(parameters, method.parameters);
  ModelScores result;
  switch (method.protocol)
  {
    case SegmentationMethod::Protocol::HumanBaseline:
      result = scoreHumans(benchmarkCase);
      break;
    case SegmentationMethod::Protocol::Interactive:
      result = scoreInteractive(benchmarkCase, method, parsed);
      break;
    case SegmentationMethod::Protocol::Automatic:
      result = scoreAutomatic(benchmarkCase, method, parsed);
      break;
  }
  BenchmarkRow row;
  row.model = benchmarkCase.model.id;
  row.category = benchmarkCase.model.category;
  row.method = method.name;
  row.parameters = parameters;
  row.values = result.values;
  if (scores)
  {
    *scores = std::move(result);
  }
  return row;
}

std::string resultsHeader()
{
  std::string header = "Model,Category,Method,Parameters";
  for (const std::string& column : benchmarkMetricColumns())
  {
    header += "," + column;
  }
  return header;
}

std::string formatResultRow(const BenchmarkRow& row)
{
  std::ostringstream line;
  line << std::setprecision(10) << row.model << "," << row.category << "," << row.method << ","
       << quoted(row.parameters);
  for (const std::string& column : benchmarkMetricColumns())
  {
    const auto found = row.values.find(column);
    line << "," << (found == row.values.end() ? 0.0 : found->second);
  }
  return line.str();
}

BenchmarkRow parseResultRow(const std::string& line)
{
  const std::vector<std::string> fields = splitCsv(line);
  const std::vector<std::string>& columns = benchmarkMetricColumns();
  if (fields.size() != 4 + columns.size())
  {
    throw Error("a malformed result line: " + line);
  }
  BenchmarkRow row;
  try
  {
    row.model = std::stoi(fields[0]);
    row.category = fields[1];
    row.method = fields[2];
    row.parameters = fields[3];
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
      row.values[columns[c]] = std::stod(fields[4 + c]);
    }
  }
  catch (const std::exception&)
  {
    throw Error("a malformed result line: " + line);
  }
  return row;
}

void writeResults(const std::vector<BenchmarkRow>& rows, const std::string& fileName)
{
  std::ofstream csv(fileName);
  csv << resultsHeader() << "\n";
  for (const BenchmarkRow& row : rows)
  {
    csv << formatResultRow(row) << "\n";
  }
  if (!csv)
  {
    throw Error("cannot write " + fileName);
  }
}

std::string writeSummary(const std::vector<BenchmarkRow>& rows, const std::string& method, const std::string& fileName)
{
  std::vector<std::pair<std::string, std::vector<const BenchmarkRow*>>> groups;
  for (const BenchmarkRow& row : rows)
  {
    auto group = std::find_if(groups.begin(), groups.end(), [&row](const auto& g) { return g.first == row.category; });
    if (group == groups.end())
    {
      groups.emplace_back(row.category, std::vector<const BenchmarkRow*>());
      group = groups.end() - 1;
    }
    group->second.push_back(&row);
  }
  std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const BenchmarkRow*> all;
  for (const BenchmarkRow& row : rows)
  {
    all.push_back(&row);
  }
  groups.emplace_back("all", all);

  std::ofstream csv(fileName);
  std::ostringstream table;
  csv << "Category,Method,Models";
  for (const std::string& column : benchmarkSummaryColumns())
  {
    csv << "," << column;
  }
  csv << "\n";
  // Terminal headings of the summary columns: the fidelity is 1 - RI against the input human.
  const std::map<std::string, std::string> headings = { { "CutDiscrepancy", "CD" }, { "HammingDistance", "HD" },
    { "RandIndexError", "1-RI" }, { "GlobalConsistencyError", "GCE" }, { "LocalConsistencyError", "LCE" },
    { "Fidelity", "fidelity" }, { "InputSegmentsMatched", "k-match" }, { "Seconds", "seconds" } };
  table << std::left << std::setw(11) << "category" << std::right << std::setw(7) << "models";
  for (const std::string& column : benchmarkSummaryColumns())
  {
    table << std::setw(column == "Seconds" ? 10 : 9) << headings.at(column);
  }
  table << "\n";
  for (const auto& group : groups)
  {
    csv << group.first << "," << method << "," << group.second.size();
    table << std::left << std::setw(11) << group.first << std::right << std::setw(7) << group.second.size();
    for (const std::string& column : benchmarkSummaryColumns())
    {
      double sum = 0.0;
      for (const BenchmarkRow* row : group.second)
      {
        sum += row->values.at(column);
      }
      const double mean = group.second.empty() ? 0.0 : sum / static_cast<double>(group.second.size());
      csv << "," << std::setprecision(10) << mean;
      table << std::fixed << std::setprecision(3) << std::setw(column == "Seconds" ? 10 : 9) << mean;
      table.unsetf(std::ios::fixed);
    }
    csv << "\n";
    table << "\n";
  }
  if (!csv)
  {
    throw Error("cannot write " + fileName);
  }
  return table.str();
}

std::string progressLine(std::size_t done, std::size_t total, const BenchmarkRow& row)
{
  std::ostringstream line;
  line << "[" << std::setw(3) << done << "/" << total << "] model " << std::setw(4) << row.model << " "
       << std::left << std::setw(10) << row.category << std::right << " 1-RI " << std::fixed
       << std::setprecision(3) << row.values.at("RandIndexError") << "  CD " << row.values.at("CutDiscrepancy")
       << "  HD " << row.values.at("HammingDistance") << "  (" << std::setprecision(2)
       << row.values.at("Seconds") << " s)";
  return line.str();
}

std::vector<BenchmarkRow> runInWorkers(const std::vector<int>& models, int jobs,
  const std::function<BenchmarkRow(int)>& work, const std::function<void(std::size_t, const BenchmarkRow&)>& finished)
{
  std::vector<BenchmarkRow> rows;
  if (jobs <= 1)
  {
    for (int model : models)
    {
      rows.push_back(work(model));
      finished(rows.size(), rows.back());
    }
    return rows;
  }
  struct Worker
  {
    pid_t pid;
    int fd;
    std::string buffer;
  };
  std::vector<Worker> workers;
  std::fflush(nullptr);
  for (int w = 0; w < jobs; ++w)
  {
    int fds[2];
    if (pipe(fds) != 0)
    {
      throw Error("cannot create a pipe for the workers");
    }
    const pid_t pid = fork();
    if (pid < 0)
    {
      throw Error("cannot start a worker process");
    }
    if (pid == 0)
    {
      close(fds[0]);
      int status = 0;
      for (std::size_t i = static_cast<std::size_t>(w); i < models.size(); i += static_cast<std::size_t>(jobs))
      {
        std::string line;
        try
        {
          line = formatResultRow(work(models[i])) + "\n";
        }
        catch (const std::exception& e)
        {
          line = "!" + std::string(e.what()) + "\n";
          status = 1;
        }
        if (write(fds[1], line.data(), line.size()) != static_cast<ssize_t>(line.size()))
        {
          status = 1;
        }
      }
      close(fds[1]);
      std::fflush(nullptr);
      _exit(status);
    }
    close(fds[1]);
    workers.push_back({ pid, fds[0], "" });
  }
  std::vector<std::string> failures;
  std::size_t open = workers.size();
  while (open > 0)
  {
    std::vector<pollfd> fds;
    for (const Worker& w : workers)
    {
      fds.push_back({ w.fd, POLLIN, 0 });
    }
    if (poll(fds.data(), fds.size(), -1) < 0)
    {
      continue;
    }
    for (std::size_t i = 0; i < workers.size(); ++i)
    {
      if (workers[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP)))
      {
        continue;
      }
      char chunk[4096];
      const ssize_t n = read(workers[i].fd, chunk, sizeof(chunk));
      if (n <= 0)
      {
        close(workers[i].fd);
        workers[i].fd = -1;
        --open;
        continue;
      }
      workers[i].buffer.append(chunk, static_cast<std::size_t>(n));
      std::size_t end;
      while ((end = workers[i].buffer.find('\n')) != std::string::npos)
      {
        const std::string line = workers[i].buffer.substr(0, end);
        workers[i].buffer.erase(0, end + 1);
        if (!line.empty() && line[0] == '!')
        {
          failures.push_back(line.substr(1));
          continue;
        }
        rows.push_back(parseResultRow(line));
        finished(rows.size(), rows.back());
      }
    }
  }
  for (const Worker& w : workers)
  {
    int status = 0;
    waitpid(w.pid, &status, 0);
    if (failures.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0))
    {
      failures.push_back("a worker process ended abnormally");
    }
  }
  if (!failures.empty())
  {
    throw Error(failures.size() == 1 ? failures[0]
                                     : std::to_string(failures.size()) + " models failed; the first: " + failures[0]);
  }
  std::sort(rows.begin(), rows.end(), [](const BenchmarkRow& a, const BenchmarkRow& b) { return a.model < b.model; });
  return rows;
}

} // namespace kerf
