// vtkDrawnStrokeAlgorithm: the strokes drawn in a filter's panel, shared by the filters that take strokes.
#include "vtkDrawnStrokeAlgorithm.h"

#include "Error.h"
#include "KerfDrawnInput.h"
#include "KerfFilterBorder.h"

#include <vtkPoints.h>

vtkDrawnStrokeAlgorithm::vtkDrawnStrokeAlgorithm()
  : DrawnStrokes(new kerf::DrawnStrokeList)
{
}

vtkDrawnStrokeAlgorithm::~vtkDrawnStrokeAlgorithm() = default;

void vtkDrawnStrokeAlgorithm::SetNumberOfDrawnStrokePoints(int count)
{
  kerf::SetPanelPointCount(this, this->DrawnStrokes->Points, count, "drawn stroke");
}

int vtkDrawnStrokeAlgorithm::GetNumberOfDrawnStrokePoints() const
{
  return this->DrawnStrokes->Points.Count();
}

void vtkDrawnStrokeAlgorithm::SetDrawnStrokePoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->DrawnStrokes->Points, index, kerf::Vector3(x, y, z), "drawn stroke");
}

void vtkDrawnStrokeAlgorithm::SetNumberOfDrawnStrokeSizes(int count)
{
  kerf::SetPanelIntegerCount(this, this->DrawnStrokes->Sizes, count, "drawn stroke sizes");
}

int vtkDrawnStrokeAlgorithm::GetNumberOfDrawnStrokeSizes() const
{
  return this->DrawnStrokes->Sizes.Count();
}

void vtkDrawnStrokeAlgorithm::SetDrawnStrokeSize(int index, int size)
{
  kerf::SetPanelInteger(this, this->DrawnStrokes->Sizes, index, size, "drawn stroke size");
}

int vtkDrawnStrokeAlgorithm::GetDrawnStrokeSize(int index) const
{
  const std::vector<int>& sizes = this->DrawnStrokes->Sizes.Values();
  return index >= 0 && index < static_cast<int>(sizes.size()) ? sizes[static_cast<std::size_t>(index)] : 0;
}

void vtkDrawnStrokeAlgorithm::SetNumberOfDrawnStrokeLabels(int count)
{
  kerf::SetPanelIntegerCount(this, this->DrawnStrokes->Labels, count, "drawn stroke labels");
}

int vtkDrawnStrokeAlgorithm::GetNumberOfDrawnStrokeLabels() const
{
  return this->DrawnStrokes->Labels.Count();
}

void vtkDrawnStrokeAlgorithm::SetDrawnStrokeLabel(int index, int label)
{
  kerf::SetPanelInteger(this, this->DrawnStrokes->Labels, index, label, "drawn stroke label");
}

int vtkDrawnStrokeAlgorithm::GetDrawnStrokeLabel(int index) const
{
  const std::vector<int>& labels = this->DrawnStrokes->Labels.Values();
  return index >= 0 && index < static_cast<int>(labels.size()) ? labels[static_cast<std::size_t>(index)] : 0;
}

void vtkDrawnStrokeAlgorithm::AddDrawnStroke(vtkPoints* points, int label)
{
  kerf::GuardSetter(this, "Cannot add a drawn stroke", [&]() {
    std::vector<kerf::Vector3> stroke(static_cast<std::size_t>(points ? points->GetNumberOfPoints() : 0));
    for (std::size_t i = 0; i < stroke.size(); ++i)
    {
      points->GetPoint(static_cast<vtkIdType>(i), stroke[i].data());
    }
    if (stroke.empty())
    {
      throw kerf::Error("a drawn stroke needs at least one point");
    }
    if (this->DrawnStrokes->Add(stroke, label))
    {
      this->Modified();
    }
  });
}

void vtkDrawnStrokeAlgorithm::RemoveAllDrawnStrokes()
{
  if (this->DrawnStrokes->Clear())
  {
    this->Modified();
  }
}

void vtkDrawnStrokeAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DrawnStrokePoints: " << this->DrawnStrokes->Points.Count() << "\n";
  os << indent << "DrawnStrokeSizes: " << this->DrawnStrokes->Sizes.Count() << "\n";
  os << indent << "DrawnStrokeLabels: " << this->DrawnStrokes->Labels.Count() << "\n";
}
