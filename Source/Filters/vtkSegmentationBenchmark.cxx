// vtkSegmentationBenchmark: per model, loads the mesh and humans, runs the method, averages scores.
#include "vtkSegmentationBenchmark.h"

#include "Error.h"
#include "Evaluation/PrincetonBenchmark.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Evaluation/SimulatedStrokes.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Harmonic/LaplacianWeights.h"
#include "Harmonic/StrokeConstraints.h"
#include "IO/MeshFormats.h"
#include "KerfErrorCollector.h"
#include "KerfSurfaceInput.h"
#include "vtkOFFReader.h"

#include <vtkCommand.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkExecutive.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

vtkStandardNewMacro(vtkSegmentationBenchmark);

namespace
{
const char* const MetricNames[] = { "CutDiscrepancy", "HammingDistance", "MissingRate",
  "FalseAlarmRate", "RandIndexError", "GlobalConsistencyError", "LocalConsistencyError" };
constexpr int MetricCount = 7;

struct ModelResult
{
  double metrics[MetricCount] = { 0, 0, 0, 0, 0, 0, 0 };
  int comparisons = 0;
  double segments = 0.0;
  double seconds = 0.0;
  std::vector<int> shownMethod;
  std::vector<int> shownHuman;
};

void accumulate(ModelResult& result, const kerf::SegmentationScores& s, const kerf::SegmentationScores* reverse)
{
  const double values[MetricCount] = { s.cutDiscrepancy, s.hammingDistance,
    reverse ? 0.5 * (s.missingRate + reverse->missingRate) : s.missingRate,
    reverse ? 0.5 * (s.falseAlarmRate + reverse->falseAlarmRate) : s.falseAlarmRate,
    s.randIndexError, s.globalConsistencyError, s.localConsistencyError };
  for (int m = 0; m < MetricCount; ++m)
  {
    result.metrics[m] += values[m];
  }
  ++result.comparisons;
}

// The benchmark's human baseline: every unordered pair of human segmentations.
ModelResult runHumans(const kerf::SegmentationEvaluator& evaluator,
  const std::vector<kerf::PreparedSegmentation>& humans, const std::vector<std::vector<int>>& raw)
{
  ModelResult result;
  for (std::size_t a = 0; a < humans.size(); ++a)
  {
    result.segments += humans[a].segmentCount;
    for (std::size_t b = a + 1; b < humans.size(); ++b)
    {
      const kerf::SegmentationScores forward = evaluator.compare(humans[a], humans[b]);
      const kerf::SegmentationScores backward = evaluator.compare(humans[b], humans[a]);
      accumulate(result, forward, &backward);
    }
  }
  result.segments /= static_cast<double>(humans.size());
  result.shownMethod = raw[0];
  result.shownHuman = raw[1];
  return result;
}

// "name=value;name=value" into a map; throws on malformed pairs or unknown names.
std::map<std::string, std::string> parseParameters(const std::string& text, const std::vector<std::string>& known)
{
  std::map<std::string, std::string> values;
  std::size_t start = 0;
  while (start < text.size())
  {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string pair = text.substr(start, end - start);
    start = end + 1;
    if (pair.empty())
    {
      continue;
    }
    const std::size_t equals = pair.find('=');
    const std::string name = pair.substr(0, equals);
    if (equals == std::string::npos || std::find(known.begin(), known.end(), name) == known.end())
    {
      throw kerf::Error("unknown or malformed method parameter '" + pair + "'");
    }
    values[name] = pair.substr(equals + 1);
  }
  return values;
}

double numberParameter(const std::map<std::string, std::string>& values, const std::string& name, double fallback)
{
  const auto found = values.find(name);
  if (found == values.end())
  {
    return fallback;
  }
  try
  {
    std::size_t used = 0;
    const double value = std::stod(found->second, &used);
    if (used == found->second.size() && std::isfinite(value) && value > 0.0)
    {
      return value;
    }
  }
  catch (const std::exception&)
  {
  }
  throw kerf::Error("method parameter " + name + " must be a positive number, got '" + found->second + "'");
}

// SeamCut's harmonic cuts with simulated strokes: one stroke along each boundary between two
// segments of human 0, one field and cut per stroke, all cuts together segmenting the mesh;
// scored against the other humans.
ModelResult runHarmonicCuts(const kerf::TriangleMesh& mesh, const kerf::SegmentationEvaluator& evaluator,
  const std::vector<kerf::PreparedSegmentation>& humans, const std::vector<std::vector<int>>& raw,
  const std::string& parameterText)
{
  const std::map<std::string, std::string> parameters =
    parseParameters(parameterText, { "weighting", "samples", "offset", "spacing", "weight" });
  kerf::LaplacianWeightOptions weighting;
  const std::string weightingName = parameters.count("weighting") ? parameters.at("weighting") : "cotangent";
  if (weightingName == "cotangent")
  {
    weighting.weighting = kerf::LaplacianWeighting::Cotangent;
  }
  else if (weightingName == "uniform")
  {
    weighting.weighting = kerf::LaplacianWeighting::Uniform;
  }
  else if (weightingName == "concavity")
  {
    weighting.weighting = kerf::LaplacianWeighting::ConcavityAware;
  }
  else if (weightingName == "smooth-concavity")
  {
    weighting.weighting = kerf::LaplacianWeighting::SmoothConcavity;
  }
  else
  {
    throw kerf::Error("weighting must be cotangent, uniform, concavity or smooth-concavity, got '" + weightingName + "'");
  }
  const double diagonal = mesh.boundingBoxDiagonal();
  kerf::StrokeOptions strokeOptions;
  strokeOptions.samplesPerSegment = static_cast<int>(numberParameter(parameters, "samples", 4));
  strokeOptions.offset = numberParameter(parameters, "offset", 0.01) * diagonal;
  strokeOptions.maximumDistance = 0.05 * diagonal;
  const double spacing = numberParameter(parameters, "spacing", 0.03) * diagonal;
  const double softWeight = numberParameter(parameters, "weight", 1.0);

  const auto start = std::chrono::steady_clock::now();
  const std::vector<kerf::BoundaryStroke> strokes = kerf::boundaryStrokes(mesh, raw[0], spacing);
  const bool needsCurvature = weighting.weighting == kerf::LaplacianWeighting::ConcavityAware ||
    weighting.weighting == kerf::LaplacianWeighting::SmoothConcavity;
  kerf::SurfaceDescriptors descriptors;
  if (needsCurvature)
  {
    descriptors = kerf::computeSurfaceDescriptors(mesh);
  }
  const std::vector<double> weights =
    kerf::computeLaplacianWeights(mesh, weighting, needsCurvature ? &descriptors : nullptr);
  const kerf::ClosestPointLocator locator(mesh);
  const std::vector<kerf::Vector3> normals = kerf::computeVertexNormals(mesh);
  kerf::HarmonicFieldSolver solver;
  std::vector<std::vector<double>> fields;
  std::vector<std::vector<kerf::Isoline>> isolines;
  fields.reserve(strokes.size());
  isolines.reserve(strokes.size());
  std::vector<kerf::FieldCut> cuts;
  for (const kerf::BoundaryStroke& stroke : strokes)
  {
    const kerf::StrokeConstraintSet set =
      kerf::strokeConstraints(mesh, locator, normals, { stroke.points }, strokeOptions);
    kerf::FieldConstraints constraints;
    constraints.soft = set.constraints;
    constraints.softWeight = softWeight * kerf::laplacianMeanDiagonal(mesh, weights);
    fields.push_back(solver.solve(mesh, weights, constraints).field);
    isolines.push_back(kerf::extractIsolines(mesh, fields.back(), 0.0));
    const int nearest = kerf::nearestIsoline(isolines.back(), set.strokeSamples);
    if (nearest >= 0)
    {
      cuts.push_back({ &fields.back(), 0.0, { &isolines.back()[static_cast<std::size_t>(nearest)] } });
    }
  }
  const std::vector<int> labels = kerf::labelCuts(mesh, cuts);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  ModelResult result;
  const kerf::PreparedSegmentation prepared = evaluator.prepare(labels);
  for (std::size_t h = 1; h < humans.size(); ++h)
  {
    accumulate(result, evaluator.compare(prepared, humans[h]), nullptr);
  }
  result.segments = prepared.segmentCount;
  result.seconds = seconds;
  result.shownMethod = labels;
  result.shownHuman = raw[0];
  return result;
}

vtkSmartPointer<vtkIntArray> labelArray(const char* name, const std::vector<int>& labels)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  for (std::size_t i = 0; i < labels.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), labels[i]);
  }
  return array;
}
} // namespace

