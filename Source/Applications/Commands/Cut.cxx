// kerf cut: a mesh cut along the isoline of a harmonic field built from a stroke.
#include "CutPipeline.h"
#include "KerfCommands.h"

#include <vtkPolyData.h>

#include <iostream>

namespace kerf
{

int RunCut(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  if (!args.has("stroke"))
  {
    throw CommandError{ "cut needs --stroke FILE (a polyline drawn on the surface)" };
  }
  if (args.has("png"))
  {
    RequireDisplay(); // before the work, not after
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  vtkSmartPointer<vtkPolyData> stroke = ReadMesh(args.get("stroke"));
  CutPipeline pipeline;
  pipeline.Run(mesh, stroke, args);
  if (args.has("output"))
  {
    WriteMesh(pipeline.cut->GetLabelledSurface(), args.get("output"));
  }
  if (args.has("curve"))
  {
    WriteMesh(pipeline.cut->GetOutput(), args.get("curve"));
  }
  if (args.has("png"))
  {
    pipeline.Render(stroke, "harmonic field from one stroke", args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << "cut of " << input << ": " << CutSummary(pipeline.cut->GetOutput()) << "; "
              << SegmentSizes(pipeline.cut->GetLabelledSurface()) << "\n";
  }
  return 0;
}

} // namespace kerf
