// kerf convert: a mesh from one file format to another.
#include "KerfCommands.h"

#include <vtkPolyData.h>

#include <iostream>

namespace kerf
{

int RunConvert(const Arguments& args)
{
  if (args.positional.size() != 2)
  {
    throw CommandError{ "expected an input and an output file (see --help)" };
  }
  WriteMesh(ReadMesh(args.positional[0]), args.positional[1]);
  if (!args.has("quiet"))
  {
    std::cout << "wrote " << args.positional[1] << "\n";
  }
  return 0;
}

} // namespace kerf
