// kerf: the command-line program that runs Kerf's filters on mesh files and renders the results.
#include "KerfErrorCollector.h"
#include "KerfScene.h"
#include "vtkMeshFileReader.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineScoring.h"
#include "vtkMeshFileWriter.h"
#include "vtkStrokeConstraints.h"
#include "vtkSegmentationBenchmark.h"
#include "vtkSurfaceDescriptors.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkVariant.h>
#include <vtksys/SystemTools.hxx>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef KERF_SOURCE_DIR
#define KERF_SOURCE_DIR ""
#endif

namespace
{
const char* const Version = "0.1.0";

// A failure the program reports as "kerf: error: ..." with exit code 1.
struct CommandError
{
  std::string message;
};

// Parsed command line: positional arguments and --name value options (or --flag).
struct Arguments
{
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;

  bool has(const std::string& name) const { return this->options.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const
  {
    const auto found = this->options.find(name);
    return found == this->options.end() ? fallback : found->second;
  }
  double number(const std::string& name, double fallback) const
  {
    if (!this->has(name))
    {
      return fallback;
    }
    std::istringstream in(this->get(name));
    double value;
    if (!(in >> value) || !in.eof())
    {
      throw CommandError{ "--" + name + " expects a number, got '" + this->get(name) + "'" };
    }
    return value;
  }
};

// Options that take no value.
const char* const Flags[] = { "help", "quiet", "no-pictures" };

Arguments parse(int argc, char* argv[], int first)
{
  Arguments args;
  for (int i = first; i < argc; ++i)
  {
    std::string word = argv[i];
    if (word.size() > 2 && word.compare(0, 2, "--") == 0)
    {
      std::string name = word.substr(2);
      const std::size_t equals = name.find('=');
      if (equals != std::string::npos)
      {
        args.options[name.substr(0, equals)] = name.substr(equals + 1);
        continue;
      }
      bool flag = false;
      for (const char* f : Flags)
      {
        flag = flag || name == f;
      }
      if (flag)
      {
        args.options[name] = "1";
      }
      else if (i + 1 < argc)
      {
        args.options[name] = argv[++i];
      }
      else
      {
        throw CommandError{ "--" + name + " needs a value" };
      }
    }
    else if (word == "-o" && i + 1 < argc)
    {
      args.options["output"] = argv[++i];
    }
    else if (word == "-h")
    {
      args.options["help"] = "1";
    }
    else
    {
      args.positional.push_back(word);
    }
  }
  return args;
}

// Runs an algorithm, turning its VTK error into a CommandError with the message alone.
void run(vtkAlgorithm* algorithm, const std::string& what)
{
  vtkNew<kerf::ErrorCollector> errors;
  vtkNew<kerf::ErrorCollector> pipelineErrors;
  algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineErrors);
  const int ok = algorithm->GetExecutive()->Update();
  if (!ok || !errors->Message.empty())
  {
    throw CommandError{ what + ": " +
      (errors->Message.empty() ? pipelineErrors->Message : errors->Message) };
  }
}

vtkSmartPointer<vtkPolyData> readMesh(const std::string& fileName)
{
  vtkNew<vtkMeshFileReader> reader;
  reader->SetFileName(fileName.c_str());
  run(reader, "cannot read the mesh");
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}

void writeMesh(vtkPolyData* mesh, const std::string& fileName)
{
  vtkNew<vtkMeshFileWriter> writer;
  writer->SetFileName(fileName.c_str());
  writer->SetInputData(mesh);
  vtkNew<kerf::ErrorCollector> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  if (writer->Write() != 1 || !errors->Message.empty())
  {
    throw CommandError{ errors->Message.empty() ? "cannot write " + fileName : errors->Message };
  }
}

kerf::SceneOptions::ColorMap colorMap(const std::string& name)
{
  if (name == "diverging")
  {
    return kerf::SceneOptions::ColorMap::Diverging;
  }
  if (name == "sequential")
  {
    return kerf::SceneOptions::ColorMap::Sequential;
  }
  if (name == "categorical")
  {
    return kerf::SceneOptions::ColorMap::Categorical;
  }
  throw CommandError{ "--map must be diverging, sequential or categorical, got '" + name + "'" };
}

kerf::SceneOptions sceneOptions(const Arguments& args)
{
  kerf::SceneOptions options;
  options.colorArray = args.get("array");
  options.colorMap = colorMap(args.get("map", "diverging"));
  options.directionArray = args.get("directions");
  options.caption = args.get("caption");
  options.azimuth = args.number("azimuth", options.azimuth);
  options.elevation = args.number("elevation", options.elevation);
  options.rangeFraction = args.number("range-fraction", options.rangeFraction);
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
    if (x == std::string::npos || options.width < 16 || options.height < 16 ||
      options.width > 8192 || options.height > 8192)
    {
      throw CommandError{ "--size expects WIDTHxHEIGHT between 16 and 8192, got '" + size + "'" };
    }
  }
  return options;
}

