// kerf unwrap: a mesh cut open along curves into charts and given texture coordinates (a UV atlas).
#include "KerfCommands.h"

#include "vtkChartParameterization.h"
#include "vtkCurveExport.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtksys/SystemTools.hxx>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace kerf
{

namespace
{
int exportMode(const std::string& name)
{
  if (name == "scissor")
  {
    return vtkCurveExport::SCISSOR;
  }
  if (name == "snap")
  {
    return vtkCurveExport::SNAP;
  }
  if (name == "inverse-snap")
  {
    return vtkCurveExport::INVERSE_SNAP;
  }
  throw CommandError{ "--mode must be scissor, snap or inverse-snap, got '" + name + "'" };
}

int flatteningMethod(const std::string& name)
{
  if (name == "lscm")
  {
    return vtkChartParameterization::LSCM;
  }
  if (name == "linabf")
  {
    return vtkChartParameterization::LINABF;
  }
  throw CommandError{ "--method must be lscm or linabf, got '" + name + "'" };
}

double fieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array != nullptr && array->GetNumberOfTuples() > 0 ? array->GetComponent(0, 0) : 0.0;
}
std::string counted(int count, const std::string& noun)
{
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

int sumOf(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  double sum = 0.0;
  for (vtkIdType i = 0; array != nullptr && i < array->GetNumberOfTuples(); ++i)
  {
    sum += array->GetComponent(i, 0);
  }
  return static_cast<int>(sum);
}
} // namespace

int RunUnwrap(const Arguments& args)
{
  const std::string input = args.single("mesh file");
  if (!args.has("curves"))
  {
    throw CommandError{ "unwrap needs --curves FILE (polylines on the surface: cuts or seams)" };
  }
  if (!args.has("output") && !args.has("png"))
  {
    throw CommandError{ "unwrap needs -o OUT.obj and/or --png OUT.png (nothing would be written)" };
  }
  const int mode = exportMode(args.get("mode", "scissor"));
  const int method = flatteningMethod(args.get("method", "lscm"));
  const double margin = args.number("margin", 0.01, 0.0, 0.25);
  const int squares = args.integer("checker", 24, 1, 512);
  const int seams = args.integer("seams", 10, 0, 1000);
  if (args.has("png"))
  {
    RequireDisplay(); // before the work, not after
  }
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(input);
  vtkSmartPointer<vtkPolyData> curves = ReadMesh(args.get("curves"));
  const double readTime = MillisecondsSince(start);

  // Curves -> cut edges and charts (SeamCut's export, section 4) -> one UV chart each, packed.
  vtkNew<vtkCurveExport> cut;
  cut->SetInputData(0, mesh);
  cut->SetInputData(1, curves);
  cut->SetMode(mode);
  auto stage = std::chrono::steady_clock::now();
  RunAlgorithm(cut, "cannot cut the mesh along the curves");
  const double exportTime = MillisecondsSince(stage);
  vtkNew<vtkChartParameterization> atlas;
  atlas->SetInputConnection(cut->GetOutputPort(0));
  atlas->SetMethod(method);
  atlas->SetMargin(margin);
  atlas->SetMaximumSeams(seams);
  atlas->SetCutToDisks(!args.has("refuse-non-disks"));
  stage = std::chrono::steady_clock::now();
  RunAlgorithm(atlas, "cannot flatten the charts");
  const double atlasTime = MillisecondsSince(stage);
  vtkPolyData* surface = atlas->GetOutput(0);

  if (args.has("output"))
  {
    const std::string file = args.get("output");
    // The texture coordinates travel as TCoords: OBJ (vt), PLY (u v), VTP and VTK keep them.
    WriteMesh(surface, file);
  }
  if (args.has("png"))
  {
    SceneOptions left = ParseSceneOptions(args);
    left.checkerboardSquares = squares;
    left.frameLongestAxis = true;
    if (!args.has("size"))
    {
      left.width = 1200;
      left.height = 600;
    }
    if (left.caption.empty())
    {
      left.caption = vtksys::SystemTools::GetFilenameName(input) + " textured with a checkerboard";
    }
    SceneOptions right = left;
    right.colorArray = "Stretch";
    right.colorMap = SceneOptions::ColorMap::Sequential;
    right.checkerboardSquares = 0;
    right.frameLongestAxis = false;
    right.azimuth = 0.0;
    right.elevation = 0.0;
    right.zoom = 0.9;
    right.legendTitle = "stretch";
    right.caption = "UV layout in the unit square, coloured by stretch";
    std::string error;
    vtkSmartPointer<vtkRenderWindow> window = RenderPair(surface, left, atlas->GetOutput(1), right, error);
    if (!window || !WritePNG(window, args.get("png"), error))
    {
      throw CommandError{ "cannot render: " + error };
    }
  }
  if (!args.has("quiet"))
  {
    std::cout << std::fixed << std::setprecision(3) << "unwrap of " << input << ": "
              << counted(static_cast<int>(fieldValue(surface, "ChartCount")), "chart") << " ("
              << static_cast<int>(fieldValue(surface, "CutCharts")) << " cut into disks, "
              << counted(sumOf(surface, "ChartSeams"), "seam") << " added), " << surface->GetNumberOfPoints()
              << " points (" << mesh->GetNumberOfPoints() << " before the cut), " << surface->GetNumberOfPolys()
              << " triangles; stretch mean " << fieldValue(surface, "MeanStretch") << " max "
              << fieldValue(surface, "MaxStretch") << ", L2 " << fieldValue(surface, "L2Stretch") << ", shear mean "
              << fieldValue(surface, "MeanShear") << ", "
              << counted(static_cast<int>(fieldValue(surface, "FlippedFaces")), "flipped triangle") << ", "
              << counted(static_cast<int>(fieldValue(surface, "OverlappingChartPairs")), "overlapping chart pair")
              << std::setprecision(1) << "; time: read " << readTime << " ms, export " << exportTime << " ms, charts "
              << atlasTime << " ms\n";
  }
  return 0;
}

} // namespace kerf
