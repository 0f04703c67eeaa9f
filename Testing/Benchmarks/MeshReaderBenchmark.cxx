// Reading mesh files: vtkKerfMeshFileReader (Kerf's PLY, STL and OBJ parsers; Kerf's checks before
// VTK's legacy and XML readers) beside VTK's own readers on the same files (/10k /100k /1M).
//
// The files are the cube dumbbell (BenchmarkMeshes.h) written once per run into the temporary
// folder, as `kerf convert` writes them (vtkKerfMeshFileWriter: binary PLY, STL, legacy VTK, VTP with
// raw appended LZ4 blocks, zlib before 2026-11-26; OBJ as text) plus ASCII PLY and STL. Each iteration reads the file
// with a new reader.
#include "BenchmarkMeshes.h"
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"

#include "vtkKerfMeshFileReader.h"
#include "vtkKerfMeshFileWriter.h"

#include <vtkAlgorithm.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <map>
#include <string>

namespace
{
using kerf::benchmarks::Fail;

struct ReaderSize
{
  const char* label;
  int cells; // cube cells per face edge: 12 cells^2 triangles
  double minimumSeconds;
};

const ReaderSize Sizes[] = {
  { "10k", 29, 0.2 },
  { "100k", 91, 0.5 },
  { "1M", 289, 2.0 },
};

// File flavours: how each is written.
enum class Flavour
{
  PLYBinary,
  PLYAscii,
  STLBinary,
  STLAscii,
  OBJ,
  LegacyBinary,
  VTPCompressed
};

const char* extensionOf(Flavour f)
{
  switch (f)
  {
    case Flavour::PLYBinary:
    case Flavour::PLYAscii:
      return ".ply";
    case Flavour::STLBinary:
    case Flavour::STLAscii:
      return ".stl";
    case Flavour::OBJ:
      return ".obj";
    case Flavour::LegacyBinary:
      return ".vtk";
    default:
      return ".vtp";
  }
}

// The file of `flavour` at `size`, written on first use; "" if it could not be written.
std::string fileFor(Flavour flavour, const ReaderSize& size)
{
  static std::map<std::pair<int, int>, std::string> written;
  const auto key = std::make_pair(static_cast<int>(flavour), size.cells);
  const auto found = written.find(key);
  if (found != written.end())
  {
    return found->second;
  }
  vtkSmartPointer<vtkPolyData> mesh =
    kerf::benchmarks::MakePolyData(kerf::benchmarks::MakeCubeDumbbell(1.0, { 0.5, 0.5 }, 0.25, 0.1, size.cells));
  const std::string file = (std::filesystem::temp_directory_path() /
    ("kerf-reader-benchmark-" + std::to_string(static_cast<int>(flavour)) + "-" + size.label + extensionOf(flavour)))
                             .string();
  int ok = 0;
  if (flavour == Flavour::PLYAscii)
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileTypeToASCII();
    writer->SetInputData(mesh);
    writer->SetFileName(file.c_str());
    ok = writer->Write();
  }
  else if (flavour == Flavour::STLAscii)
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetFileTypeToASCII();
    writer->SetInputData(mesh);
    writer->SetFileName(file.c_str());
    ok = writer->Write();
  }
  else
  {
    vtkNew<vtkKerfMeshFileWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(file.c_str());
    ok = writer->Write();
  }
  written[key] = ok == 1 ? file : std::string();
  return written[key];
}

template <typename Reader>
void readWith(benchmark::State& state, Flavour flavour, const ReaderSize& size)
{
  const std::string file = fileFor(flavour, size);
  if (file.empty())
  {
    Fail(state, "cannot write the benchmark file");
    return;
  }
  const vtkIdType triangles = 12 * static_cast<vtkIdType>(size.cells) * size.cells;
  for (auto _ : state)
  {
    vtkNew<Reader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!output || output->GetNumberOfPolys() != triangles)
    {
      Fail(state, "the reader did not return the " + std::to_string(triangles) + " triangles");
      return;
    }
    benchmark::DoNotOptimize(output);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
}
} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterMeshReaderBenchmarks(bool useSizeMinimumTimes)
{
  using Function = void (*)(benchmark::State&, Flavour, const ReaderSize&);
  struct Entry
  {
    const char* name;
    Flavour flavour;
    Function function;
  };
  const Entry entries[] = {
    { "BM_ReadPLYBinary_Kerf", Flavour::PLYBinary, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadPLYBinary_VTK", Flavour::PLYBinary, readWith<vtkPLYReader> },
    { "BM_ReadPLYAscii_Kerf", Flavour::PLYAscii, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadPLYAscii_VTK", Flavour::PLYAscii, readWith<vtkPLYReader> },
    { "BM_ReadSTLBinary_Kerf", Flavour::STLBinary, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadSTLBinary_VTK", Flavour::STLBinary, readWith<vtkSTLReader> },
    { "BM_ReadSTLAscii_Kerf", Flavour::STLAscii, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadSTLAscii_VTK", Flavour::STLAscii, readWith<vtkSTLReader> },
    { "BM_ReadOBJ_Kerf", Flavour::OBJ, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadOBJ_VTK", Flavour::OBJ, readWith<vtkOBJReader> },
    { "BM_ReadLegacyVTK_Kerf", Flavour::LegacyBinary, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadLegacyVTK_VTK", Flavour::LegacyBinary, readWith<vtkPolyDataReader> },
    { "BM_ReadVTP_Kerf", Flavour::VTPCompressed, readWith<vtkKerfMeshFileReader> },
    { "BM_ReadVTP_VTK", Flavour::VTPCompressed, readWith<vtkXMLPolyDataReader> },
  };
  for (const ReaderSize& size : Sizes)
  {
    for (const Entry& e : entries)
    {
      const std::string fullName = std::string(e.name) + "/" + size.label;
      benchmark::internal::Benchmark* registered =
        benchmark::RegisterBenchmark(fullName.c_str(), e.function, e.flavour, size);
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(size.minimumSeconds);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