void renderPNG(vtkPolyData* mesh, const kerf::SceneOptions& options, const std::string& fileName)
{
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(mesh, options, error);
  if (!window)
  {
    throw CommandError{ "cannot render: " + error };
  }
  if (!kerf::WritePNG(window, fileName, error))
  {
    throw CommandError{ error };
  }
}

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string arrayList(vtkPolyData* mesh)
{
  std::string names;
  for (int i = 0; i < mesh->GetPointData()->GetNumberOfArrays(); ++i)
  {
    names += (names.empty() ? "" : ", ") + std::string(mesh->GetPointData()->GetArrayName(i));
  }
  return names;
}

std::string requireOne(const Arguments& args, const char* what)
{
  if (args.positional.size() != 1)
  {
    throw CommandError{ std::string("expected one ") + what + " (see --help)" };
  }
  return args.positional[0];
}

// ---- commands -------------------------------------------------------------------------------

int info(const Arguments& args)
{
  const std::string input = requireOne(args, "mesh file");
  vtkSmartPointer<vtkPolyData> mesh = readMesh(input);
  double bounds[6];
  mesh->GetBounds(bounds);
  std::cout << input << "\n  points: " << mesh->GetNumberOfPoints()
            << "\n  cells: " << mesh->GetNumberOfCells() << " (" << mesh->GetNumberOfPolys()
            << " polygons, " << mesh->GetNumberOfStrips() << " strips, " << mesh->GetNumberOfLines()
            << " lines, " << mesh->GetNumberOfVerts() << " vertices)"
            << "\n  bounds: [" << bounds[0] << ", " << bounds[1] << "] x [" << bounds[2] << ", "
            << bounds[3] << "] x [" << bounds[4] << ", " << bounds[5] << "]\n";
  vtkNew<vtkSurfaceDescriptors> check;
  check->SetInputData(mesh);
  try
  {
    run(check, "validation");
    std::cout << "  surface: accepted by Kerf's filters\n";
  }
  catch (const CommandError& e)
  {
    std::cout << "  surface: " << e.message << "\n";
    return 1;
  }
  return 0;
}

int convert(const Arguments& args)
{
  if (args.positional.size() != 2)
  {
    throw CommandError{ "expected an input and an output file (see --help)" };
  }
  writeMesh(readMesh(args.positional[0]), args.positional[1]);
  if (!args.has("quiet"))
  {
    std::cout << "wrote " << args.positional[1] << "\n";
  }
  return 0;
}

int render(const Arguments& args)
{
  const std::string input = requireOne(args, "mesh file");
  if (!args.has("output"))
  {
    throw CommandError{ "render needs -o FILE.png" };
  }
  renderPNG(readMesh(input), sceneOptions(args), args.get("output"));
  if (!args.has("quiet"))
  {
    std::cout << "wrote " << args.get("output") << "\n";
  }
  return 0;
}

