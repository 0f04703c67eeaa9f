// kerf descriptors: normals, curvatures and the other surface descriptors, to a file or a picture.
#include "KerfCommands.h"

#include "vtkSurfaceDescriptors.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iomanip>
#include <iostream>

namespace kerf
{

int RunDescriptors(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  vtkNew<vtkSurfaceDescriptors> filter;
  filter->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  RunAlgorithm(filter, "surface descriptors");
  const double milliseconds = MillisecondsSince(start);
  vtkPolyData* output = filter->GetOutput();
  if (args.has("output"))
  {
    WriteMesh(output, args.get("output"));
  }
  if (args.has("png"))
  {
    SceneOptions options = ParseSceneOptions(args);
    if (options.colorArray.empty())
    {
      options.colorArray = "MeanCurvature";
      options.rangeFraction = args.number("range-fraction", 0.85, 0.01, 1.0);
      options.directionArray = args.get("directions", "MinimumCurvatureDirection");
    }
    RenderPNG(output, options, args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << "surface descriptors of " << input << ": " << output->GetNumberOfPoints() << " points, "
              << output->GetNumberOfPolys() << " triangles in " << std::fixed << std::setprecision(1) << milliseconds
              << " ms\n  arrays: " << PointArrayNames(output) << "\n";
  }
  return 0;
}

} // namespace kerf
