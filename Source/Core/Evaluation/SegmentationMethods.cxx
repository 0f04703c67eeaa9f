// The benchmark's segmentation methods: each reads its parameters, runs a Core algorithm on a model and
// returns per-face labels; the registry lists them with their protocols.
#include "Evaluation/SegmentationMethods.h"

#include "Error.h"
#include "Evaluation/SimulatedClicks.h"
#include "Evaluation/SimulatedStrokes.h"
#include "Harmonic/HarmonicCutSession.h"
#include "Segmentation/ConsensusCutSegmentation.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/EasyMeshCut.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Segmentation/KMeansSegmentation.h"
#include "Segmentation/SpectralSegmentation.h"
#include "Segmentation/WatershedSegmentation.h"

#include <algorithm>

namespace kerf
{

namespace
{
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

// Core extraction chooses its own number of segments: the model's k is not read.
MethodOutput segmentWithCoreExtraction(
  const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  CoreExtractionOptions options;
  options.coarseSize = parameters.wholeNumber("coarse", options.coarseSize);
  options.featureRadius = parameters.positive("radius", options.featureRadius);
  options.hullTolerance = parameters.number("tolerance", options.hullTolerance);
  options.extensionFactor = parameters.positive("extension", options.extensionFactor);
  options.minimumSegmentArea = parameters.number("minimum-area", options.minimumSegmentArea);
  options.refinement.bandWidth = parameters.number("band", options.refinement.bandWidth);
  return { segmentByCoreExtraction(FaceGraph(c.surface->mesh()), options).labels, 0 };
}

MethodOutput segmentByFaceClustering(
  const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
{
  HierarchicalClusteringOptions options;
  options.directionWeight = parameters.positive("a1", options.directionWeight);
  options.shapeWeight = parameters.positive("a2", options.shapeWeight);
  options.exactClusterCount =
    static_cast<int>(std::min(parameters.positive("exact", options.exactClusterCount), 2147483647.0));
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
  return { segmentSpectrally(*c.surface, requestedSegments(c), options).labels, 0 };
}

MethodOutput segmentWithConsensusCuts(
  const BenchmarkCase& c, const std::vector<int>*, const MethodParameters& parameters)
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
  options.coreExtractionWeight = parameters.number("core-extraction", options.coreExtractionWeight);
  options.areaWeighted = parameters.number("area-weighted", options.areaWeighted ? 1.0 : 0.0) != 0.0;
  options.convexTolerance = parameters.number("convex-tolerance", options.convexTolerance);
  options.refinement.bandWidth = parameters.number("band", options.refinement.bandWidth);
  options.refinement.convexWeight = parameters.number("convex-weight", options.refinement.convexWeight);
  options.consensusCuts.walkDepth = parameters.number("walk-depth", options.consensusCuts.walkDepth);
  options.consensusCuts.maximumFeaturePoints =
    static_cast<int>(parameters.positive("points", options.consensusCuts.maximumFeaturePoints));
  // hierarchy=1: one tree from the members at every count of the range, cut at the model's k (or,
  // with choose-count=1, at the count the tree chooses).
  if (parameters.number("hierarchy", 0.0) != 0.0)
  {
    const EnsembleHierarchy hierarchy = ensembleHierarchy(
      *c.surface, parameters.wholeNumber("minimum-count", 5), parameters.wholeNumber("maximum-count", 11), options);
    const bool choose = parameters.number("choose-count", 0.0) != 0.0;
    return { cutEnsembleHierarchy(
               *c.surface, hierarchy, choose ? hierarchy.chosenCount : requestedSegments(c), options.refinement)
               .labels,
      0 };
  }
  // choose-count=1: the method chooses k itself (nSeg-ByModel.txt is not read).
  if (parameters.number("choose-count", 0.0) != 0.0)
  {
    return { segmentByEnsembleChoosingCount(*c.surface, parameters.wholeNumber("minimum-count", 5),
               parameters.wholeNumber("maximum-count", 11), options)
               .labels,
      0 };
  }
  return { segmentByEnsemble(*c.surface, requestedSegments(c), options).labels, 0 };
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
  options.growing.cutPlacement.band = parameters.fraction("cut-band", options.growing.cutPlacement.band);
  const double depth = parameters.positive("depth", 0.2);
  const int corrections = parameters.wholeNumber("corrections", 3);
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
    // The labels are the growing from these strokes, so the snakes start from them (as
    // easyMeshCut with refine would, after growing the same regions again).
    options.refine = true;
    output.labels = refineBoundaries(c.surface, output.labels, options).faceLabels;
  }
  output.inputs = static_cast<int>(strokes.size());
  // Boundary editing (Ji et al. 2006, section 5.2): `overrides` rounds in which the user draws
  // override strokes along the input human's boundaries where faces are still wrong (each
  // boundary stroke that passes within the override radius plus the stroke spacing of a wrongly
  // labelled face). An override the snake refuses (no boundary of the result within the radius)
  // changes nothing and is not counted, as a stroke with no effect would be retracted.
  const int overrideRounds = parameters.wholeNumber("overrides", 0);
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
MethodOutput segmentWithRoiScissor(
  const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters)
{
  SimulatedClickOptions options;
  options.radiusMargin = parameters.positive("margin", options.radiusMargin);
  options.clicksPerPiece = parameters.wholeNumber("clicks", options.clicksPerPiece);
  options.correctionThreshold = parameters.number("threshold", options.correctionThreshold);
  options.surfaceThreshold = parameters.number("surface-threshold", options.surfaceThreshold);
  options.spineDepth = parameters.positive("depth", options.spineDepth);
  const std::string placement = parameters.text("placement", "spine-middle");
  const std::string order = parameters.text("order", "extremities");
  if ((placement != "spine-middle" && placement != "innermost") || (order != "extremities" && order != "smallest"))
  {
    throw Error("the method parameters 'placement' (spine-middle, innermost) and 'order' (extremities, smallest) "
                "got '" +
      placement + "' and '" + order + "'");
  }
  options.placement =
    placement == "innermost" ? SimulatedClickPlacement::Innermost : SimulatedClickPlacement::SpineMiddle;
  options.order = order == "smallest" ? SimulatedClickOrder::SmallestFirst : SimulatedClickOrder::Extremities;
  options.includeClaimed = parameters.wholeNumber("hanging", 1) != 0;
  const ClickedSegmentation selected = selectByClicks(c.surface, *input, options);
  return { selected.labels, static_cast<int>(selected.clicks.size()) };
}
} // namespace

const std::vector<SegmentationMethod>& segmentationMethods()
{
  static const std::vector<SegmentationMethod> methods = {
    { "human", "every pair of the model's human segmentations (the benchmark's human baseline)", {},
      SegmentationMethod::Protocol::HumanBaseline, nullptr },
    { "harmonic-cuts", "SeamCut's cuts from simulated strokes along the input human's boundaries, one field per stroke",
      { "weighting", "samples", "offset", "offset-length", "spacing", "weight", "support", "formulation" },
      SegmentationMethod::Protocol::Interactive, segmentWithHarmonicCuts },
    { "convex-flooding",
      "convex patches flooded on the dual graph, small ones merged (Kouhestani 2013, section 3.1), down to k",
      { "epsilon", "q" }, SegmentationMethod::Protocol::Automatic, segmentByFlooding },
    { "watershed", "edge watershed of 1 - cos(dihedral angle), basins merged by depth down to k", { "depth" },
      SegmentationMethod::Protocol::Automatic, segmentWithWatershed },
    { "core-extraction",
      "Katz, Leifman and Tal 2005's feature points and core extraction (the number of segments is its own, k unread)",
      { "coarse", "radius", "tolerance", "extension", "minimum-area", "band" }, SegmentationMethod::Protocol::Automatic,
      segmentWithCoreExtraction },
    { "face-clustering", "Garland et al. 2001's hierarchical face clustering cut at k clusters",
      { "a1", "a2", "exact", "block" }, SegmentationMethod::Protocol::Automatic, segmentByFaceClustering },
    { "k-means", "Shlafman et al. 2002's k-means face clustering on the dual graph", { "delta" },
      SegmentationMethod::Protocol::Automatic, segmentWithKMeans },
    { "spectral", "Liu and Zhang 2004's spectral clustering on a coarsened patch graph", { "delta", "eta", "patches" },
      SegmentationMethod::Protocol::Automatic, segmentWithSpectralClustering },
    { "consensus-cuts", "cuts that many concavity-aware harmonic fields between feature points agree on, k - 1 of them",
      { "weighting", "extra", "points", "isovalues", "clip", "same", "area", "votes", "length", "sizes", "peaks",
        "walk-depth" },
      SegmentationMethod::Protocol::Automatic, segmentWithConsensusCuts },
    { "ensemble",
      "the partition that consensus cuts, spectral clustering, convex flooding, k-means and the watershed agree on "
      "most (evidence accumulation, Fred and Jain 2005)",
      { "cuts", "spectral", "flooding", "k-means", "watershed", "clustering", "core-extraction", "area-weighted",
        "band", "convex-weight", "walk-depth", "points", "choose-count", "minimum-count", "maximum-count",
        "convex-tolerance", "hierarchy" },
      SegmentationMethod::Protocol::Automatic, segmentWithEnsemble },
    { "region-growing",
      "Easy Mesh Cutting's region growing from one simulated stroke per segment along its innermost faces, then "
      "strokes inside the wrongly labelled faces and, when asked, override strokes along its boundaries",
      { "normal-weight", "curvature-weight", "augmentation", "curvature-term", "placement", "cut-band", "depth",
        "corrections", "overrides", "override-radius", "spacing" },
      SegmentationMethod::Protocol::Interactive,
      [](const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters) {
        return segmentWithRegionGrowing(c, input, parameters, false);
      } },
    { "region-growing+snakes", "region growing as region-growing, then its boundaries refined as snakes",
      { "normal-weight", "curvature-weight", "augmentation", "curvature-term", "placement", "cut-band", "depth",
        "corrections", "overrides", "override-radius", "spacing" },
      SegmentationMethod::Protocol::Interactive,
      [](const BenchmarkCase& c, const std::vector<int>* input, const MethodParameters& parameters) {
        return segmentWithRegionGrowing(c, input, parameters, true);
      } },
    { "roi-scissor",
      "ROI Scissor from simulated clicks: each piece of the input human but the largest, extremities first, by a click "
      "at the middle of its spine, corrected by added or subtracted discs; each region cut from what the earlier left",
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

} // namespace kerf