int descriptors(const Arguments& args)
{
  const std::string input = requireOne(args, "mesh file");
  vtkSmartPointer<vtkPolyData> mesh = readMesh(input);
  vtkNew<vtkSurfaceDescriptors> filter;
  filter->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  run(filter, "surface descriptors");
  const double milliseconds = millisecondsSince(start);
  vtkPolyData* output = filter->GetOutput();
  if (args.has("output"))
  {
    writeMesh(output, args.get("output"));
  }
  if (args.has("png"))
  {
    kerf::SceneOptions options = sceneOptions(args);
    if (options.colorArray.empty())
    {
      options.colorArray = "MeanCurvature";
      options.rangeFraction = args.number("range-fraction", 0.85);
      options.directionArray = args.get("directions", "MinimumCurvatureDirection");
    }
    renderPNG(output, options, args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << "surface descriptors of " << input << ": " << output->GetNumberOfPoints()
              << " points, " << output->GetNumberOfPolys() << " triangles in " << std::fixed
              << std::setprecision(1) << milliseconds << " ms\n  arrays: " << arrayList(output)
              << "\n";
  }
  return 0;
}


// ---- harmonic cuts --------------------------------------------------------------------------

// The stages of a stroke cut, kept alive together so that their outputs stay valid.
struct CutPipeline
{
  vtkNew<vtkSurfaceDescriptors> descriptors;
  vtkNew<vtkStrokeConstraints> constraints;
  vtkNew<vtkHarmonicField> field;
  vtkNew<vtkIsolineScoring> cut;
  std::map<std::string, double> milliseconds;
};

int weightingCode(const std::string& name)
{
  if (name == "uniform")
  {
    return vtkHarmonicField::UNIFORM;
  }
  if (name == "cotangent")
  {
    return vtkHarmonicField::COTANGENT;
  }
  if (name == "concavity")
  {
    return vtkHarmonicField::CONCAVITY_AWARE;
  }
  if (name == "smooth-concavity")
  {
    return vtkHarmonicField::SMOOTH_CONCAVITY;
  }
  throw CommandError{ "--weighting must be uniform, cotangent, concavity or smooth-concavity, got '" + name + "'" };
}

// mesh -> descriptors -> stroke constraints -> harmonic field -> cut nearest the stroke.
void runCut(CutPipeline& p, vtkPolyData* mesh, vtkPolyData* stroke, const Arguments& args)
{
  auto timed = [&p](vtkAlgorithm* algorithm, const std::string& stage) {
    const auto start = std::chrono::steady_clock::now();
    run(algorithm, stage);
    p.milliseconds[stage] = millisecondsSince(start);
  };
  p.descriptors->SetInputData(mesh);
  timed(p.descriptors, "surface descriptors");
  p.constraints->SetInputConnection(p.descriptors->GetOutputPort());
  p.constraints->SetInputData(1, stroke);
  p.constraints->SetSamplesPerSegment(static_cast<int>(args.number("samples", 4)));
  p.constraints->SetOffset(args.number("offset", 0.01));
  p.constraints->SetIsoValue(args.number("iso-value", 0.0));
  timed(p.constraints, "stroke constraints");
  p.field->SetInputConnection(p.descriptors->GetOutputPort());
  p.field->SetInputConnection(1, p.constraints->GetOutputPort());
  p.field->SetWeighting(weightingCode(args.get("weighting", "cotangent")));
  p.field->SetSoftConstraintWeight(args.number("soft-weight", 1.0));
  timed(p.field, "harmonic field");
  p.cut->SetInputConnection(p.field->GetOutputPort());
  p.cut->SetInputData(1, stroke);
  p.cut->SetModeToNearStroke();
  p.cut->SetIsoValue(args.number("iso-value", 0.0));
  timed(p.cut, "cut");
}

// Left: the field with isolines, the stroke and its constraints; right: the segments and the cut.
void renderCut(CutPipeline& p, vtkPolyData* stroke, const std::string& caption, const std::string& file)
{
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderCutScene(p.cut->GetLabelledSurface(), stroke,
    p.constraints->GetOutput(), p.cut->GetOutput(), caption, error);
  if (!window || !kerf::WritePNG(window, file, error))
  {
    throw CommandError{ "cannot draw the cut: " + error };
  }
}

std::string segmentSizes(vtkPolyData* surface)
{
  vtkDataArray* labels = surface->GetCellData()->GetArray("Segment");
  std::map<int, int> sizes;
  for (vtkIdType c = 0; c < labels->GetNumberOfTuples(); ++c)
  {
    ++sizes[static_cast<int>(labels->GetComponent(c, 0))];
  }
  std::ostringstream out;
  out << sizes.size() << " segments (";
  bool first = true;
  for (const auto& entry : sizes)
  {
    out << (first ? "" : ", ") << entry.second;
    first = false;
  }
  out << " triangles)";
  return out.str();
}

std::string cutSummary(vtkPolyData* curve)
{
  std::ostringstream out;
  double length = 0.0;
  int closed = 0;
  for (vtkIdType c = 0; c < curve->GetNumberOfCells(); ++c)
  {
    length += curve->GetCellData()->GetArray("Length")->GetComponent(c, 0);
    closed += static_cast<int>(curve->GetCellData()->GetArray("Closed")->GetComponent(c, 0));
  }
  out << curve->GetNumberOfCells() << (curve->GetNumberOfCells() == 1 ? " curve" : " curves") << " ("
      << closed << " closed), length " << std::setprecision(4) << length;
  return out.str();
}

int cut(const Arguments& args)
{
  const std::string input = requireOne(args, "mesh file");
  if (!args.has("stroke"))
  {
    throw CommandError{ "cut needs --stroke FILE (a polyline drawn on the surface)" };
  }
  vtkSmartPointer<vtkPolyData> mesh = readMesh(input);
  vtkSmartPointer<vtkPolyData> stroke = readMesh(args.get("stroke"));
  CutPipeline pipeline;
  runCut(pipeline, mesh, stroke, args);
  if (args.has("output"))
  {
    writeMesh(pipeline.cut->GetLabelledSurface(), args.get("output"));
  }
  if (args.has("curve"))
  {
    writeMesh(pipeline.cut->GetOutput(), args.get("curve"));
  }
  if (args.has("png"))
  {
    renderCut(pipeline, stroke, "harmonic field from one stroke", args.get("png"));
  }
  if (!args.has("quiet"))
  {
    std::cout << "cut of " << input << ": " << cutSummary(pipeline.cut->GetOutput()) << "; "
              << segmentSizes(pipeline.cut->GetLabelledSurface()) << "\n";
  }
  return 0;
}

std::string defaultShowcaseMesh(const char* program)
{
  // Installed: <prefix>/bin/kerf and <prefix>/share/kerf/Data; in the build tree: the sources.
  const std::string directory = vtksys::SystemTools::GetFilenamePath(
    vtksys::SystemTools::CollapseFullPath(program));
  const std::string installed = directory + "/../share/kerf/Data/camel.off";
  if (vtksys::SystemTools::FileExists(installed, true))
  {
    return vtksys::SystemTools::CollapseFullPath(installed);
  }
  return std::string(KERF_SOURCE_DIR) + "/Data/camel.off";
}

int showcase(const Arguments& args, const char* program)
{
  if (args.positional.size() > 1)
  {
    throw CommandError{ "expected at most one mesh file (see --help)" };
  }
  const std::string input = args.positional.empty() ? defaultShowcaseMesh(program) : args.positional[0];
  const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(input);
  const std::string strokeFile = args.has("stroke") ? args.get("stroke")
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
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyData> mesh = readMesh(input);
  vtkSmartPointer<vtkPolyData> stroke = readMesh(strokeFile);
  const double readTime = millisecondsSince(start);
  CutPipeline pipeline;
  runCut(pipeline, mesh, stroke, args);
  vtkPolyData* surface = pipeline.cut->GetLabelledSurface();
  vtkPolyData* curve = pipeline.cut->GetOutput();

  const std::string surfaceFile = folder + "/" + stem + "-cut.vtp";
  const std::string curveFile = folder + "/" + stem + "-cut-curve.vtp";
  const std::string imageFile = folder + "/" + stem + "-cut.png";
  writeMesh(surface, surfaceFile);
  writeMesh(curve, curveFile);
  renderCut(pipeline, stroke, stem + ": a cut from one stroke", imageFile);

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
            << "  computed:  point arrays " << arrayList(surface) << "\n"
            << "             cell arrays " << cellArrays << "\n"
            << "  cut:       " << cutSummary(curve) << "; " << segmentSizes(surface) << "\n"
            << "  solve:     " << args.get("weighting", "cotangent") << " weights, "
            << vtkStringArray::SafeDownCast(solve->GetAbstractArray("SolverWork"))->GetValue(0)
            << ", relative residual " << std::scientific << std::setprecision(1)
            << solve->GetArray("RelativeResidual")->GetComponent(0, 0) << std::fixed << "\n"
            << "  time:      read " << readTime << " ms";
  for (const char* stage : { "surface descriptors", "stroke constraints", "harmonic field", "cut" })
  {
    std::cout << ", " << stage << " " << pipeline.milliseconds[stage] << " ms";
  }
  std::cout << "; total " << millisecondsSince(start) << " ms\n"
            << "  surface:   " << vtksys::SystemTools::CollapseFullPath(surfaceFile) << "\n"
            << "  cut curve: " << vtksys::SystemTools::CollapseFullPath(curveFile) << "\n"
            << "  picture:   " << vtksys::SystemTools::CollapseFullPath(imageFile) << "\n";
  return 0;
}

// ---- the benchmark runner -------------------------------------------------------------------

// Columns of results.csv after the model, category, method and parameters.
const char* const ResultColumns[] = { "Comparisons", "CutDiscrepancy", "HammingDistance",
  "MissingRate", "FalseAlarmRate", "RandIndexError", "GlobalConsistencyError",
  "LocalConsistencyError", "Segments", "Seconds" };
const char* const SummaryMetrics[] = { "CutDiscrepancy", "HammingDistance", "RandIndexError",
  "GlobalConsistencyError", "LocalConsistencyError", "Seconds" };

struct ModelRow
{
  int model = 0;
  std::string category;
  std::map<std::string, double> values;
  std::string csv; // the whole line of results.csv
};

std::string quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + "\"";
}

