// kerf segment: automatic segmentation of one mesh by any of the automatic filters, to a mesh, a .seg file or a
// picture.
#include "KerfCommands.h"
#include "KerfRanks.h"
#include "Threads.h"

#include "vtkConsensusCutSegmentation.h"
#include "vtkConvexFlooding.h"
#include "vtkCoreExtractionSegmentation.h"
#include "vtkEnsembleSegmentation.h"
#include "vtkHierarchicalFaceClustering.h"
#include "vtkKMeansSegmentation.h"
#include "vtkSpectralSegmentation.h"
#include "vtkWatershedSegmentation.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMultiProcessStream.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace kerf
{
namespace
{

// k of --auto: the method chooses the number of segments.
constexpr int ChosenCount = -1;

// The filter of a method (the benchmark runner's names) with k segments (0: the filter's default).
template <typename Filter>
vtkSmartPointer<vtkPolyDataAlgorithm> withCount(int k)
{
  if (k == ChosenCount)
  {
    throw CommandError{ "--auto is for the methods that can choose the number of segments: ensemble (core-extraction "
                        "always does)" };
  }
  vtkSmartPointer<Filter> filter = vtkSmartPointer<Filter>::New();
  if (k > 0)
  {
    filter->SetSegmentCount(k);
  }
  return filter;
}

// The ensemble with k segments, or choosing them (--auto: vtkEnsembleSegmentation's ChooseSegmentCount).
vtkSmartPointer<vtkPolyDataAlgorithm> ensemble(int k)
{
  vtkSmartPointer<vtkEnsembleSegmentation> filter = vtkSmartPointer<vtkEnsembleSegmentation>::New();
  if (k == ChosenCount)
  {
    filter->ChooseSegmentCountOn();
  }
  else if (k > 0)
  {
    filter->SetSegmentCount(k);
  }
  return filter;
}

// A method that chooses its number of segments itself: -k is refused (--auto is what it does).
template <typename Filter>
vtkSmartPointer<vtkPolyDataAlgorithm> ownCount(int k)
{
  if (k > 0)
  {
    throw CommandError{ "core-extraction chooses the number of segments itself: leave out -k" };
  }
  return vtkSmartPointer<Filter>::New();
}

struct SegmentMethod
{
  const char* name;
  vtkSmartPointer<vtkPolyDataAlgorithm> (*make)(int k);
};

// The benchmark runner's names, the default first.
const SegmentMethod Methods[] = {
  { "ensemble", ensemble },
  { "consensus-cuts", withCount<vtkConsensusCutSegmentation> },
  { "spectral", withCount<vtkSpectralSegmentation> },
  { "k-means", withCount<vtkKMeansSegmentation> },
  { "face-clustering", withCount<vtkHierarchicalFaceClustering> },
  { "watershed", withCount<vtkWatershedSegmentation> },
  { "convex-flooding", withCount<vtkConvexFlooding> },
  { "core-extraction", ownCount<vtkCoreExtractionSegmentation> },
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

namespace
{
// What one mesh gave: the output surface, its labels and the time.
struct Segmented
{
  vtkSmartPointer<vtkPolyData> surface;
  std::vector<long long> labels;
  std::size_t segments = 0;
  double milliseconds = 0.0;
};

Segmented segmentFile(const std::string& file, const std::string& method, int k)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = segmentationFilter(method, k);
  filter->SetInputData(ReadMesh(file));
  const auto start = std::chrono::steady_clock::now();
  RunAlgorithm(filter, method + " segmentation");
  Segmented out;
  out.milliseconds = MillisecondsSince(start);
  out.surface = filter->GetOutput();
  vtkDataArray* segment = out.surface->GetCellData()->GetArray("Segment");
  if (!segment || segment->GetNumberOfTuples() != out.surface->GetNumberOfCells())
  {
    throw CommandError{ method + " segmentation gave no Segment label per triangle" };
  }
  for (vtkIdType c = 0; c < segment->GetNumberOfTuples(); ++c)
  {
    out.labels.push_back(static_cast<long long>(segment->GetComponent(c, 0)));
  }
  out.segments = std::set<long long>(out.labels.begin(), out.labels.end()).size();
  return out;
}

// The Princeton benchmark's format: one label per line, one line per triangle in order.
void writeSeg(const std::vector<long long>& labels, const std::string& file)
{
  std::ofstream seg(file);
  for (std::size_t c = 0; c < labels.size() && seg; ++c)
  {
    seg << labels[c] << "\n";
  }
  if (!seg)
  {
    throw CommandError{ "cannot write " + file };
  }
}

std::string summary(const std::string& method, const std::string& file, const Segmented& result)
{
  std::ostringstream line;
  line << method << " segmentation of " << file << ": " << result.segments
       << (result.segments == 1 ? " segment over " : " segments over ") << result.surface->GetNumberOfCells()
       << " triangles in " << std::fixed << std::setprecision(1) << result.milliseconds << " ms";
  return line.str();
}

// The mesh files of a folder (by extension), in name order.
std::vector<std::string> meshFiles(const std::string& folder)
{
  std::vector<std::string> files;
  vtksys::Directory directory;
  directory.Load(folder);
  for (unsigned long f = 0; f < directory.GetNumberOfFiles(); ++f)
  {
    const std::string name = directory.GetFile(f);
    const std::string extension = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(name));
    const std::string path = folder + "/" + name;
    if (!vtksys::SystemTools::FileIsDirectory(path) &&
      (extension == ".off" || extension == ".ply" || extension == ".obj" || extension == ".stl" ||
        extension == ".vtp" || extension == ".vtk"))
    {
      files.push_back(name);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The rank that segments each file: the largest file first, each to the rank with the fewest bytes
// so far (the lowest on a tie), so that ranks finish close together. Deterministic.
std::vector<int> dealBySize(const std::string& folder, const std::vector<std::string>& files, int ranks)
{
  std::vector<unsigned long> bytes(files.size());
  std::vector<std::size_t> order(files.size());
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    bytes[i] = vtksys::SystemTools::FileLength(folder + "/" + files[i]);
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&bytes](std::size_t a, std::size_t b) { return bytes[a] > bytes[b]; });
  std::vector<unsigned long long> load(static_cast<std::size_t>(ranks), 0);
  std::vector<int> owner(files.size(), 0);
  for (const std::size_t i : order)
  {
    const auto least = std::min_element(load.begin(), load.end());
    owner[i] = static_cast<int>(least - load.begin());
    *least += bytes[i] + 1; // + 1: empty files are dealt out too
  }
  return owner;
}

// A CSV field, quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text)
{
  if (text.find_first_of(",\"\n\r") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  }
  return quoted + "\"";
}

// One mesh of a folder: what it gave, or why it failed, and which rank segmented it.
struct FolderRow
{
  vtkTypeInt64 triangles = 0;
  int segments = 0;
  double milliseconds = 0.0;
  int rank = 0;
  std::string error;
};

// Every mesh file of a folder (in name order) to OUT/NAME.vtp and OUT/NAME.seg, and a line per mesh
// in OUT/summary.csv; a mesh that fails is reported and the others go on. Under mpirun the meshes
// are dealt out over the ranks (dealBySize), each rank writes its own meshes' files, and rank 0
// gathers the rows, writes summary.csv and reports the failures.
int segmentFolder(
  const Arguments& args, const std::string& folder, const std::string& method, int k, const Ranks& ranks)
{
  if (args.has("png") || args.has("seg"))
  {
    throw CommandError{ "a folder is segmented into -o FOLDER (NAME.vtp and NAME.seg per mesh); --png and "
                        "--seg take one mesh" };
  }
  const std::vector<std::string> files = meshFiles(folder);
  if (files.empty())
  {
    throw CommandError{ folder + " holds no mesh files (.off .ply .obj .stl .vtp .vtk)" };
  }
  const std::string out = args.get("output", "kerf-segment");
  if (!vtksys::SystemTools::MakeDirectory(out))
  {
    throw CommandError{ "cannot create the folder " + out };
  }
  const std::vector<int> owner = dealBySize(folder, files, ranks.size());
  // The ranks on a host share its cores: each takes its share of Kerf's threads unless
  // --threads or KERF_NUM_THREADS says otherwise.
  if (ranks.size() > 1 && kerf::threadLimitSetting() == 0 && !std::getenv("KERF_NUM_THREADS"))
  {
    kerf::setThreadLimit(std::max(1, kerf::threadLimit() / LaunchedRanksOnThisHost()));
  }
  vtkMultiProcessStream mine;
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    if (owner[i] != ranks.rank())
    {
      continue;
    }
    const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(files[i]);
    std::ostringstream progress;
    progress << "[" << std::setw(static_cast<int>(std::to_string(files.size()).size())) << i + 1 << "/" << files.size()
             << "] ";
    const std::string where = ranks.size() > 1 ? " (rank " + std::to_string(ranks.rank()) + ")" : "";
    FolderRow row;
    try
    {
      const Segmented result = segmentFile(folder + "/" + files[i], method, k);
      WriteMesh(result.surface, out + "/" + stem + ".vtp");
      writeSeg(result.labels, out + "/" + stem + ".seg");
      row.triangles = result.surface->GetNumberOfCells();
      row.segments = static_cast<int>(result.segments);
      row.milliseconds = result.milliseconds;
      if (!args.has("quiet"))
      {
        std::cout << progress.str() << summary(method, files[i], result) << where << std::endl;
      }
    }
    catch (const CommandError& e)
    {
      row.error = e.message;
      std::cout << progress.str() << files[i] << " failed: " << e.message << where << std::endl;
    }
    mine << static_cast<int>(i) << row.triangles << row.segments << row.milliseconds << row.error;
  }
  // Every rank takes part in the gather and the broadcast before anything can throw.
  std::vector<vtkMultiProcessStream> gathered = ranks.gather(mine);
  std::vector<FolderRow> rows(files.size());
  for (std::size_t r = 0; r < gathered.size(); ++r)
  {
    while (!gathered[r].Empty())
    {
      int i = 0;
      FolderRow row;
      gathered[r] >> i >> row.triangles >> row.segments >> row.milliseconds >> row.error;
      row.rank = static_cast<int>(r);
      rows[static_cast<std::size_t>(i)] = row;
    }
  }
  std::string failure; // rank 0's report, if any
  if (ranks.rank() == 0)
  {
    std::ofstream csv(out + "/summary.csv");
    csv << "Mesh,Triangles,Segments,Milliseconds,Rank,Error\n";
    std::size_t failures = 0;
    for (std::size_t i = 0; i < files.size(); ++i)
    {
      const FolderRow& row = rows[i];
      csv << csvField(files[i]) << "," << row.triangles << "," << row.segments << "," << std::fixed
          << std::setprecision(1) << row.milliseconds << "," << row.rank << "," << csvField(row.error) << "\n";
      if (!row.error.empty() && failures++ == 0)
      {
        failure = files[i] + ": " + row.error;
      }
    }
    if (failures)
    {
      failure =
        std::to_string(failures) + " of " + std::to_string(files.size()) + " meshes failed; the first: " + failure;
    }
    if (!csv)
    {
      failure = "cannot write " + out + "/summary.csv" + (failure.empty() ? "" : "; " + failure);
    }
  }
  if (ranks.broadcast(failure.empty() ? 0 : 1) == 0)
  {
    return 0;
  }
  if (ranks.rank() != 0)
  {
    return 1; // rank 0 says why
  }
  throw CommandError{ failure };
}
} // namespace

int RunSegment(const Arguments& args)
{
  const std::string input = args.single("mesh file or folder");
  const std::string method = args.get("method", "ensemble");
  if (args.has("k") && args.has("auto"))
  {
    throw CommandError{ "-k gives the number of segments and --auto lets the method choose it: one of them" };
  }
  const int k = args.has("auto") ? ChosenCount : args.has("k") ? args.integer("k", 6, 1, 1000000) : 0;
  segmentationFilter(method, k); // an unknown method before any reading
  const bool folder = vtksys::SystemTools::FileIsDirectory(input);
  if (!folder && LaunchedRanks() > 1)
  {
    throw CommandError{ "under mpirun, segment takes a folder, whose meshes it deals out over the ranks" };
  }
  if (folder && LaunchedRanks() > 1 && !Ranks::available())
  {
    throw CommandError{ "this kerf was built without VTK's ParallelMPI, so it cannot deal a folder out over "
                        "mpirun's ranks; run it without mpirun" };
  }
  if (folder)
  {
    const Ranks ranks; // MPI, under mpirun, until the folder is done
    return segmentFolder(args, input, method, k, ranks);
  }
  if (args.has("png"))
  {
    RequireDisplay(); // before the work, not after
  }
  const Segmented result = segmentFile(input, method, k);
  if (args.has("output"))
  {
    WriteMesh(result.surface, args.get("output"));
  }
  if (args.has("seg"))
  {
    writeSeg(result.labels, args.get("seg"));
  }
  if (args.has("png"))
  {
    SceneOptions options = ParseSceneOptions(args);
    options.colorArray = "Segment";
    options.colorMap = SceneOptions::ColorMap::Categorical;
    options.frameLongestAxis = true;
    RenderPNG(result.surface, options, args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << summary(method, input, result) << "\n";
  }
  return 0;
}

} // namespace kerf
