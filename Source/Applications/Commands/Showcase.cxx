// kerf showcase: the stroke cut of a bundled mesh, written to files and summarised.
#include "CutPipeline.h"
#include "KerfCommands.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtksys/SystemTools.hxx>

#include <iomanip>
#include <iostream>

#ifndef KERF_SOURCE_DIR
#define KERF_SOURCE_DIR ""
#endif

namespace kerf
{

namespace
{
std::string defaultShowcaseMesh(const char* program)
{
  // Installed: <prefix>/bin/kerf and <prefix>/share/kerf/Data; in the build tree: the sources.
  const std::string directory = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(program));
  const std::string installed = directory + "/../share/kerf/Data/camel.off";
  if (vtksys::SystemTools::FileExists(installed, true))
  {
    return vtksys::SystemTools::CollapseFullPath(installed);
  }
  return std::string(KERF_SOURCE_DIR) + "/Data/camel.off";
}
} // namespace

int RunShowcase(const Arguments& args, const char* program)
{
  if (args.positional.size() > 1)
  {
    throw CommandError{ "expected at most one mesh file (see --help)" };
  }
  const std::string input = args.positional.empty() ? defaultShowcaseMesh(program) : args.positional[0];
  const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(input);
  const std::string strokeFile = args.has("stroke")
    ? args.get("stroke")
    : vtksys::SystemTools::GetFilenamePath(input) + "/" + stem + "-neck-stroke.vtk";
  if (!vtksys::SystemTools::FileExists(strokeFile, true))
  {
    throw CommandError{ "no stroke for " + input + ": give one with --stroke FILE" };
  }
  const std::string folder = args.get("output", "kerf-output");
  if (!vtksys::SystemTools::MakeDirectory(folder))
  {
    throw CommandError{ "cannot create the output folder " + folder };
  }
  RequireDisplay();
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  vtkSmartPointer<vtkPolyData> stroke = ReadMesh(strokeFile);
  const double readTime = MillisecondsSince(start);
  CutPipeline pipeline;
  pipeline.Run(mesh, stroke, args, true);
  vtkPolyData* surface = pipeline.cut->GetLabelledSurface();
  vtkPolyData* curve = pipeline.cut->GetOutput();

  const std::string surfaceFile = folder + "/" + stem + "-cut.vtp";
  const std::string curveFile = folder + "/" + stem + "-cut-curve.vtp";
  const std::string imageFile = folder + "/" + stem + "-cut.png";
  WriteMesh(surface, surfaceFile);
  WriteMesh(curve, curveFile);
  pipeline.Render(stroke, stem + ": a cut from one stroke", imageFile);

  vtkFieldData* solve = pipeline.field->GetOutput()->GetFieldData();
  std::string cellArrays;
  for (int i = 0; i < surface->GetCellData()->GetNumberOfArrays(); ++i)
  {
    cellArrays += (cellArrays.empty() ? "" : ", ") + std::string(surface->GetCellData()->GetArrayName(i));
  }
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "Kerf showcase: a harmonic cut from one stroke\n"
            << "  mesh:      " << input << " (" << surface->GetNumberOfPoints() << " points, "
            << surface->GetNumberOfPolys() << " triangles)\n"
            << "  stroke:    " << strokeFile << " (" << stroke->GetNumberOfPoints() << " points -> "
            << pipeline.constraints->GetOutput()->GetNumberOfPoints() << " constraints)\n"
            << "  computed:  point arrays " << PointArrayNames(surface) << "\n"
            << "             cell arrays " << cellArrays << "\n"
            << "  cut:       " << CutSummary(curve) << "; " << SegmentSizes(surface) << "\n"
            << "  solve:     " << args.get("weighting", "cotangent") << " weights, "
            << vtkStringArray::SafeDownCast(solve->GetAbstractArray("SolverWork"))->GetValue(0)
            << ", relative residual " << std::scientific << std::setprecision(1)
            << solve->GetArray("RelativeResidual")->GetComponent(0, 0) << std::fixed << "\n"
            << "  time:      read " << readTime << " ms";
  for (const auto& stage : pipeline.milliseconds)
  {
    std::cout << ", " << stage.first << " " << stage.second << " ms";
  }
  std::cout << "; total " << MillisecondsSince(start) << " ms\n"
            << "  surface:   " << vtksys::SystemTools::CollapseFullPath(surfaceFile) << "\n"
            << "  cut curve: " << vtksys::SystemTools::CollapseFullPath(curveFile) << "\n"
            << "  picture:   " << vtksys::SystemTools::CollapseFullPath(imageFile) << "\n";
  return 0;
}

} // namespace kerf