// Runs the method on one model, writes its picture, and returns its row.
ModelRow runModel(const std::string& data, const std::string& method, const std::string& parameters,
  int model, const std::string& pictures)
{
  vtkNew<vtkSegmentationBenchmark> benchmark;
  benchmark->SetDataDirectory(data.c_str());
  benchmark->SetMethod(method.c_str());
  benchmark->SetMethodParameters(parameters.c_str());
  benchmark->AddModel(model);
  run(benchmark, "model " + std::to_string(model));
  vtkTable* table = benchmark->GetOutput();
  ModelRow row;
  row.model = model;
  row.category = table->GetValueByName(0, "Category").ToString();
  std::ostringstream line;
  line << std::setprecision(10) << model << "," << row.category << "," << method << ","
       << quoted(parameters);
  for (const char* column : ResultColumns)
  {
    row.values[column] = table->GetValueByName(0, column).ToDouble();
    line << "," << row.values[column];
  }
  row.csv = line.str();
  if (!pictures.empty())
  {
    kerf::SceneOptions left;
    left.colorArray = "Method";
    left.colorMap = kerf::SceneOptions::ColorMap::Categorical;
    left.width = 1000;
    left.height = 520;
    left.caption = "model " + std::to_string(model) + ": " + method;
    left.frameLongestAxis = true;
    left.zoom = 1.0;
    left.azimuth = 20.0;
    left.elevation = 15.0;
    kerf::SceneOptions right = left;
    right.colorArray = "Human";
    right.caption = method == "human" ? "another human" : "a human";
    vtkPolyData* shown = vtkPolyData::SafeDownCast(benchmark->GetOutputDataObject(1));
    std::string error;
    vtkSmartPointer<vtkRenderWindow> window = kerf::RenderSideBySide(shown, left, right, error);
    if (!window || !kerf::WritePNG(window, pictures + "/" + std::to_string(model) + ".png", error))
    {
      throw CommandError{ "model " + std::to_string(model) + ": cannot draw its picture: " + error };
    }
  }
  return row;
}

