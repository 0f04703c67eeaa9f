// vtkMeshFileReader: dispatches on the extension and turns the inner reader's errors into its own.
#include "vtkMeshFileReader.h"

#include "vtkOFFReader.h"

#include "KerfErrorCollector.h"

#include "IO/PLYValidation.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <vtksys/SystemTools.hxx>

#include <string>

vtkStandardNewMacro(vtkMeshFileReader);

namespace
{
std::string lowerExtension(const char* fileName)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
}

vtkSmartPointer<vtkAlgorithm> makeReader(const std::string& extension, const char* fileName)
{
  if (extension == ".off")
  {
    auto reader = vtkSmartPointer<vtkOFFReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  if (extension == ".ply")
  {
    auto reader = vtkSmartPointer<vtkPLYReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  if (extension == ".obj")
  {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  if (extension == ".stl")
  {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  if (extension == ".vtp")
  {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  if (extension == ".vtk")
  {
    auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
    reader->SetFileName(fileName);
    return reader;
  }
  return nullptr;
}
} // namespace

vtkMeshFileReader::vtkMeshFileReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkMeshFileReader::~vtkMeshFileReader()
{
  this->SetFileName(nullptr);
}

int vtkMeshFileReader::IsSupportedExtension(const char* fileName)
{
  return fileName && makeReader(lowerExtension(fileName), fileName) ? 1 : 0;
}

int vtkMeshFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was given.");
    return 0;
  }
  if (!vtksys::SystemTools::FileExists(this->FileName, true))
  {
    vtkErrorMacro("The file " << this->FileName << " does not exist.");
    return 0;
  }
  const std::string extension = lowerExtension(this->FileName);
  vtkSmartPointer<vtkAlgorithm> reader = makeReader(extension, this->FileName);
  if (!reader)
  {
    vtkErrorMacro("Unsupported mesh file extension '"
      << extension << "' (" << this->FileName << "); use .off, .ply, .obj, .stl, .vtp or .vtk.");
    return 0;
  }
  if (extension == ".ply")
  {
    // VTK's PLY reader crashes on truncated files: check the structure first.
    const std::string problem = kerf::checkPLYStructure(this->FileName);
    if (!problem.empty())
    {
      vtkErrorMacro("Cannot read " << this->FileName << ": " << problem);
      return 0;
    }
  }
  auto errors = vtkSmartPointer<kerf::ErrorCollector>::New();
  auto warnings = vtkSmartPointer<kerf::ErrorCollector>::New();
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, warnings);
  const int ok = reader->GetExecutive()->Update();
  vtkPolyData* result = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!ok || !errors->Message.empty() || !result)
  {
    // Debian 12's expat security update (reparse deferral) breaks VTK 9.2's parsing of VTP files
    // with appended data, the format ParaView writes by default.
    const char* hint = extension == ".vtp"
      ? " (if the file uses appended data, this VTK cannot read it with the system's expat: "
        "save it again with binary or ASCII data mode)"
      : "";
    const std::string prefix = std::string("Cannot read ") + this->FileName;
    if (errors->Message.compare(0, prefix.size(), prefix) == 0)
    {
      vtkErrorMacro(<< errors->Message << hint);
    }
    else
    {
      vtkErrorMacro(<< prefix << ": "
                    << (errors->Message.empty() ? "the reader failed" : errors->Message) << hint);
    }
    return 0;
  }
  if (result->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The file " << this->FileName << " holds no points.");
    return 0;
  }
  // Some VTK readers pass face indices through unchecked (a PLY or OBJ face naming a point the
  // file does not have); such cells would crash whatever reads them next.
  vtkCellArray* cellArrays[] = { result->GetVerts(), result->GetLines(), result->GetPolys(),
    result->GetStrips() };
  for (vtkCellArray* cells : cellArrays)
  {
    vtkDataArray* ids = cells ? cells->GetConnectivityArray() : nullptr;
    if (ids && ids->GetNumberOfTuples() > 0)
    {
      double range[2];
      ids->GetRange(range, 0);
      if (range[0] < 0 || range[1] >= static_cast<double>(result->GetNumberOfPoints()))
      {
        vtkErrorMacro("Cannot read " << this->FileName << ": a cell uses point "
                                     << (range[0] < 0 ? range[0] : range[1]) << ", but the file has "
                                     << result->GetNumberOfPoints() << " points.");
        return 0;
      }
    }
  }
  output->ShallowCopy(result);
  return 1;
}

void vtkMeshFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
