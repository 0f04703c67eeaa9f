// kerf render: a mesh coloured by an array, as a PNG.
#include "KerfCommands.h"

#include <vtkPolyData.h>

#include <iostream>

namespace kerf
{

int RunRender(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  if (!args.has("output"))
  {
    throw CommandError{ "render needs -o FILE.png" };
  }
  RenderPNG(ReadMesh(input), ParseSceneOptions(args), args.get("output"));
  if (!args.has("quiet"))
  {
    std::cout << "wrote " << args.get("output") << "\n";
  }
  return 0;
}

} // namespace kerf