// Parses one results.csv line back into a row (for rows that come from worker processes).
ModelRow parseRow(const std::string& line)
{
  ModelRow row;
  row.csv = line;
  std::vector<std::string> fields;
  std::string field;
  bool inQuotes = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (c == '"')
    {
      if (inQuotes && i + 1 < line.size() && line[i + 1] == '"')
      {
        field += '"';
        ++i;
      }
      else
      {
        inQuotes = !inQuotes;
      }
    }
    else if (c == ',' && !inQuotes)
    {
      fields.push_back(field);
      field.clear();
    }
    else
    {
      field += c;
    }
  }
  fields.push_back(field);
  if (fields.size() != 4 + sizeof(ResultColumns) / sizeof(ResultColumns[0]))
  {
    throw CommandError{ "a worker sent a malformed result: " + line };
  }
  row.model = std::stoi(fields[0]);
  row.category = fields[1];
  for (std::size_t c = 0; c < sizeof(ResultColumns) / sizeof(ResultColumns[0]); ++c)
  {
    row.values[ResultColumns[c]] = std::stod(fields[4 + c]);
  }
  return row;
}

void printProgress(std::size_t done, std::size_t total, const ModelRow& row)
{
  std::cout << "[" << std::setw(3) << done << "/" << total << "] model " << std::setw(4) << row.model
            << " " << std::left << std::setw(10) << row.category << std::right << " 1-RI "
            << std::fixed << std::setprecision(3) << row.values.at("RandIndexError") << "  CD "
            << row.values.at("CutDiscrepancy") << "  HD " << row.values.at("HammingDistance")
            << "  (" << std::setprecision(2) << row.values.at("Seconds") << " s)" << std::endl;
}

