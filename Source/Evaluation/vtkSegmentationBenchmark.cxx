// vtkSegmentationBenchmark: the models of a benchmark folder through kerf's runner, into a table, files and pictures.
#include "vtkSegmentationBenchmark.h"

#include "Error.h"
#include "Evaluation/BenchmarkRunner.h"
#include "Evaluation/SegmentationMetrics.h"
#include "KerfBenchmarkWorkers.h"
#include "KerfScene.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <iostream>
#include <new>

vtkStandardNewMacro(vtkSegmentationBenchmark);

namespace
{
vtkSmartPointer<vtkIntArray> labelArray(const char* name, const std::vector<int>& labels)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  std::copy(labels.begin(), labels.end(), array->GetPointer(0));
  return array;
}

// The model's mesh with the method's segmentation ("Method", renumbered to match the human's
// labels) and the human's ("Human").
vtkSmartPointer<vtkPolyData> shownSurface(const kerf::TriangleMesh& mesh, const kerf::ModelScores& scores)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    points->SetPoint(v, mesh.point(v).data());
  }
  vtkNew<vtkCellArray> triangles;
  for (const kerf::Triangle& t : mesh.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetCellData()->AddArray(labelArray("Method", kerf::matchLabels(scores.shownMethod, scores.shownHuman)));
  surface->GetCellData()->AddArray(labelArray("Human", scores.shownHuman));
  return surface;
}

// pictures/N.png: the method's segmentation beside the human's, coloured alike.
void drawPicture(vtkPolyData* shown, int model, const std::string& method, const std::string& file)
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
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderSideBySide(shown, left, right, error);
  if (!window || !kerf::WritePNG(window, file, error))
  {
    throw kerf::Error("model " + std::to_string(model) + ": cannot draw its picture: " + error);
  }
}

// The rows as output 0.
void fillTable(const std::vector<kerf::BenchmarkRow>& rows, vtkTable* table)
{
  vtkNew<vtkIntArray> models;
  models->SetName("Model");
  vtkNew<vtkStringArray> categories, methods, parameters;
  categories->SetName("Category");
  methods->SetName("Method");
  parameters->SetName("Parameters");
  std::vector<vtkSmartPointer<vtkDoubleArray>> metrics;
  for (const std::string& column : kerf::benchmarkMetricColumns())
  {
    metrics.push_back(vtkSmartPointer<vtkDoubleArray>::New());
    metrics.back()->SetName(column.c_str());
  }
  for (const kerf::BenchmarkRow& row : rows)
  {
    models->InsertNextValue(row.model);
    categories->InsertNextValue(row.category);
    methods->InsertNextValue(row.method);
    parameters->InsertNextValue(row.parameters);
    for (std::size_t c = 0; c < metrics.size(); ++c)
    {
      metrics[c]->InsertNextValue(row.values.at(kerf::benchmarkMetricColumns()[c]));
    }
  }
  table->AddColumn(models);
  table->AddColumn(categories);
  table->AddColumn(methods);
  table->AddColumn(parameters);
  for (const auto& column : metrics)
  {
    table->AddColumn(column);
  }
}

// Output 0 of earlier runs back into rows.
std::vector<kerf::BenchmarkRow> tableRows(vtkTable* table)
{
  std::vector<kerf::BenchmarkRow> rows(static_cast<std::size_t>(table->GetNumberOfRows()));
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    kerf::BenchmarkRow& row = rows[static_cast<std::size_t>(r)];
    row.model = table->GetValueByName(r, "Model").ToInt();
    row.category = table->GetValueByName(r, "Category").ToString();
    row.method = table->GetValueByName(r, "Method").ToString();
    row.parameters = table->GetValueByName(r, "Parameters").ToString();
    for (const std::string& column : kerf::benchmarkMetricColumns())
    {
      row.values[column] = table->GetValueByName(r, column.c_str()).ToDouble();
    }
  }
  std::sort(rows.begin(), rows.end(),
    [](const kerf::BenchmarkRow& a, const kerf::BenchmarkRow& b) { return a.model < b.model; });
  return rows;
}

// Writes results.csv and summary.csv; returns the summary table.
std::string writeFiles(const std::vector<kerf::BenchmarkRow>& rows, const std::string& directory)
{
  if (!vtksys::SystemTools::MakeDirectory(directory))
  {
    throw kerf::Error("cannot create the output folder " + directory);
  }
  kerf::writeResults(rows, directory + "/results.csv");
  return kerf::writeSummary(rows, rows.empty() ? "" : rows.front().method, directory + "/summary.csv");
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
  this->SetOutputDirectory(nullptr);
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
  std::vector<std::string> names;
  for (const kerf::SegmentationMethod& method : kerf::segmentationMethods())
  {
    names.push_back(method.name);
  }
  return names;
}

