// vtkKerfSegmentationWriter: checks a cell label array and writes it with kerf::writeSegmentation.
#include "vtkKerfSegmentationWriter.h"

#include "Error.h"
#include "IO/MeshFormats.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkKerfSegmentationWriter);

vtkKerfSegmentationWriter::vtkKerfSegmentationWriter()
{
  this->SetArrayName("Segment");
}

vtkKerfSegmentationWriter::~vtkKerfSegmentationWriter()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
}

int vtkKerfSegmentationWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

void vtkKerfSegmentationWriter::WriteData()
{
  vtkDataSet* input = vtkDataSet::SafeDownCast(this->GetInput());
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was given.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  vtkDataArray* array = input && this->ArrayName ? input->GetCellData()->GetArray(this->ArrayName) : nullptr;
  if (!array)
  {
    vtkErrorMacro("The input has no cell array named '" << (this->ArrayName ? this->ArrayName : "") << "'.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The cell array '" << this->ArrayName << "' has " << array->GetNumberOfComponents()
                                     << " components; a segmentation has one.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  std::vector<int> labels(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double value = array->GetComponent(i, 0);
    if (!std::isfinite(value) || value != std::floor(value) || std::abs(value) > std::numeric_limits<int>::max())
    {
      vtkErrorMacro(
        "Cell " << i << " of '" << this->ArrayName << "' holds " << value << ", which is not an integer label.");
      this->SetErrorCode(vtkErrorCode::UnknownError);
      return;
    }
    labels[static_cast<std::size_t>(i)] = static_cast<int>(value);
  }
  try
  {
    kerf::writeSegmentation(this->FileName, labels);
  }
  catch (const kerf::Error& e)
  {
    vtkErrorMacro("Cannot write segmentation: " << e.what());
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkKerfSegmentationWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
}
