// vtkKerfSegmentationReader: reads labels with kerf::readSegmentation and adds them as a cell array.
#include "vtkKerfSegmentationReader.h"

#include "Error.h"
#include "IO/MeshFormats.h"

#include <vtkCellData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkKerfSegmentationReader);

vtkKerfSegmentationReader::vtkKerfSegmentationReader()
{
  this->SetArrayName("Segment");
}

vtkKerfSegmentationReader::~vtkKerfSegmentationReader()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
}

int vtkKerfSegmentationReader::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No .seg file name was given.");
    return 0;
  }
  if (!this->ArrayName || !*this->ArrayName)
  {
    vtkErrorMacro("The output array needs a non-empty name.");
    return 0;
  }
  std::vector<int> labels;
  try
  {
    labels = kerf::readSegmentation(this->FileName);
  }
  catch (const kerf::Error& e)
  {
    vtkErrorMacro("Cannot read segmentation: " << e.what());
    return 0;
  }
  if (static_cast<vtkIdType>(labels.size()) != input->GetNumberOfCells())
  {
    vtkErrorMacro("The segmentation " << this->FileName << " has " << labels.size() << " labels but the mesh has "
                                      << input->GetNumberOfCells() << " cells.");
    return 0;
  }
  output->ShallowCopy(input);
  vtkNew<vtkIntArray> array;
  array->SetName(this->ArrayName);
  array->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  for (std::size_t i = 0; i < labels.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), labels[i]);
  }
  output->GetCellData()->AddArray(array);
  return 1;
}

void vtkKerfSegmentationReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
}
