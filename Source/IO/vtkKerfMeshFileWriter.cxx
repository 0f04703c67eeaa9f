// vtkKerfMeshFileWriter: dispatches on the extension and reports the inner writer's failure.
#include "vtkKerfMeshFileWriter.h"

#include "vtkKerfOFFWriter.h"

#include "KerfErrorCollector.h"

#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtksys/SystemTools.hxx>

#include <functional>
#include <string>

vtkStandardNewMacro(vtkKerfMeshFileWriter);

namespace
{
// A configured writer and the call that writes with it.
struct Writer
{
  vtkSmartPointer<vtkAlgorithm> algorithm;
  std::function<int()> write;
};

template <typename WriterType>
Writer wrap(vtkSmartPointer<WriterType> writer, const char* fileName)
{
  writer->SetFileName(fileName);
  WriterType* raw = writer;
  return { writer, [raw] { return raw->Write(); } };
}

// The writer for an extension (lower case); an empty algorithm if the extension is unknown.
Writer makeWriter(const std::string& extension, const char* fileName)
{
  if (extension == ".vtp")
  {
    // Raw appended blocks with LZ4: zlib took 5.5 s to save 12% of a 1M-triangle cut's 144 MB
    // of doubles, base64 a third more bytes; LZ4 writes it in 0.3 s (VTK's XML readers read LZ4 blocks).
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToLZ4();
    return wrap(writer, fileName);
  }
  if (extension == ".vtk")
  {
    auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
    writer->SetFileTypeToBinary();
    return wrap(writer, fileName);
  }
  if (extension == ".ply")
  {
    auto writer = vtkSmartPointer<vtkPLYWriter>::New();
    writer->SetFileTypeToBinary();
    return wrap(writer, fileName);
  }
  if (extension == ".obj")
  {
    return wrap(vtkSmartPointer<vtkOBJWriter>::New(), fileName);
  }
  if (extension == ".stl")
  {
    auto writer = vtkSmartPointer<vtkSTLWriter>::New();
    writer->SetFileTypeToBinary();
    return wrap(writer, fileName);
  }
  if (extension == ".off")
  {
    return wrap(vtkSmartPointer<vtkKerfOFFWriter>::New(), fileName);
  }
  return {};
}

std::string lowerExtension(const char* fileName)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
}
} // namespace

vtkKerfMeshFileWriter::~vtkKerfMeshFileWriter()
{
  this->SetFileName(nullptr);
}

int vtkKerfMeshFileWriter::IsSupportedExtension(const char* fileName)
{
  return fileName && makeWriter(lowerExtension(fileName), fileName).algorithm ? 1 : 0;
}

int vtkKerfMeshFileWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkKerfMeshFileWriter::WriteData()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was given.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  const std::string extension = lowerExtension(this->FileName);
  const Writer writer = makeWriter(extension, this->FileName);
  if (!writer.algorithm)
  {
    vtkErrorMacro("Unsupported mesh file extension '" << extension << "' (" << this->FileName
                                                      << "); use .vtp, .vtk, .ply, .obj, .stl or .off.");
    this->SetErrorCode(vtkErrorCode::UnrecognizedFileTypeError);
    return;
  }
  // vtkPLYWriter reads texture coordinates as floats whatever their type (a double array
  // crashes it): a PLY gets a float copy.
  vtkSmartPointer<vtkPolyData> written = input;
  vtkDataArray* tcoords = input ? input->GetPointData()->GetTCoords() : nullptr;
  if (extension == ".ply" && tcoords && !vtkFloatArray::SafeDownCast(tcoords))
  {
    written = vtkSmartPointer<vtkPolyData>::New();
    written->ShallowCopy(input);
    vtkNew<vtkFloatArray> floats;
    floats->DeepCopy(tcoords);
    floats->SetName(tcoords->GetName());
    written->GetPointData()->SetTCoords(floats);
  }
  writer.algorithm->SetInputDataObject(written);
  auto errors = vtkSmartPointer<kerf::ErrorCollector>::New();
  writer.algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
  writer.algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, vtkSmartPointer<kerf::ErrorCollector>::New());
  const unsigned long code =
    writer.write() == 1 ? writer.algorithm->GetErrorCode() : static_cast<unsigned long>(vtkErrorCode::UnknownError);
  if (code != vtkErrorCode::NoError || !errors->Message.empty())
  {
    vtkErrorMacro(
      "Cannot write " << this->FileName << ": " << (errors->Message.empty() ? "the writer failed" : errors->Message));
    this->SetErrorCode(code != vtkErrorCode::NoError ? code : vtkErrorCode::UnknownError);
  }
}

void vtkKerfMeshFileWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