std::string vtkSegmentationBenchmark::GetMethodDescription(const std::string& method)
{
  try
  {
    const kerf::SegmentationMethod& found = kerf::findSegmentationMethod(method);
    std::string parameters;
    for (const std::string& name : found.parameters)
    {
      parameters += (parameters.empty() ? " (parameters: " : ", ") + name;
    }
    return found.description + (parameters.empty() ? "" : parameters + ")");
  }
  catch (const kerf::Error&)
  {
    return "";
  }
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

std::string vtkSegmentationBenchmark::WriteResults(vtkTable* table, const std::string& directory, std::string& error)
{
  try
  {
    return writeFiles(tableRows(table), directory);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return "";
  }
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

int vtkSegmentationBenchmark::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkTable* table = vtkTable::GetData(outputVector, 0);
  vtkPolyData* shown = vtkPolyData::GetData(outputVector, 1);
  this->Summary.clear();
  try
  {
    const kerf::SegmentationMethod& method = kerf::findSegmentationMethod(this->Method ? this->Method : "");
    const std::string parameters = this->MethodParameters ? this->MethodParameters : "";
    kerf::MethodParameters(parameters, method.parameters); // refuses bad parameters before any work
    if (!this->DataDirectory || !*this->DataDirectory)
    {
      throw kerf::Error("no benchmark folder was given");
    }
    const std::vector<kerf::BenchmarkModel> all = kerf::scanBenchmark(this->DataDirectory);
    std::vector<int> ids = this->Models;
    if (ids.empty())
    {
      for (const kerf::BenchmarkModel& model : all)
      {
        ids.push_back(model.id);
      }
    }
    for (int id : ids)
    {
      if (std::none_of(all.begin(), all.end(), [id](const kerf::BenchmarkModel& m) { return m.id == id; }))
      {
        throw kerf::Error("model " + std::to_string(id) + " is not in " + this->DataDirectory);
      }
    }
    const std::string output = this->OutputDirectory ? this->OutputDirectory : "";
    const std::string pictures = !output.empty() && this->WritePictures ? output + "/pictures" : "";
    if (!pictures.empty() && !vtksys::SystemTools::MakeDirectory(pictures))
    {
      throw kerf::Error("cannot create the output folder " + pictures);
    }

    vtkSmartPointer<vtkPolyData> last;
    const auto work = [&](int id) {
      const kerf::BenchmarkModel& model =
        *std::find_if(all.begin(), all.end(), [id](const kerf::BenchmarkModel& m) { return m.id == id; });
      try
      {
        const kerf::BenchmarkCase benchmarkCase = kerf::loadBenchmarkCase(model);
        kerf::ModelScores scores;
        const kerf::BenchmarkRow row = kerf::runBenchmarkModel(benchmarkCase, method, parameters, &scores);
        if (!pictures.empty() || this->NumberOfJobs == 1)
        {
          last = shownSurface(benchmarkCase.surface->mesh(), scores);
        }
        if (!pictures.empty())
        {
          drawPicture(last, model.id, method.name, pictures + "/" + std::to_string(model.id) + ".png");
        }
        return row;
      }
      catch (const kerf::Error& e)
      {
        throw kerf::Error("model " + std::to_string(model.id) + " (" + model.meshFile + "): " + e.what());
      }
    };
    const auto finished = [&](std::size_t done, const kerf::BenchmarkRow& row) {
      if (this->PrintProgress)
      {
        std::cout << kerf::progressLine(done, ids.size(), row) << std::endl;
      }
      this->UpdateProgress(static_cast<double>(done) / static_cast<double>(ids.size()));
    };
    const std::vector<kerf::BenchmarkRow> rows = kerf::runInWorkers(ids, this->NumberOfJobs, work, finished);
    fillTable(rows, table);
    if (this->NumberOfJobs == 1 && last)
    {
      shown->ShallowCopy(last);
    }
    if (!output.empty())
    {
      this->Summary = writeFiles(rows, output);
    }
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Cannot run the benchmark: out of memory.");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot run the benchmark: " << e.what() << ".");
    return 0;
  }
  return 1;
}

void vtkSegmentationBenchmark::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DataDirectory: " << (this->DataDirectory ? this->DataDirectory : "(none)") << "\n";
  os << indent << "Method: " << (this->Method ? this->Method : "(none)") << "\n";
  os << indent << "MethodParameters: " << (this->MethodParameters ? this->MethodParameters : "") << "\n";
  os << indent << "Models: " << this->Models.size() << (this->Models.empty() ? " (all)" : "") << "\n";
  os << indent << "NumberOfJobs: " << this->NumberOfJobs << "\n";
  os << indent << "OutputDirectory: " << (this->OutputDirectory ? this->OutputDirectory : "(none)") << "\n";
  os << indent << "WritePictures: " << this->WritePictures << "\n";
  os << indent << "PrintProgress: " << this->PrintProgress << "\n";
}
