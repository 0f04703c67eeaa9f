// The automatic-segmentation filters on surfaces with known parts (a dumbbell's two lobes, a cube's
// six sides, a body with three fingers): segment counts, Rand index against the known labels, determinism, untouched
// input, the cached merge tree and the errors.
#include "Evaluation/SegmentationMetrics.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/FaceGraph.h"
#include "SegmentationShapes.h"
#include "vtkBoundaryBandCut.h"
#include "vtkConsensusCutSegmentation.h"
#include "vtkConvexFlooding.h"
#include "vtkCoreExtractionSegmentation.h"
#include "vtkEnsembleSegmentation.h"
#include "vtkHierarchicalFaceClustering.h"
#include "vtkKMeansSegmentation.h"
#include "vtkSpectralSegmentation.h"
#include "vtkWatershedSegmentation.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
/// The int cell array `name` of `output`, or an empty list.
std::vector<int> ReadLabels(vtkPolyData* output, const char* name)
{
  std::vector<int> labels;
  vtkDataArray* array = output->GetCellData()->GetArray(name);
  if (array)
  {
    for (vtkIdType c = 0; c < array->GetNumberOfTuples(); ++c)
    {
      labels.push_back(static_cast<int>(array->GetComponent(c, 0)));
    }
  }
  return labels;
}

double FieldValue(vtkPolyData* output, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray(name));
  return array ? array->GetComponent(0, 0) : std::nan("");
}

/// The triangles of a polydata whose cells are all triangles, as a Core mesh (no welding).
kerf::TriangleMesh ToTriangleMesh(vtkPolyData* polyData)
{
  std::vector<kerf::Vector3> points;
  for (vtkIdType p = 0; p < polyData->GetNumberOfPoints(); ++p)
  {
    double x[3];
    polyData->GetPoint(p, x);
    points.push_back({ x[0], x[1], x[2] });
  }
  std::vector<kerf::Triangle> triangles;
  auto cells = vtk::TakeSmartPointer(polyData->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return kerf::TriangleMesh(std::move(points), std::move(triangles));
}

/// A surface with its known parts, one label per triangle.
struct Fixture
{
  const char* name;
  vtkSmartPointer<vtkPolyData> surface;
  std::vector<int> parts;
};

/// Two equal lobes pinched at z = 0 (the profile is symmetric): part 0 below the neck, 1 above.
Fixture Dumbbell()
{
  const kerf::TriangleMesh mesh = kerf::makeDumbbell(2.2, { { 1.0, 1.0 } }, 0.0, 0.65, 4);
  std::vector<int> parts;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    double z = 0.0;
    for (int v : mesh.triangle(f))
    {
      z += mesh.point(v)[2];
    }
    parts.push_back(z > 0.0 ? 1 : 0);
  }
  return { "dumbbell", kerf::test::ToPolyData(mesh), parts };
}

/// A unit cube whose sides are 32 triangles each, with points repeated along its edges (the
/// filters weld them): the part of a triangle is its side.
Fixture Cube()
{
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkLinearSubdivisionFilter> subdivision;
  subdivision->SetInputConnection(triangles->GetOutputPort());
  subdivision->SetNumberOfSubdivisions(2);
  subdivision->Update();
  vtkSmartPointer<vtkPolyData> surface = subdivision->GetOutput();
  const kerf::TriangleMesh mesh = ToTriangleMesh(surface);
  std::vector<int> parts;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    kerf::Vector3 centroid = kerf::Vector3::Zero();
    for (int v : mesh.triangle(f))
    {
      centroid = centroid + mesh.point(v) / 3.0;
    }
    int side = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      if (std::abs(centroid[axis]) > 0.5 - 1e-9)
      {
        side = 2 * axis + (centroid[axis] > 0.0 ? 1 : 0);
      }
    }
    parts.push_back(side);
  }
  return { "cube", surface, parts };
}

