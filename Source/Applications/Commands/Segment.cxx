// kerf segment: automatic segmentation of one mesh by any of the automatic filters, to a mesh, a .seg file or a
// picture.
#include "KerfCommands.h"

#include "vtkConsensusCutSegmentation.h"
#include "vtkConvexFlooding.h"
#include "vtkEnsembleSegmentation.h"
#include "vtkHierarchicalFaceClustering.h"
#include "vtkKMeansSegmentation.h"
#include "vtkSpectralSegmentation.h"
#include "vtkWatershedSegmentation.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>

namespace kerf
{
namespace
{

// The filter of a method (the benchmark runner's names) with k segments (0: the filter's default).
template <typename Filter>
vtkSmartPointer<vtkPolyDataAlgorithm> withCount(int k)
{
  vtkSmartPointer<Filter> filter = vtkSmartPointer<Filter>::New();
  if (k > 0)
  {
    filter->SetSegmentCount(k);
  }
  return filter;
}

struct SegmentMethod
{
  const char* name;
  vtkSmartPointer<vtkPolyDataAlgorithm> (*make)(int k);
};

// The benchmark runner's names, the default first.
const SegmentMethod Methods[] = {
  { "ensemble", withCount<vtkEnsembleSegmentation> },
  { "consensus-cuts", withCount<vtkConsensusCutSegmentation> },
  { "spectral", withCount<vtkSpectralSegmentation> },
  { "k-means", withCount<vtkKMeansSegmentation> },
  { "face-clustering", withCount<vtkHierarchicalFaceClustering> },
  { "watershed", withCount<vtkWatershedSegmentation> },
  { "convex-flooding", withCount<vtkConvexFlooding> },
};

} // namespace

std::string SegmentMethodNames()
{
  std::string names;
  for (const SegmentMethod& method : Methods)
  {
    names += (names.empty() ? "" : ", ") + std::string(method.name);
  }
  return names;
}

namespace
{
vtkSmartPointer<vtkPolyDataAlgorithm> segmentationFilter(const std::string& name, int k)
{
  for (const SegmentMethod& method : Methods)
  {
    if (name == method.name)
    {
      return method.make(k);
    }
  }
  throw CommandError{ "unknown method '" + name + "' for segment (" + SegmentMethodNames() + ")" };
}
} // namespace

int RunSegment(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  const std::string method = args.get("method", "ensemble");
  const int k = args.has("k") ? args.integer("k", 6, 1, 1000000) : 0;
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = segmentationFilter(method, k);
  if (args.has("png"))
  {
    RequireDisplay(); // before the work, not after
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  filter->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  RunAlgorithm(filter, method + " segmentation");
  const double milliseconds = MillisecondsSince(start);
  vtkPolyData* output = filter->GetOutput();
  vtkDataArray* segment = output->GetCellData()->GetArray("Segment");
  if (!segment || segment->GetNumberOfTuples() != output->GetNumberOfCells())
  {
    throw CommandError{ method + " segmentation gave no Segment label per triangle" };
  }
  std::set<long long> labels;
  for (vtkIdType c = 0; c < segment->GetNumberOfTuples(); ++c)
  {
    labels.insert(static_cast<long long>(segment->GetComponent(c, 0)));
  }
  if (args.has("output"))
  {
    WriteMesh(output, args.get("output"));
  }
  if (args.has("seg"))
  {
    // The Princeton benchmark's format: one label per line, one line per triangle in order.
    std::ofstream seg(args.get("seg"));
    for (vtkIdType c = 0; c < segment->GetNumberOfTuples() && seg; ++c)
    {
      seg << static_cast<long long>(segment->GetComponent(c, 0)) << "\n";
    }
    if (!seg)
    {
      throw CommandError{ "cannot write " + args.get("seg") };
    }
  }
  if (args.has("png"))
  {
    SceneOptions options = ParseSceneOptions(args);
    options.colorArray = "Segment";
    options.colorMap = SceneOptions::ColorMap::Categorical;
    options.frameLongestAxis = true;
    RenderPNG(output, options, args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << method << " segmentation of " << input << ": " << labels.size() << " segments over "
              << output->GetNumberOfCells() << " triangles in " << std::fixed << std::setprecision(1) << milliseconds
              << " ms\n";
  }
  return 0;
}

} // namespace kerf