// Runs models in `jobs` worker processes; each sends one results.csv line per model through a
// pipe, so the parent can show progress as models finish.
std::vector<ModelRow> runInWorkers(const std::vector<int>& models, int jobs,
  const std::function<ModelRow(int)>& work)
{
  std::vector<ModelRow> rows;
  if (jobs <= 1)
  {
    for (int model : models)
    {
      rows.push_back(work(model));
      printProgress(rows.size(), models.size(), rows.back());
    }
    return rows;
  }
  struct Worker
  {
    pid_t pid;
    int fd;
    std::string buffer;
  };
  std::vector<Worker> workers;
  std::cout.flush();
  for (int w = 0; w < jobs; ++w)
  {
    int fds[2];
    if (pipe(fds) != 0)
    {
      throw CommandError{ "cannot create a pipe for the workers" };
    }
    const pid_t pid = fork();
    if (pid < 0)
    {
      throw CommandError{ "cannot start a worker process" };
    }
    if (pid == 0)
    {
      close(fds[0]);
      int status = 0;
      for (std::size_t i = static_cast<std::size_t>(w); i < models.size(); i += static_cast<std::size_t>(jobs))
      {
        try
        {
          const std::string line = work(models[i]).csv + "\n";
          if (write(fds[1], line.data(), line.size()) != static_cast<ssize_t>(line.size()))
          {
            status = 1;
          }
        }
        catch (const CommandError& e)
        {
          const std::string line = "!" + e.message + "\n";
          (void)!write(fds[1], line.data(), line.size());
          status = 1;
        }
      }
      close(fds[1]);
      std::fflush(nullptr);
      _exit(status);
    }
    close(fds[1]);
    workers.push_back({ pid, fds[0], "" });
  }
  std::vector<std::string> failures;
  std::size_t open = workers.size();
  while (open > 0)
  {
    std::vector<pollfd> fds;
    for (const Worker& w : workers)
    {
      fds.push_back({ w.fd, POLLIN, 0 });
    }
    if (poll(fds.data(), fds.size(), -1) < 0)
    {
      continue;
    }
    for (std::size_t i = 0; i < workers.size(); ++i)
    {
      if (workers[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP)))
      {
        continue;
      }
      char chunk[4096];
      const ssize_t n = read(workers[i].fd, chunk, sizeof(chunk));
      if (n <= 0)
      {
        close(workers[i].fd);
        workers[i].fd = -1;
        --open;
        continue;
      }
      workers[i].buffer.append(chunk, static_cast<std::size_t>(n));
      std::size_t end;
      while ((end = workers[i].buffer.find('\n')) != std::string::npos)
      {
        const std::string line = workers[i].buffer.substr(0, end);
        workers[i].buffer.erase(0, end + 1);
        if (!line.empty() && line[0] == '!')
        {
          failures.push_back(line.substr(1));
          std::cerr << "kerf: error: " << line.substr(1) << std::endl;
          continue;
        }
        rows.push_back(parseRow(line));
        printProgress(rows.size(), models.size(), rows.back());
      }
    }
  }
  for (const Worker& w : workers)
  {
    int status = 0;
    waitpid(w.pid, &status, 0);
  }
  if (!failures.empty())
  {
    throw CommandError{ std::to_string(failures.size()) + " model(s) failed; first: " + failures[0] };
  }
  std::sort(rows.begin(), rows.end(), [](const ModelRow& a, const ModelRow& b) { return a.model < b.model; });
  return rows;
}