/// The triangulated, twice subdivided quads `quads` on `points`.
vtkSmartPointer<vtkPolyData> SubdividedQuads(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::array<vtkIdType, 4>>& quads)
{
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> coordinates;
  for (const auto& p : points)
  {
    coordinates->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& quad : quads)
  {
    cells->InsertNextCell(4, quad.data());
  }
  polyData->SetPoints(coordinates);
  polyData->SetPolys(cells);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(polyData);
  vtkNew<vtkLinearSubdivisionFilter> subdivision;
  subdivision->SetInputConnection(triangles->GetOutputPort());
  subdivision->SetNumberOfSubdivisions(2);
  subdivision->Update();
  return subdivision->GetOutput();
}

/// A box [-1, 1]^2 x [-1, 0] with a box [-0.5, 0.5]^2 x [0, 1] on it, closed and outward
/// oriented, 448 triangles: part 1 is the upper box (its walls and top), part 0 the rest.
Fixture StackedBoxes()
{
  const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  std::vector<std::array<double, 3>> points;
  for (const auto& level :
    { std::array<double, 2>{ { 1.0, -1.0 } }, { { 1.0, 0.0 } }, { { 0.5, 0.0 } }, { { 0.5, 1.0 } } })
  {
    for (const auto& corner : corners)
    {
      points.push_back({ { level[0] * corner[0], level[0] * corner[1], level[1] } });
    }
  }
  // Rings of four points: 0 the big box's bottom, 1 its top, 2 the small box's bottom, 3 its top.
  std::vector<std::array<vtkIdType, 4>> quads{ { { 0, 3, 2, 1 } }, { { 12, 13, 14, 15 } } };
  for (vtkIdType i = 0; i < 4; ++i)
  {
    const vtkIdType j = (i + 1) % 4;
    for (vtkIdType ring : { 0, 4, 8 })
    {
      quads.push_back({ { ring + i, ring + j, ring + 4 + j, ring + 4 + i } });
    }
  }
  vtkSmartPointer<vtkPolyData> surface = SubdividedQuads(points, quads);
  const kerf::TriangleMesh mesh = ToTriangleMesh(surface);
  std::vector<int> parts;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    double z = 0.0;
    for (int v : mesh.triangle(f))
    {
      z += mesh.point(v)[2];
    }
    parts.push_back(z > 1e-9 ? 1 : 0);
  }
  return { "stacked boxes", surface, parts };
}

/// makeProtrusions' body with three fingers (5,120 triangles): part 0 the body, 1 to 3 the fingers.
Fixture Fingers()
{
  const kerf::test::Fingers& shape = kerf::test::fingers();
  return { "fingers", kerf::test::ToPolyData(shape.surface->mesh()), shape.parts };
}

/// 1 - Rand index of `labels` against the fixture's parts.
double RandIndexError(const Fixture& fixture, const std::vector<int>& labels)
{
  const kerf::TriangleMesh mesh = ToTriangleMesh(fixture.surface);
  const kerf::SegmentationEvaluator evaluator(mesh);
  return evaluator.compare(evaluator.prepare(labels), evaluator.prepare(fixture.parts)).randIndexError;
}

/// One filter, made and configured by `make`, on a fixture: it must find `segments` segments
/// within `maximumError` (1 - Rand index) of the known parts, the same labels from a second
/// filter, and leave its input untouched.
bool CheckSegmentation(const char* method, const Fixture& fixture,
  const std::function<vtkSmartPointer<vtkPolyDataAlgorithm>()>& make, int segments, double maximumError)
{
  bool ok = true;
  const vtkMTimeType inputTime = fixture.surface->GetMTime();
  const int inputArrays = fixture.surface->GetCellData()->GetNumberOfArrays();
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = make();
  filter->SetInputData(fixture.surface);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  const std::vector<int> labels = ReadLabels(filter->GetOutput(), "Segment");
  ok &= KERF_CHECK(labels.size() == fixture.parts.size());
  if (labels.size() != fixture.parts.size())
  {
    return false;
  }
  const double error = RandIndexError(fixture, labels);
  const int count = static_cast<int>(FieldValue(filter->GetOutput(), "SegmentCount"));
  std::cout << method << " on the " << fixture.name << ": " << count << " segments, 1 - Rand index " << error
            << std::endl;
  ok &= KERF_CHECK(count == segments);
  ok &= KERF_CHECK(*std::max_element(labels.begin(), labels.end()) == segments - 1);
  ok &= KERF_CHECK(*std::min_element(labels.begin(), labels.end()) == 0);
  ok &= KERF_CHECK(error <= maximumError);
  // Bit for bit the same from a new filter; the input untouched.
  vtkSmartPointer<vtkPolyDataAlgorithm> again = make();
  again->SetInputData(fixture.surface);
  again->Update();
  ok &= KERF_CHECK(ReadLabels(again->GetOutput(), "Segment") == labels);
  ok &= KERF_CHECK(fixture.surface->GetMTime() == inputTime);
  ok &= KERF_CHECK(fixture.surface->GetCellData()->GetNumberOfArrays() == inputArrays);
  return ok;
}

