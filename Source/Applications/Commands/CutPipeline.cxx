// The stroke cut pipeline shared by `kerf cut` and `kerf showcase`.
#include "CutPipeline.h"

#include "Error.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "KerfCommands.h"
#include "Numerics/LaplacianWeights.h"

#include <vtkAlgorithmOutput.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace kerf
{

void CutPipeline::Run(vtkPolyData* mesh, vtkPolyData* stroke, const Arguments& args, bool withDescriptors)
{
  auto timed = [this](vtkAlgorithm* algorithm, const std::string& stage) {
    const auto start = std::chrono::steady_clock::now();
    RunAlgorithm(algorithm, stage);
    this->milliseconds.emplace_back(stage, MillisecondsSince(start));
  };
  int weighting = 0;
  try
  {
    weighting = static_cast<int>(parseLaplacianWeighting(args.get("weighting", "cotangent")));
  }
  catch (const Error& e)
  {
    throw CommandError{ std::string("--") + e.what() };
  }
  // The descriptors are output arrays only (the field computes the curvatures a weighting needs
  // on its own): at 1M triangles they cost 0.6 s and half the written file.
  vtkAlgorithmOutput* surface = nullptr;
  if (withDescriptors)
  {
    this->descriptors->SetInputData(mesh);
    timed(this->descriptors, "surface descriptors");
    surface = this->descriptors->GetOutputPort();
  }
  if (surface)
  {
    this->constraints->SetInputConnection(surface);
  }
  else
  {
    this->constraints->SetInputData(mesh);
  }
  this->constraints->SetInputData(1, stroke);
  this->constraints->SetSamplesPerSegment(args.integer("samples", 4, 1, 1000));
  this->constraints->SetOffset(args.number("offset", 0.005, 1e-6, 0.5));
  this->constraints->SetIsoValue(args.number("iso-value", 0.0, -1e15, 1e15));
  timed(this->constraints, "stroke constraints");
  if (surface)
  {
    this->field->SetInputConnection(surface);
  }
  else
  {
    this->field->SetInputData(mesh);
  }
  this->field->SetInputConnection(1, this->constraints->GetOutputPort());
  this->field->SetWeighting(weighting);
  const std::string formulation = args.get("formulation", "auto");
  try
  {
    this->field->SetFormulation(formulation == "auto" ? static_cast<int>(vtkHarmonicField::AUTOMATIC)
                                                      : static_cast<int>(parseSoftConstraintFormulation(formulation)));
  }
  catch (const Error&)
  {
    throw CommandError{ "--formulation must be auto, least-squares or point-values, got '" + formulation + "'" };
  }
  this->field->SetSoftConstraintWeight(args.number("soft-weight", 1.0, 1e-6, 1e6));
  timed(this->field, "harmonic field");
  this->cut->SetInputConnection(this->field->GetOutputPort());
  this->cut->SetInputData(1, stroke);
  this->cut->SetModeToNearStroke();
  this->cut->SetIsoValue(args.number("iso-value", 0.0, -1e15, 1e15));
  timed(this->cut, "cut");
}

void CutPipeline::Render(vtkPolyData* stroke, const std::string& caption, const std::string& file)
{
  RequireDisplay();
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = RenderCutScene(
    this->cut->GetLabelledSurface(), stroke, this->constraints->GetOutput(), this->cut->GetOutput(), caption, error);
  if (!window || !WritePNG(window, file, error))
  {
    throw CommandError{ "cannot draw the cut: " + error };
  }
}

std::string SegmentSizes(vtkPolyData* surface)
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

std::string CutSummary(vtkPolyData* curve)
{
  std::ostringstream out;
  double length = 0.0;
  int closed = 0;
  for (vtkIdType c = 0; c < curve->GetNumberOfCells(); ++c)
  {
    length += curve->GetCellData()->GetArray("Length")->GetComponent(c, 0);
    closed += static_cast<int>(curve->GetCellData()->GetArray("Closed")->GetComponent(c, 0));
  }
  out << curve->GetNumberOfCells() << (curve->GetNumberOfCells() == 1 ? " curve" : " curves") << " (" << closed
      << " closed), length " << std::setprecision(4) << length;
  return out.str();
}

} // namespace kerf