// Per-category and overall means, written as CSV and printed as a table.
void writeSummary(const std::vector<ModelRow>& rows, const std::string& method, const std::string& file)
{
  std::vector<std::pair<std::string, std::vector<const ModelRow*>>> groups;
  for (const ModelRow& row : rows)
  {
    auto group = std::find_if(groups.begin(), groups.end(),
      [&row](const auto& g) { return g.first == row.category; });
    if (group == groups.end())
    {
      groups.emplace_back(row.category, std::vector<const ModelRow*>());
      group = groups.end() - 1;
    }
    group->second.push_back(&row);
  }
  std::sort(groups.begin(), groups.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const ModelRow*> all;
  for (const ModelRow& row : rows)
  {
    all.push_back(&row);
  }
  groups.emplace_back("all", all);
  std::ofstream csv(file);
  csv << "Category,Method,Models";
  for (const char* metric : SummaryMetrics)
  {
    csv << "," << metric;
  }
  csv << "\n";
  std::cout << "\n" << std::left << std::setw(11) << "category" << std::right << std::setw(7)
            << "models" << std::setw(9) << "CD" << std::setw(9) << "HD" << std::setw(9) << "1-RI"
            << std::setw(9) << "GCE" << std::setw(9) << "LCE" << std::setw(10) << "seconds" << "\n";
  for (const auto& group : groups)
  {
    csv << group.first << "," << method << "," << group.second.size();
    std::cout << std::left << std::setw(11) << group.first << std::right << std::setw(7)
              << group.second.size();
    for (const char* metric : SummaryMetrics)
    {
      double sum = 0.0;
      for (const ModelRow* row : group.second)
      {
        sum += row->values.at(metric);
      }
      const double mean = sum / static_cast<double>(group.second.size());
      csv << "," << std::setprecision(10) << mean;
      std::cout << std::fixed << std::setprecision(3) << std::setw(std::string(metric) == "Seconds" ? 10 : 9) << mean;
    }
    csv << "\n";
    std::cout << "\n";
  }
  if (!csv)
  {
    throw CommandError{ "cannot write " + file };
  }
}

int benchmark(const Arguments& args)
{
  if (!args.positional.empty() || !args.has("data"))
  {
    throw CommandError{ "benchmark needs --data FOLDER (see --help)" };
  }
  const std::string data = args.get("data");
  const std::string method = args.get("method", "human");
  const std::string parameters = args.get("parameters");
  const std::string folder = args.get("output", "kerf-benchmark");
  const double jobs = args.number("jobs", 1.0);
  if (jobs < 1 || jobs > 64 || jobs != std::floor(jobs))
  {
    throw CommandError{ "--jobs expects a whole number from 1 to 64" };
  }
  std::vector<int> models;
  if (args.has("models"))
  {
    std::istringstream list(args.get("models"));
    std::string item;
    while (std::getline(list, item, ','))
    {
      try
      {
        models.push_back(std::stoi(item));
      }
      catch (const std::exception&)
      {
        throw CommandError{ "--models expects ids separated by commas, got '" + args.get("models") + "'" };
      }
    }
  }
  else
  {
    std::string error;
    models = vtkSegmentationBenchmark::FindModels(data, error);
    if (models.empty())
    {
      throw CommandError{ error.empty() ? data + " holds no models" : error };
    }
  }
  const std::string pictures = args.has("no-pictures") ? "" : folder + "/pictures";
  if (!vtksys::SystemTools::MakeDirectory(folder) ||
    (!pictures.empty() && !vtksys::SystemTools::MakeDirectory(pictures)))
  {
    throw CommandError{ "cannot create the output folder " + folder };
  }
  std::cout << "Kerf benchmark: method " << method << " on " << models.size() << " models of "
            << data << " with " << jobs << (jobs == 1 ? " process" : " processes") << std::endl;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ModelRow> rows = runInWorkers(models, static_cast<int>(jobs),
    [&](int model) { return runModel(data, method, parameters, model, pictures); });

  const std::string results = folder + "/results.csv";
  std::ofstream csv(results);
  csv << "Model,Category,Method,Parameters";
  for (const char* column : ResultColumns)
  {
    csv << "," << column;
  }
  csv << "\n";
  for (const ModelRow& row : rows)
  {
    csv << row.csv << "\n";
  }
  if (!csv)
  {
    throw CommandError{ "cannot write " + results };
  }
  csv.close();
  writeSummary(rows, method, folder + "/summary.csv");
  std::cout << "\nresults:  " << vtksys::SystemTools::CollapseFullPath(results)
            << "\nsummary:  " << vtksys::SystemTools::CollapseFullPath(folder + "/summary.csv");
  if (!pictures.empty())
  {
    std::cout << "\npictures: " << vtksys::SystemTools::CollapseFullPath(pictures);
  }
  std::cout << "\ntime:     " << std::fixed << std::setprecision(1)
            << millisecondsSince(start) / 1000.0 << " s" << std::endl;
  return 0;
}

struct Command
{
  const char* name;
  const char* usage;
  const char* help;
};

const Command Commands[] = {
  { "showcase", "kerf showcase [MESH] [--stroke FILE] [-o FOLDER]",
    "The showcase pipeline: cuts MESH (default: the bundled camel) along a stroke (default:\n"
    "<mesh>-neck-stroke.vtk beside the mesh): surface descriptors, stroke constraints, harmonic\n"
    "field, the isoline nearest the stroke and the segments it bounds. Writes the surface with\n"
    "every computed array (.vtp), the cut curve (.vtp) and a picture (.png) into FOLDER\n"
    "(default: kerf-output), then prints a summary." },
  { "cut", "kerf cut MESH --stroke FILE [-o OUT.vtp] [--curve CURVE.vtp] [--png OUT.png] [cut options]",
    "Cuts MESH along the isoline of a harmonic field built from a stroke (SeamCut): the stroke\n"
    "becomes +1/-1 constraints on both sides, the field is solved, and the isoline nearest the\n"
    "stroke splits the mesh into segments (cell array Segment).\n"
    "Cut options: --weighting uniform|cotangent|concavity|smooth-concavity (cotangent),\n"
    "--iso-value I (0), --samples N per stroke segment (4), --offset F of the diagonal (0.01),\n"
    "--soft-weight W (1)." },
  { "descriptors", "kerf descriptors MESH [-o OUT.vtp] [--png OUT.png] [render options]",
    "Computes the surface descriptors (normals, principal curvatures and directions, mean and\n"
    "Gaussian curvature, concavity, normal-cone angle) and writes them and/or a picture." },
  { "info", "kerf info MESH",
    "Prints the mesh size and whether Kerf's filters accept it (and if not, why). Exit code 1\n"
    "when the surface is refused." },
  { "convert", "kerf convert IN OUT", "Converts between mesh formats (by extension)." },
  { "render", "kerf render MESH -o OUT.png [render options]",
    "Renders a mesh, coloured by a point or cell array, to a PNG." },
  { "benchmark",
    "kerf benchmark --data FOLDER [--method NAME] [--parameters P] [--models 1,9] [--jobs N] [-o FOLDER]",
    "Runs a segmentation method over a folder in the Princeton benchmark's layout (off/N.off,\n"
    "seg/N/N_j.seg, nSeg-ByModel.txt) and scores it against the human segmentations. Writes\n"
    "results.csv (one row per model: model, category, method, parameters, every metric, time),\n"
    "summary.csv (means per category and overall) and pictures/N.png (the method's segmentation\n"
    "beside a human's) into the output folder (default: kerf-benchmark). Methods: human (every\n"
    "pair of the model's human segmentations: the human baseline). --jobs N runs N processes;\n"
    "--no-pictures skips the pictures." },
};

void printHelp()
{
  std::cout << "kerf " << Version << ": mesh segmentation with VTK\n\n"
            << "Usage: kerf COMMAND [ARGUMENTS] [OPTIONS]\n\nCommands:\n";
  for (const Command& c : Commands)
  {
    std::cout << "  " << std::left << std::setw(12) << c.name << c.usage << "\n";
  }
  std::cout << "\nMesh files: .off .ply .obj .stl .vtp .vtk (read); .vtp .vtk .ply .obj .stl .off (write).\n"
            << "\nRender options:\n"
            << "  --array NAME          colour by this point or cell array\n"
            << "  --map diverging|sequential|categorical   colour map (default diverging)\n"
            << "  --directions NAME     draw this 3-component point array as strokes\n"
            << "  --range-fraction F    colour range covers this fraction of the values (0.95)\n"
            << "  --size WxH            image size in pixels (900x700)\n"
            << "  --azimuth DEG --elevation DEG   camera rotation (30, 20)\n"
            << "  --caption TEXT        caption in the top-left corner\n"
            << "\nOther options: -o FILE (output), --quiet, -h/--help (also after a command).\n"
            << "Rendering needs a display; on a headless machine run under xvfb-run -a.\n";
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" ||
    std::string(argv[1]) == "help")
  {
    printHelp();
    return argc < 2 ? 2 : 0;
  }
  if (std::string(argv[1]) == "--version")
  {
    std::cout << "kerf " << Version << "\n";
    return 0;
  }
  const std::string name = argv[1];
  try
  {
    const Arguments args = parse(argc, argv, 2);
    for (const Command& c : Commands)
    {
      if (name != c.name)
      {
        continue;
      }
      if (args.has("help"))
      {
        std::cout << "Usage: " << c.usage << "\n\n" << c.help << "\n";
        return 0;
      }
      if (name == "showcase")
      {
        return showcase(args, argv[0]);
      }
      if (name == "descriptors")
      {
        return descriptors(args);
      }
      if (name == "info")
      {
        return info(args);
      }
      if (name == "benchmark")
      {
        return benchmark(args);
      }
      if (name == "cut")
      {
        return cut(args);
      }
      if (name == "convert")
      {
        return convert(args);
      }
      return render(args);
    }
    throw CommandError{ "unknown command '" + name + "' (see kerf --help)" };
  }
  catch (const CommandError& e)
  {
    std::cerr << "kerf: error: " << e.message << std::endl;
    return 1;
  }
}