/// The filter fails with a message naming `word` and leaves an empty output.
bool CheckRefused(vtkPolyDataAlgorithm* filter, vtkPolyData* input, const std::string& word)
{
  filter->SetInputData(input);
  int succeeded = 1;
  const std::string message = kerf::test::UpdateAndCaptureError(filter, &succeeded);
  bool ok = KERF_CHECK(succeeded == 0);
  ok &= KERF_CHECK(message.find(word) != std::string::npos);
  ok &= KERF_CHECK(filter->GetOutput()->GetNumberOfCells() == 0);
  if (message.find(word) == std::string::npos)
  {
    std::cerr << "message: " << message << std::endl;
  }
  return ok;
}

template <typename T>
std::function<vtkSmartPointer<vtkPolyDataAlgorithm>()> Maker(const std::function<void(T*)>& configure)
{
  return [configure]() {
    auto filter = vtkSmartPointer<T>::New();
    configure(filter);
    return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
  };
}
} // namespace

int TestAutomaticSegmentationFilters(int, char*[])
{
  bool ok = true;
  const Fixture dumbbell = Dumbbell();
  const Fixture cube = Cube();
  const Fixture steps = StackedBoxes();

  // The dumbbell's two lobes, cut near the neck (measured 1 - Rand index: watershed 0.011,
  // spectral 0.012, convex flooding 0.044, consensus cuts 0.0062: the random walks from the
  // segments' spines move its cut from 0.18 above the neck (0.065) into it; the ensemble 0: its
  // boundary band re-cuts the boundary onto the neck's ring of concave edges, also with convex
  // flooding and the watershed alone, whose tie goes to convex flooding's cut (0.044 without the band)).
  // K-means and face clustering split it lengthwise at k = 2: they are tested on the cube.
  ok &= CheckSegmentation("Watershed", dumbbell,
    Maker<vtkWatershedSegmentation>([](vtkWatershedSegmentation* f) { f->SetSegmentCount(2); }), 2, 0.02);
  ok &= CheckSegmentation("Spectral", dumbbell,
    Maker<vtkSpectralSegmentation>([](vtkSpectralSegmentation* f) { f->SetSegmentCount(2); }), 2, 0.02);
  ok &= CheckSegmentation("Convex Flooding", dumbbell,
    Maker<vtkConvexFlooding>([](vtkConvexFlooding* f) { f->SetSegmentCount(2); }), 2, 0.06);
  ok &= CheckSegmentation("Consensus Cuts", dumbbell,
    Maker<vtkConsensusCutSegmentation>([](vtkConsensusCutSegmentation* f) { f->SetSegmentCount(2); }), 2, 0.01);
  ok &= CheckSegmentation("Consensus Cuts without the walks", dumbbell,
    Maker<vtkConsensusCutSegmentation>([](vtkConsensusCutSegmentation* f) {
      f->SetSegmentCount(2);
      f->SetWalkDepth(0.0);
    }),
    2, 0.08);
  ok &= CheckSegmentation("Ensemble", dumbbell,
    Maker<vtkEnsembleSegmentation>([](vtkEnsembleSegmentation* f) { f->SetSegmentCount(2); }), 2, 0.0);
  for (const double band : { 0.4, 0.0 })
  {
    ok &= CheckSegmentation(band > 0.0 ? "Ensemble of convex flooding and the watershed"
                                       : "Ensemble of convex flooding and the watershed without the band",
      dumbbell, Maker<vtkEnsembleSegmentation>([band](vtkEnsembleSegmentation* f) {
        f->SetSegmentCount(2);
        f->SetConsensusCutsWeight(0.0);
        f->SetSpectralWeight(0.0);
        f->SetKMeansWeight(0.0);
        f->SetBoundaryBand(band);
      }),
      2, band > 0.0 ? 0.0 : 0.05);
  }

  // Two stacked boxes: every edge where they meet is concave, so each is one convex patch.
  ok &= CheckSegmentation("Convex Flooding", steps, Maker<vtkConvexFlooding>([](vtkConvexFlooding*) {}), 2, 0.0);

  // The cube's six sides; a closed convex surface is one convex patch.
  ok &= CheckSegmentation("Convex Flooding", cube, Maker<vtkConvexFlooding>([](vtkConvexFlooding*) {}), 1, 1.0);
  ok &= CheckSegmentation("Watershed", cube, Maker<vtkWatershedSegmentation>([](vtkWatershedSegmentation*) {}), 6, 0.0);
  ok &= CheckSegmentation("Hierarchical Face Clustering", cube,
    Maker<vtkHierarchicalFaceClustering>([](vtkHierarchicalFaceClustering* f) { f->SetSegmentCount(6); }), 6, 0.0);
  ok &= CheckSegmentation("Hierarchical Face Clustering in blocks", cube,
    Maker<vtkHierarchicalFaceClustering>([](vtkHierarchicalFaceClustering* f) {
      f->SetSegmentCount(6);
      f->SetExactClusterCount(24);
      f->SetBlockSize(32);
    }),
    6, 0.0);
  ok &= CheckSegmentation(
    "K-Means", cube, Maker<vtkKMeansSegmentation>([](vtkKMeansSegmentation* f) { f->SetSegmentCount(6); }), 6, 0.0);
  ok &= CheckSegmentation("Spectral", cube,
    Maker<vtkSpectralSegmentation>([](vtkSpectralSegmentation* f) { f->SetSegmentCount(6); }), 6, 0.0);
  ok &= CheckSegmentation("Ensemble", cube,
    Maker<vtkEnsembleSegmentation>([](vtkEnsembleSegmentation* f) { f->SetSegmentCount(6); }), 6, 0.0);

  // Core extraction finds the body and the three fingers without being told how many: the
  // fingertips are feature points, the body the core (measured 0.068, as the Core test).
  const Fixture fingers = Fingers();
  ok &= CheckSegmentation(
    "Core Extraction", fingers, Maker<vtkCoreExtractionSegmentation>([](vtkCoreExtractionSegmentation*) {}), 4, 0.075);
  {
    vtkNew<vtkCoreExtractionSegmentation> coreExtraction;
    coreExtraction->SetInputData(fingers.surface);
    coreExtraction->Update();
    vtkPolyData* output = coreExtraction->GetOutput();
    const kerf::CoreExtractionResult expected = kerf::segmentByCoreExtraction(
      kerf::FaceGraph(kerf::test::fingers().surface->mesh()), kerf::CoreExtractionOptions());
    ok &= KERF_CHECK(ReadLabels(output, "Segment") == expected.labels);
    const std::vector<int> core = ReadLabels(output, "Core");
    ok &= KERF_CHECK(core == std::vector<int>(expected.core.begin(), expected.core.end()));
    ok &= KERF_CHECK(FieldValue(output, "FeaturePoints") == expected.featurePoints);
    ok &= KERF_CHECK(FieldValue(output, "CoreExtensions") == expected.coreExtensions);
    vtkDataArray* featureFaces = vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("FeatureFaces"));
    ok &= KERF_CHECK(featureFaces && featureFaces->GetNumberOfTuples() == expected.featurePoints);
    // The core holds most of the body and none of a fingertip.
    int bodyInCore = 0, body = 0;
    for (std::size_t f = 0; f < core.size(); ++f)
    {
      body += fingers.parts[f] == 0 ? 1 : 0;
      bodyInCore += fingers.parts[f] == 0 && core[f] == 1 ? 1 : 0;
    }
    ok &= KERF_CHECK(bodyInCore > 0.9 * body);
    // Without the minimum cuts, the coarse boundaries (measured 0.059).
    coreExtraction->SetBandWidth(0.0);
    coreExtraction->Update();
    ok &= KERF_CHECK(RandIndexError(fingers, ReadLabels(coreExtraction->GetOutput(), "Segment")) <= 0.065);
    // Refused parameters.
    vtkNew<vtkCoreExtractionSegmentation> refused;
    refused->SetCoarseSize(5);
    ok &= CheckRefused(refused, fingers.surface, "coarse size");
    refused->SetCoarseSize(300);
    refused->SetFeatureRadius(std::nan(""));
    ok &= CheckRefused(refused, fingers.surface, "FeatureRadius");
    refused->SetFeatureRadius(0.15);
    refused->SetMinimumSegmentArea(1.0);
    ok &= CheckRefused(refused, fingers.surface, "minimum segment area");
  }

  // The merge tree is built once: another count only relabels, and the tree is the output's.
  vtkNew<vtkHierarchicalFaceClustering> clustering;
  clustering->SetInputData(cube.surface);
  clustering->SetSegmentCount(6);
  clustering->Update();
  auto work = [&]() {
    return vtkStringArray::SafeDownCast(clustering->GetOutput()->GetFieldData()->GetAbstractArray("Work"))->GetValue(0);
  };
  ok &= KERF_CHECK(work() == "hierarchy");
  ok &= KERF_CHECK(clustering->GetOutput()->GetFieldData()->GetAbstractArray("MergeCost")->GetNumberOfTuples() ==
    static_cast<vtkIdType>(cube.parts.size()) - 1);
  clustering->SetSegmentCount(3);
  clustering->Update();
  ok &= KERF_CHECK(work() == "relabel");
  ok &= KERF_CHECK(FieldValue(clustering->GetOutput(), "SegmentCount") == 3.0);

  // Parameters out of range are refused.
  vtkNew<vtkKMeansSegmentation> kMeans;
  kMeans->SetSegmentCount(static_cast<int>(cube.parts.size()) + 1);
  ok &= CheckRefused(kMeans, cube.surface, "segment");
  vtkNew<vtkConvexFlooding> flooding;
  flooding->SetAngleTolerance(std::nan(""));
  ok &= CheckRefused(flooding, cube.surface, "AngleTolerance");
  vtkNew<vtkWatershedSegmentation> watershed;
  watershed->SetDepthThreshold(-1.0);
  ok &= CheckRefused(watershed, cube.surface, "threshold");
  vtkNew<vtkHierarchicalFaceClustering> negative;
  negative->SetSegmentCount(-1);
  ok &= CheckRefused(negative, cube.surface, "SegmentCount");
  negative->SetSegmentCount(6);
  negative->SetExactClusterCount(0);
  ok &= CheckRefused(negative, cube.surface, "ExactClusterCount");
  negative->SetExactClusterCount(100);
  negative->SetBlockSize(0);
  ok &= CheckRefused(negative, cube.surface, "BlockSize");
  vtkNew<vtkSpectralSegmentation> spectral;
  spectral->SetPatchCount(1);
  ok &= CheckRefused(spectral, cube.surface, "patch");
  vtkNew<vtkConsensusCutSegmentation> consensus;
  consensus->SetSegmentCount(0);
  ok &= CheckRefused(consensus, cube.surface, "segment");
  consensus->SetSegmentCount(2);
  consensus->SetSegmentArrayName("");
  ok &= CheckRefused(consensus, cube.surface, "name");
  vtkNew<vtkEnsembleSegmentation> ensemble;
  ensemble->SetSegmentCount(0);
  ok &= CheckRefused(ensemble, cube.surface, "segment");
  ensemble->SetSegmentCount(2);
  ensemble->SetKMeansWeight(-1.0);
  ok &= CheckRefused(ensemble, cube.surface, "weight");
  ensemble->SetKMeansWeight(std::nan(""));
  ok &= CheckRefused(ensemble, cube.surface, "KMeansWeight");
  ensemble->SetKMeansWeight(1.0);
  ensemble->SetBoundaryBand(-0.1);
  ok &= CheckRefused(ensemble, cube.surface, "band");
  ensemble->SetBoundaryBand(std::nan(""));
  ok &= CheckRefused(ensemble, cube.surface, "BoundaryBand");
  ensemble->SetBoundaryBand(0.4);
  ensemble->SetConvexWeight(-1.0);
  ok &= CheckRefused(ensemble, cube.surface, "convex weight");
  ensemble->SetConvexWeight(0.1);
  ensemble->SetSegmentArrayName("");
  ok &= CheckRefused(ensemble, cube.surface, "name");

  // Boundary Band Cut on the dumbbell, its cut drawn 0.3 above the neck with a wave of 6 periods
  // around the axis (1 - Rand index 0.14): re-cut into the neck, onto a ring of edges one row of
  // triangles from the construction's (measured 0.0247, also from 0.2 and 0.25 above it); then
  // convex flooding's cut (0.044) re-cut in a pipeline, exactly onto the neck (0).
  Fixture wavy = Dumbbell();
  wavy.name = "dumbbell cut off its neck";
  {
    const kerf::TriangleMesh mesh = ToTriangleMesh(wavy.surface);
    vtkNew<vtkIntArray> drawn;
    drawn->SetName("Segment");
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      kerf::Vector3 c = kerf::Vector3::Zero();
      for (int v : mesh.triangle(f))
      {
        c = c + mesh.point(v) / 3.0;
      }
      drawn->InsertNextValue(c.z() > 0.3 + 0.12 * std::sin(6.0 * std::atan2(c.y(), c.x())) ? 1 : 0);
    }
    vtkSmartPointer<vtkPolyData> labelled = vtkSmartPointer<vtkPolyData>::New();
    labelled->DeepCopy(wavy.surface);
    labelled->GetCellData()->AddArray(drawn);
    wavy.surface = labelled;
    std::vector<int> before(static_cast<std::size_t>(mesh.faceCount()));
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      before[static_cast<std::size_t>(f)] = drawn->GetValue(f);
    }
    const double drawnError = RandIndexError(wavy, before);
    std::cout << "The drawn cut on the dumbbell: 1 - Rand index " << drawnError << std::endl;
    ok &= KERF_CHECK(drawnError > 0.1);
  }
  ok &= CheckSegmentation("Boundary Band Cut", wavy, Maker<vtkBoundaryBandCut>([](vtkBoundaryBandCut*) {}), 2, 0.03);
  vtkNew<vtkBoundaryBandCut> recut;
  recut->SetInputData(wavy.surface);
  recut->Update();
  ok &= KERF_CHECK(FieldValue(recut->GetOutput(), "RecutBoundaries") == 1.0);
  ok &= KERF_CHECK(FieldValue(recut->GetOutput(), "MovedFaces") > 0.0);
  recut->SetBoundaryBand(0.0);
  recut->Update();
  ok &= KERF_CHECK(FieldValue(recut->GetOutput(), "MovedFaces") == 0.0);
  vtkNew<vtkConvexFlooding> floodingFirst;
  floodingFirst->SetInputData(dumbbell.surface);
  floodingFirst->SetSegmentCount(2);
  vtkNew<vtkBoundaryBandCut> afterFlooding;
  afterFlooding->SetInputConnection(floodingFirst->GetOutputPort());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(afterFlooding).empty());
  const double floodedError = RandIndexError(dumbbell, ReadLabels(afterFlooding->GetOutput(), "Segment"));
  std::cout << "Convex Flooding, then Boundary Band Cut, on the dumbbell: 1 - Rand index " << floodedError << std::endl;
  ok &= KERF_CHECK(floodedError == 0.0);
  // Its errors: no label array, a negative label, a negative or NaN band, a negative weight.
  vtkNew<vtkBoundaryBandCut> refused;
  ok &= CheckRefused(refused, dumbbell.surface, "Segment");
  {
    vtkSmartPointer<vtkPolyData> negative = vtkSmartPointer<vtkPolyData>::New();
    negative->DeepCopy(wavy.surface);
    vtkIntArray::SafeDownCast(negative->GetCellData()->GetArray("Segment"))->SetValue(7, -1);
    ok &= CheckRefused(refused, negative, "negative");
  }
  refused->SetBoundaryBand(-0.4);
  ok &= CheckRefused(refused, wavy.surface, "band");
  refused->SetBoundaryBand(std::nan(""));
  ok &= CheckRefused(refused, wavy.surface, "BoundaryBand");
  refused->SetBoundaryBand(0.4);
  refused->SetConvexWeight(-1.0);
  ok &= CheckRefused(refused, wavy.surface, "convex weight");
  // The figures of the ensemble: five members voted, and 50 atoms (faces all five keep together).
  vtkNew<vtkEnsembleSegmentation> figures;
  figures->SetInputData(dumbbell.surface);
  figures->SetSegmentCount(2);
  figures->Update();
  ok &= KERF_CHECK(FieldValue(figures->GetOutput(), "Members") == 5.0);
  ok &= KERF_CHECK(FieldValue(figures->GetOutput(), "Atoms") == 50.0); // measured
  std::cout << "Ensemble on the dumbbell: " << FieldValue(figures->GetOutput(), "Atoms") << " atoms" << std::endl;
  // Choosing the count among 2 and 3: the output is the ensemble at the chosen count, which has the
  // smaller of the two CountScores, and SegmentCount says it; a minimum below 2 is refused.
  vtkNew<vtkEnsembleSegmentation> choosing;
  choosing->SetInputData(dumbbell.surface);
  choosing->ChooseSegmentCountOn();
  choosing->SetMinimumSegmentCount(2);
  choosing->SetMaximumSegmentCount(3);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(choosing).empty());
  vtkDataArray* scores = choosing->GetOutput()->GetFieldData()->GetArray("CountScores");
  ok &= KERF_CHECK(scores != nullptr && scores->GetNumberOfTuples() == 2);
  if (scores != nullptr && scores->GetNumberOfTuples() == 2)
  {
    const int chosen = FieldValue(choosing->GetOutput(), "SegmentCount") == 2.0 ? 2 : 3;
    std::cout << "Ensemble choosing its count on the dumbbell: scores " << scores->GetTuple1(0) << ", "
              << scores->GetTuple1(1) << "; chose " << chosen << std::endl;
    ok &= KERF_CHECK(
      chosen == 2 ? scores->GetTuple1(0) <= scores->GetTuple1(1) : scores->GetTuple1(1) < scores->GetTuple1(0));
    ok &= KERF_CHECK(FieldValue(choosing->GetOutput(), "SegmentCount") == chosen);
    figures->SetSegmentCount(chosen);
    figures->Update();
    ok &= KERF_CHECK(ReadLabels(choosing->GetOutput(), "Segment") == ReadLabels(figures->GetOutput(), "Segment"));
  }
  choosing->SetMinimumSegmentCount(1);
  ok &= CheckRefused(choosing, dumbbell.surface, "minimum");
  // A sphere has no parts: choosing its count (the defaults 5 to 11) leaves it one segment, with no
  // count scored; ConvexTolerance 0 chooses a count in the range; a tolerance of 1 is refused.
  vtkSmartPointer<vtkPolyData> sphere = kerf::test::ToPolyData(kerf::makeIcosphere(0.5, 3));
  vtkNew<vtkEnsembleSegmentation> convex;
  convex->SetInputData(sphere);
  convex->ChooseSegmentCountOn();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(convex).empty());
  ok &= KERF_CHECK(FieldValue(convex->GetOutput(), "SegmentCount") == 1.0);
  vtkDataArray* noScores = convex->GetOutput()->GetFieldData()->GetArray("CountScores");
  ok &= KERF_CHECK(noScores != nullptr && noScores->GetNumberOfTuples() == 0);
  convex->SetConvexTolerance(0.0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(convex).empty());
  ok &= KERF_CHECK(FieldValue(convex->GetOutput(), "SegmentCount") >= 5.0);
  ok &= KERF_CHECK(FieldValue(convex->GetOutput(), "SegmentCount") <= 11.0);
  convex->SetConvexTolerance(1.0);
  ok &= CheckRefused(convex, sphere, "convex tolerance");
  convex->SetConvexTolerance(0.01);
  convex->SetMaximumSegmentCount(sphere->GetNumberOfCells() + 1);
  convex->SetMinimumSegmentCount(sphere->GetNumberOfCells() - 30);
  ok &= CheckRefused(convex, sphere, "at most the number of faces");

  // The hierarchy: built once (Work "hierarchy"), then a new SegmentCount or ChooseSegmentCount
  // only re-labels; the tree is in the field data (Atoms - 1 merges on one component), the chosen
  // count has the least of the three CountScores, and a new weight builds it again.
  vtkNew<vtkEnsembleSegmentation> tree;
  tree->SetInputData(dumbbell.surface);
  tree->UseHierarchyOn();
  tree->SetMinimumSegmentCount(2);
  tree->SetMaximumSegmentCount(4);
  tree->SetSegmentCount(2);
  const auto treeWork = [&tree]() {
    vtkStringArray* array = vtkStringArray::SafeDownCast(tree->GetOutput()->GetFieldData()->GetAbstractArray("Work"));
    return array != nullptr ? array->GetValue(0) : std::string("(none)");
  };
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(tree).empty());
  ok &= KERF_CHECK(treeWork() == "hierarchy");
  ok &= KERF_CHECK(FieldValue(tree->GetOutput(), "SegmentCount") == 2.0);
  ok &= KERF_CHECK(FieldValue(tree->GetOutput(), "Members") == 15.0);
  const std::vector<int> two = ReadLabels(tree->GetOutput(), "Segment");
  const double treeError = RandIndexError(dumbbell, two);
  std::cout << "Ensemble hierarchy on the dumbbell at 2: 1 - Rand index " << treeError << ", "
            << FieldValue(tree->GetOutput(), "Atoms") << " atoms" << std::endl;
  ok &= KERF_CHECK(treeError < 0.05);
  vtkFieldData* treeData = tree->GetOutput()->GetFieldData();
  for (const char* name : { "MergeFirst", "MergeSecond", "MergeLinkage" })
  {
    vtkDataArray* merges = treeData->GetArray(name);
    ok &= KERF_CHECK(merges != nullptr && merges->GetNumberOfTuples() == FieldValue(tree->GetOutput(), "Atoms") - 1);
  }
  vtkDataArray* scoresArray = treeData->GetArray("CountScores");
  std::vector<double> treeScores;
  for (vtkIdType c = 0; scoresArray != nullptr && c < scoresArray->GetNumberOfTuples(); ++c)
  {
    treeScores.push_back(scoresArray->GetTuple1(c));
  }
  ok &= KERF_CHECK(treeScores.size() == 3);
  tree->SetSegmentCount(3);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(tree).empty());
  ok &= KERF_CHECK(treeWork() == "relabel");
  ok &= KERF_CHECK(FieldValue(tree->GetOutput(), "SegmentCount") == 3.0);
  tree->ChooseSegmentCountOn();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(tree).empty());
  ok &= KERF_CHECK(treeWork() == "relabel");
  if (treeScores.size() == 3)
  {
    const auto best = std::min_element(treeScores.begin(), treeScores.end()) - treeScores.begin();
    ok &= KERF_CHECK(FieldValue(tree->GetOutput(), "SegmentCount") == 2.0 + static_cast<double>(best));
  }
  tree->ChooseSegmentCountOff();
  tree->SetSegmentCount(2);
  tree->Update();
  ok &= KERF_CHECK(treeWork() == "relabel");
  ok &= KERF_CHECK(ReadLabels(tree->GetOutput(), "Segment") == two);
  tree->SetWatershedWeight(0.0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(tree).empty());
  ok &= KERF_CHECK(treeWork() == "hierarchy");
  ok &= KERF_CHECK(FieldValue(tree->GetOutput(), "Members") == 12.0);
  tree->SetSegmentCount(0);
  ok &= CheckRefused(tree, dumbbell.surface, "at least 1");
  tree->SetSegmentCount(2);
  tree->SetMinimumSegmentCount(5);
  ok &= CheckRefused(tree, dumbbell.surface, "minimum");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
