// kerf cut: a mesh cut along the isoline of a harmonic field built from a stroke.
#include "CutPipeline.h"
#include "KerfCommands.h"

#include <vtkPolyData.h>

#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

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
  const auto start = std::chrono::steady_clock::now();
  auto step = start;
  std::vector<std::pair<std::string, double>> times;
  auto lap = [&](const std::string& what) {
    times.emplace_back(what, MillisecondsSince(step));
    step = std::chrono::steady_clock::now();
  };
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  lap("read mesh");
  vtkSmartPointer<vtkPolyData> stroke = ReadMesh(args.get("stroke"));
  lap("read stroke");
  CutPipeline pipeline;
  pipeline.Run(mesh, stroke, args, false);
  times.insert(times.end(), pipeline.milliseconds.begin(), pipeline.milliseconds.end());
  step = std::chrono::steady_clock::now();
  if (args.has("output"))
  {
    WriteMesh(pipeline.cut->GetLabelledSurface(), args.get("output"));
    lap("write surface");
  }
  if (args.has("curve"))
  {
    WriteMesh(pipeline.cut->GetOutput(), args.get("curve"));
    lap("write curve");
  }
  if (args.has("timings"))
  {
    std::cout << std::fixed << std::setprecision(1) << "time:";
    for (const auto& entry : times)
    {
      std::cout << (&entry == &times.front() ? " " : ", ") << entry.first << " " << entry.second << " ms";
    }
    std::cout << "; total " << MillisecondsSince(start) << " ms\n" << std::defaultfloat;
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
