// kerf info: a mesh's size and whether Kerf's filters accept it.
#include "KerfCommands.h"

#include "vtkSurfaceDescriptors.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>

namespace kerf
{

int RunInfo(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  double bounds[6];
  mesh->GetBounds(bounds);
  std::cout << input << "\n  points: " << mesh->GetNumberOfPoints() << "\n  cells: " << mesh->GetNumberOfCells() << " ("
            << mesh->GetNumberOfPolys() << " polygons, " << mesh->GetNumberOfStrips() << " strips, "
            << mesh->GetNumberOfLines() << " lines, " << mesh->GetNumberOfVerts() << " vertices)"
            << "\n  bounds: [" << bounds[0] << ", " << bounds[1] << "] x [" << bounds[2] << ", " << bounds[3] << "] x ["
            << bounds[4] << ", " << bounds[5] << "]\n";
  vtkNew<vtkSurfaceDescriptors> check;
  check->SetInputData(mesh);
  try
  {
    RunAlgorithm(check, "validation");
    std::cout << "  surface: accepted by Kerf's filters\n";
  }
  catch (const CommandError& e)
  {
    std::cout << "  surface: " << e.message << "\n";
    return 1;
  }
  return 0;
}

} // namespace kerf
