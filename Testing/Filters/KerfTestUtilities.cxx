// Helpers shared by Kerf's VTK filter tests.
#include "KerfTestUtilities.h"

#include "vtkKerfMeshFileReader.h"

#include "KerfErrorCollector.h"
#include "KerfScene.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>
#include <vtkTestUtilities.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace kerf
{
namespace test
{

vtkSmartPointer<vtkPolyData> CirclePolyline(double r, double z, int points)
{
  const double pi = 3.14159265358979323846;
  auto line = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(points + 1);
  for (int i = 0; i < points; ++i)
  {
    const double a = 2.0 * pi * i / points;
    cells->InsertCellPoint(pts->InsertNextPoint(r * std::cos(a), r * std::sin(a), z));
  }
  cells->InsertCellPoint(0);
  line->SetPoints(pts);
  line->SetLines(cells);
  return line;
}

vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    points->SetPoint(v, mesh.point(v).data());
  }
  vtkNew<vtkCellArray> triangles;
  for (const Triangle& t : mesh.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  return polyData;
}

vtkSmartPointer<vtkPolyData> WithRegions(const TriangleMesh& mesh, const std::vector<double>& regions)
{
  vtkSmartPointer<vtkPolyData> surface = ToPolyData(mesh);
  vtkNew<vtkDoubleArray> array;
  array->SetName("Region");
  for (double value : regions)
  {
    array->InsertNextValue(value);
  }
  surface->GetPointData()->AddArray(array);
  return surface;
}

std::string SourcePath(int argc, char* argv[], const std::string& relative)
{
  char* expanded = vtkTestUtilities::ExpandDataFileName(argc, argv, relative.c_str());
  std::string path(expanded);
  delete[] expanded;
  return path;
}

CamelWithNeckStroke ReadCamelWithNeckStroke(int argc, char* argv[])
{
  CamelWithNeckStroke files{ vtkSmartPointer<vtkKerfMeshFileReader>::New(),
    vtkSmartPointer<vtkKerfMeshFileReader>::New() };
  files.camel->SetFileName(SourcePath(argc, argv, "Data/camel.off").c_str());
  files.stroke->SetFileName(SourcePath(argc, argv, "Data/camel-neck-stroke.vtk").c_str());
  return files;
}

std::string SharedDataPath(const std::string& relative)
{
  const char* root = std::getenv("KERF_SHARED_DATA");
  if (!root || !*root)
  {
    return "";
  }
  const std::filesystem::path path = std::filesystem::path(root) / relative;
  return std::filesystem::exists(path) ? path.string() : "";
}

std::string UpdateAndCaptureError(vtkAlgorithm* algorithm, int* succeeded)
{
  vtkNew<ErrorCollector> errors;
  vtkNew<ErrorCollector> executiveErrors;
  const unsigned long errorTag = algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  const unsigned long warningTag = algorithm->AddObserver(vtkCommand::WarningEvent, errors);
  vtkExecutive* executive = algorithm->GetExecutive();
  const unsigned long executiveTag = executive->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  const int ok = executive->Update();
  algorithm->RemoveObserver(errorTag);
  algorithm->RemoveObserver(warningTag);
  executive->RemoveObserver(executiveTag);
  if (succeeded)
  {
    *succeeded = ok;
  }
  return errors->Message.empty() ? executiveErrors->Message : errors->Message;
}

bool Check(bool condition, const char* what, const char* file, int line)
{
  if (!condition)
  {
    std::cerr << file << ":" << line << ": check failed: " << what << std::endl;
  }
  return condition;
}

std::vector<vtkIdType> OutputPointOfInput(vtkPolyData* output, int inputPoints)
{
  std::vector<vtkIdType> outputOf(static_cast<std::size_t>(inputPoints), -1);
  vtkDataArray* origin = output->GetPointData()->GetArray("OriginalPointId");
  for (vtkIdType i = 0; origin && i < output->GetNumberOfPoints(); ++i)
  {
    const int v = static_cast<int>(origin->GetComponent(i, 0));
    if (v >= 0 && v < inputPoints)
    {
      outputOf[static_cast<std::size_t>(v)] = i;
    }
  }
  return outputOf;
}

int SeamCarvingPairImageTest(
  int argc, char* argv[], vtkPolyData* left, const char* leftCaption, vtkPolyData* right, const char* rightCaption)
{
  kerf::SceneOptions options;
  options.colorArray = "RingSeam";
  options.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  options.legendTitle = "Ring";
  options.width = 900;
  options.height = 800;
  options.azimuth = 0.0;
  options.elevation = -90.0;
  options.zoom = 0.95;
  kerf::SceneOptions leftOptions = options, rightOptions = options;
  leftOptions.caption = leftCaption;
  rightOptions.caption = rightCaption;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderPair(left, leftOptions, right, rightOptions, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}

int CamelSegmentationImageTest(int argc, char* argv[], vtkPolyDataAlgorithm* segmentation)
{
  vtkNew<vtkKerfMeshFileReader> reader;
  reader->SetFileName(SourcePath(argc, argv, "Data/camel.off").c_str());
  segmentation->SetInputConnection(reader->GetOutputPort());
  segmentation->Update();

  SceneOptions options;
  options.colorArray = "Segment";
  options.colorMap = SceneOptions::ColorMap::Categorical;
  options.legendTitle = "Segment";
  options.width = 600;
  options.height = 450;
  options.azimuth = 35.0;
  options.elevation = 15.0;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = RenderScene(segmentation->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}

} // namespace test
} // namespace kerf
