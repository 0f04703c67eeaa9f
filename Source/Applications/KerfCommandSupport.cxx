// What the kerf program's commands share: running algorithms, mesh files, pictures.
#include "KerfCommands.h"

#include "KerfDisplay.h"
#include "KerfErrorCollector.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkKerfMeshFileWriter.h"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>

#include <cstdlib>

namespace kerf
{

void RunAlgorithm(vtkAlgorithm* algorithm, const std::string& what)
{
  vtkNew<ErrorCollector> errors;
  vtkNew<ErrorCollector> pipelineErrors;
  algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineErrors);
  const int ok = algorithm->GetExecutive()->Update();
  if (!ok || !errors->Message.empty())
  {
    throw CommandError{ what + ": " + (errors->Message.empty() ? pipelineErrors->Message : errors->Message) };
  }
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& fileName)
{
  vtkNew<vtkKerfMeshFileReader> reader;
  reader->SetFileName(fileName.c_str());
  RunAlgorithm(reader, "cannot read the mesh");
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}

void WriteMesh(vtkPolyData* mesh, const std::string& fileName)
{
  vtkNew<vtkKerfMeshFileWriter> writer;
  writer->SetFileName(fileName.c_str());
  writer->SetInputData(mesh);
  vtkNew<ErrorCollector> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  if (writer->Write() != 1 || !errors->Message.empty())
  {
    throw CommandError{ errors->Message.empty() ? "cannot write " + fileName : errors->Message };
  }
}

namespace
{
SceneOptions::ColorMap colorMap(const std::string& name)
{
  if (name == "diverging")
  {
    return SceneOptions::ColorMap::Diverging;
  }
  if (name == "sequential")
  {
    return SceneOptions::ColorMap::Sequential;
  }
  if (name == "categorical")
  {
    return SceneOptions::ColorMap::Categorical;
  }
  throw CommandError{ "--map must be diverging, sequential or categorical, got '" + name + "'" };
}
} // namespace

SceneOptions ParseSceneOptions(const Arguments& args)
{
  SceneOptions options;
  options.colorArray = args.get("array");
  options.colorMap = colorMap(args.get("map", "diverging"));
  options.directionArray = args.get("directions");
  options.caption = args.get("caption");
  options.azimuth = args.number("azimuth", options.azimuth, -360.0, 360.0);
  options.elevation = args.number("elevation", options.elevation, -90.0, 90.0);
  options.rangeFraction = args.number("range-fraction", options.rangeFraction, 0.01, 1.0);
  if (args.has("size"))
  {
    const std::string size = args.get("size");
    const std::size_t x = size.find('x');
    try
    {
      options.width = std::stoi(size.substr(0, x));
      options.height = std::stoi(size.substr(x + 1));
    }
    catch (const std::exception&)
    {
      throw CommandError{ "--size expects WIDTHxHEIGHT, got '" + size + "'" };
    }
    if (x == std::string::npos || options.width < 16 || options.height < 16 || options.width > 8192 ||
      options.height > 8192)
    {
      throw CommandError{ "--size expects WIDTHxHEIGHT between 16 and 8192, got '" + size + "'" };
    }
  }
  return options;
}

void RequireDisplay()
{
  std::string error;
  if (!ProcessDisplay(error))
  {
    throw CommandError{ "rendering needs an X display, and " + error +
      ": on a headless machine run the command under xvfb-run -a" };
  }
}

void RenderPNG(vtkPolyData* mesh, const SceneOptions& options, const std::string& fileName)
{
  RequireDisplay();
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = RenderScene(mesh, options, error);
  if (!window)
  {
    throw CommandError{ "cannot render: " + error };
  }
  if (!WritePNG(window, fileName, error))
  {
    throw CommandError{ error };
  }
}

double MillisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string PointArrayNames(vtkPolyData* mesh)
{
  std::string names;
  for (int i = 0; i < mesh->GetPointData()->GetNumberOfArrays(); ++i)
  {
    names += (names.empty() ? "" : ", ") + std::string(mesh->GetPointData()->GetArrayName(i));
  }
  return names;
}

} // namespace kerf
