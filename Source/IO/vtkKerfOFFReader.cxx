// vtkKerfOFFReader: parses with kerf::readOFF and builds a vtkPolyData.
#include "vtkKerfOFFReader.h"

#include "Error.h"
#include "IO/MeshFormats.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <fstream>
#include <new>
#include <string>

vtkStandardNewMacro(vtkKerfOFFReader);

vtkKerfOFFReader::vtkKerfOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkKerfOFFReader::~vtkKerfOFFReader()
{
  this->SetFileName(nullptr);
}

int vtkKerfOFFReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::ifstream in(fileName);
  std::string word;
  if (!(in >> word))
  {
    return 0;
  }
  return word.size() >= 3 && word.compare(word.size() - 3, 3, "OFF") == 0 ? 1 : 0;
}

int vtkKerfOFFReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was given.");
    return 0;
  }
  kerf::PolygonMesh mesh;
  try
  {
    mesh = kerf::parseOFF(kerf::readTextFile(this->FileName));
  }
  catch (const kerf::Error& e)
  {
    vtkErrorMacro("Cannot read " << this->FileName << ": " << e.what());
    return 0;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory while reading " << this->FileName);
    return 0;
  }

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    coordinates->SetTypedTuple(static_cast<vtkIdType>(i), mesh.points[i].data());
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.polygonOffsets.size()));
  for (std::size_t i = 0; i < mesh.polygonOffsets.size(); ++i)
  {
    offsets->SetValue(static_cast<vtkIdType>(i), mesh.polygonOffsets[i]);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.polygonIndices.size()));
  for (std::size_t i = 0; i < mesh.polygonIndices.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), mesh.polygonIndices[i]);
  }
  vtkNew<vtkCellArray> polygons;
  polygons->SetData(offsets, connectivity);

  output->SetPoints(points);
  output->SetPolys(polygons);
  return 1;
}

void vtkKerfOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
