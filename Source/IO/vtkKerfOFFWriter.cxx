// vtkKerfOFFWriter: collects polygons and strip triangles and writes them with kerf::writeOFF.
#include "vtkKerfOFFWriter.h"

#include "Error.h"
#include "IO/MeshFormats.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

vtkStandardNewMacro(vtkKerfOFFWriter);

vtkKerfOFFWriter::~vtkKerfOFFWriter()
{
  this->SetFileName(nullptr);
}

vtkPolyData* vtkKerfOFFWriter::GetInput()
{
  return vtkPolyData::SafeDownCast(this->Superclass::GetInput());
}

int vtkKerfOFFWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkKerfOFFWriter::WriteData()
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    vtkErrorMacro("The input is not a vtkPolyData.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was given.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  kerf::PolygonMesh mesh;
  mesh.points.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    input->GetPoint(i, mesh.points[static_cast<std::size_t>(i)].data());
  }
  auto polygons = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polygons->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      mesh.polygonIndices.push_back(static_cast<int>(ids[k]));
    }
    mesh.polygonOffsets.push_back(static_cast<int>(mesh.polygonIndices.size()));
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    strips->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      const bool even = k % 2 == 0;
      mesh.polygonIndices.push_back(static_cast<int>(ids[even ? k : k + 1]));
      mesh.polygonIndices.push_back(static_cast<int>(ids[even ? k + 1 : k]));
      mesh.polygonIndices.push_back(static_cast<int>(ids[k + 2]));
      mesh.polygonOffsets.push_back(static_cast<int>(mesh.polygonIndices.size()));
    }
  }
  try
  {
    kerf::writeOFF(this->FileName, mesh);
  }
  catch (const kerf::Error& e)
  {
    vtkErrorMacro("Cannot write OFF: " << e.what());
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkKerfOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