vtkSegmentationBenchmark::vtkSegmentationBenchmark()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  this->SetMethod("human");
  this->SetMethodParameters("");
}

vtkSegmentationBenchmark::~vtkSegmentationBenchmark()
{
  this->SetDataDirectory(nullptr);
  this->SetMethod(nullptr);
  this->SetMethodParameters(nullptr);
}

void vtkSegmentationBenchmark::AddModel(int id)
{
  this->Models.push_back(id);
  this->Modified();
}

void vtkSegmentationBenchmark::ClearModels()
{
  this->Models.clear();
  this->Modified();
}

std::vector<std::string> vtkSegmentationBenchmark::GetMethodNames()
{
  return { "human", "harmonic-cuts" };
}

std::vector<int> vtkSegmentationBenchmark::FindModels(const std::string& directory, std::string& error)
{
  std::vector<int> ids;
  try
  {
    for (const kerf::BenchmarkModel& model : kerf::scanBenchmark(directory))
    {
      ids.push_back(model.id);
    }
  }
  catch (const kerf::Error& e)
  {
    error = e.what();
    ids.clear();
  }
  return ids;
}

int vtkSegmentationBenchmark::FillInputPortInformation(int, vtkInformation*)
{
  return 1;
}

int vtkSegmentationBenchmark::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkSegmentationBenchmark::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkTable* table = vtkTable::GetData(outputVector, 0);
  vtkPolyData* shown = vtkPolyData::GetData(outputVector, 1);
  const std::string method = this->Method ? this->Method : "";
  const std::vector<std::string> methods = GetMethodNames();
  if (std::find(methods.begin(), methods.end(), method) == methods.end())
  {
    vtkErrorMacro("Unknown method '" << method << "'; the methods are: human, harmonic-cuts.");
    return 0;
  }
  if (!this->DataDirectory || !*this->DataDirectory)
  {
    vtkErrorMacro("No benchmark folder was given.");
    return 0;
  }

  std::vector<kerf::BenchmarkModel> models;
  try
  {
    const std::vector<kerf::BenchmarkModel> all = kerf::scanBenchmark(this->DataDirectory);
    if (this->Models.empty())
    {
      models = all;
    }
    for (int id : this->Models)
    {
      const auto found = std::find_if(all.begin(), all.end(),
        [id](const kerf::BenchmarkModel& m) { return m.id == id; });
      if (found == all.end())
      {
        vtkErrorMacro("Model " << id << " is not in " << this->DataDirectory << ".");
        return 0;
      }
      models.push_back(*found);
    }
  }
  catch (const kerf::Error& e)
  {
    vtkErrorMacro("Cannot read the benchmark: " << e.what());
    return 0;
  }

  vtkNew<vtkIntArray> modelColumn, comparisonColumn;
  vtkNew<vtkStringArray> categoryColumn, methodColumn, parameterColumn;
  modelColumn->SetName("Model");
  categoryColumn->SetName("Category");
  methodColumn->SetName("Method");
  parameterColumn->SetName("Parameters");
  comparisonColumn->SetName("Comparisons");
  vtkNew<vtkDoubleArray> metricColumns[MetricCount];
  for (int m = 0; m < MetricCount; ++m)
  {
    metricColumns[m]->SetName(MetricNames[m]);
  }
  vtkNew<vtkDoubleArray> segmentColumn, secondsColumn;
  segmentColumn->SetName("Segments");
  secondsColumn->SetName("Seconds");

  for (std::size_t index = 0; index < models.size(); ++index)
  {
    const kerf::BenchmarkModel& model = models[index];
    ModelResult result;
    vtkSmartPointer<vtkPolyData> mesh;
    try
    {
      if (model.humanSegmentations.size() < 2)
      {
        throw kerf::Error("it has " + std::to_string(model.humanSegmentations.size()) +
          " human segmentations; the protocol needs at least 2");
      }
      vtkNew<vtkOFFReader> reader;
      reader->SetFileName(model.meshFile.c_str());
      auto errors = vtkSmartPointer<kerf::ErrorCollector>::New();
      reader->AddObserver(vtkCommand::ErrorEvent, errors);
      reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, vtkSmartPointer<kerf::ErrorCollector>::New());
      if (!reader->GetExecutive()->Update())
      {
        throw kerf::Error(errors->Message);
      }
      mesh = reader->GetOutput();
      kerf::SurfaceInput surface;
      kerf::MeshRequirements requirements;
      requirements.manifold = false;
      requirements.consistentOrientation = false;
      std::string error;
      if (!surface.Load(mesh, requirements, error))
      {
        throw kerf::Error(error);
      }
      if (surface.Rebuilt())
      {
        throw kerf::Error("the benchmark's meshes are triangle meshes, but this one has other polygons");
      }
      const kerf::SegmentationEvaluator evaluator(surface.Mesh());
      std::vector<std::vector<int>> raw;
      std::vector<kerf::PreparedSegmentation> humans;
      for (const std::string& file : model.humanSegmentations)
      {
        raw.push_back(kerf::readSegmentation(file));
        humans.push_back(evaluator.prepare(raw.back()));
      }
      result = method == "human"
        ? runHumans(evaluator, humans, raw)
        : runHarmonicCuts(surface.Mesh(), evaluator, humans, raw, this->MethodParameters ? this->MethodParameters : "");
    }
    catch (const kerf::Error& e)
    {
      vtkErrorMacro("Model " << model.id << " (" << model.meshFile << "): " << e.what());
      return 0;
    }

    modelColumn->InsertNextValue(model.id);
    categoryColumn->InsertNextValue(model.category);
    methodColumn->InsertNextValue(method);
    parameterColumn->InsertNextValue(this->MethodParameters ? this->MethodParameters : "");
    comparisonColumn->InsertNextValue(result.comparisons);
    for (int m = 0; m < MetricCount; ++m)
    {
      metricColumns[m]->InsertNextValue(result.comparisons > 0 ? result.metrics[m] / result.comparisons : 0.0);
    }
    segmentColumn->InsertNextValue(result.segments);
    secondsColumn->InsertNextValue(result.seconds);
    if (index + 1 == models.size())
    {
      shown->ShallowCopy(mesh);
      shown->GetCellData()->AddArray(
        labelArray("Method", kerf::matchLabels(result.shownMethod, result.shownHuman)));
      shown->GetCellData()->AddArray(labelArray("Human", result.shownHuman));
    }
    this->UpdateProgress(static_cast<double>(index + 1) / static_cast<double>(models.size()));
  }
  table->AddColumn(modelColumn);
  table->AddColumn(categoryColumn);
  table->AddColumn(methodColumn);
  table->AddColumn(parameterColumn);
  table->AddColumn(comparisonColumn);
  for (int m = 0; m < MetricCount; ++m)
  {
    table->AddColumn(metricColumns[m]);
  }
  table->AddColumn(segmentColumn);
  table->AddColumn(secondsColumn);
  return 1;
}

void vtkSegmentationBenchmark::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DataDirectory: " << (this->DataDirectory ? this->DataDirectory : "(none)") << "\n";
  os << indent << "Method: " << (this->Method ? this->Method : "(none)") << "\n";
  os << indent << "MethodParameters: " << (this->MethodParameters ? this->MethodParameters : "") << "\n";
  os << indent << "Models: " << this->Models.size() << (this->Models.empty() ? " (all)" : "") << "\n";
}
