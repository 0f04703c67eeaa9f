// vtkKerfMeshFileReader: reads every supported format safely, by Kerf's own parser or after a check.
#include "vtkKerfMeshFileReader.h"

#include "KerfErrorCollector.h"
#include "KerfMeshFileData.h"
#include "vtkKerfOFFReader.h"

#include "Error.h"
#include "IO/LegacyVTKValidation.h"
#include "IO/MeshFormats.h"
#include "IO/OBJFormat.h"
#include "IO/PLYFormat.h"
#include "IO/STLFormat.h"
#include "IO/VTPValidation.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkZLibDataCompressor.h>
#include <vtksys/SystemTools.hxx>

#include <limits>
#include <new>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkKerfMeshFileReader);

namespace
{
const char* const Extensions[] = { ".off", ".ply", ".obj", ".stl", ".vtp", ".vtk" };

std::string lowerExtension(const char* fileName)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
}

// Decompresses a block of a VTK XML file with VTK's own compressor of that name, quietly.
bool decompressBlock(const std::string& compressorName, std::string_view compressed, std::size_t uncompressedSize,
  std::string& uncompressed)
{
  vtkSmartPointer<vtkDataCompressor> compressor;
  if (compressorName == "vtkZLibDataCompressor")
  {
    compressor = vtkSmartPointer<vtkZLibDataCompressor>::New();
  }
  else if (compressorName == "vtkLZ4DataCompressor")
  {
    compressor = vtkSmartPointer<vtkLZ4DataCompressor>::New();
  }
  else if (compressorName == "vtkLZMADataCompressor")
  {
    compressor = vtkSmartPointer<vtkLZMADataCompressor>::New();
  }
  else
  {
    return false;
  }
  auto errors = vtkSmartPointer<kerf::ErrorCollector>::New();
  compressor->AddObserver(vtkCommand::ErrorEvent, errors);
  uncompressed.assign(uncompressedSize, '\0');
  const std::size_t size = compressor->Uncompress(reinterpret_cast<const unsigned char*>(compressed.data()),
    compressed.size(), reinterpret_cast<unsigned char*>(&uncompressed[0]), uncompressedSize);
  return size == uncompressedSize && errors->Message.empty();
}

// Runs a VTK reader on bytes already checked, turning its errors into an exception.
vtkSmartPointer<vtkPolyData> runVTKReader(vtkAlgorithm* reader, const char* hint)
{
  auto errors = vtkSmartPointer<kerf::ErrorCollector>::New();
  auto warnings = vtkSmartPointer<kerf::ErrorCollector>::New();
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, warnings);
  const int ok = reader->GetExecutive()->Update();
  vtkPolyData* result = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!ok || !errors->Message.empty() || !result)
  {
    throw kerf::Error((errors->Message.empty() ? std::string("the reader failed") : errors->Message) + hint);
  }
  return result;
}

// The polydata a file holds, read by Kerf's parser or by VTK's reader after Kerf's check.
vtkSmartPointer<vtkPolyData> readFile(const std::string& extension, const char* fileName)
{
  if (extension == ".off")
  {
    vtkNew<vtkKerfOFFReader> reader;
    reader->SetFileName(fileName);
    return runVTKReader(reader, "");
  }
  const std::string bytes = kerf::readTextFile(fileName);
  if (extension == ".ply")
  {
    return kerf::MeshFileDataToPolyData(kerf::parsePLY(bytes));
  }
  if (extension == ".stl")
  {
    return kerf::MeshFileDataToPolyData(kerf::parseSTL(bytes));
  }
  if (extension == ".obj")
  {
    return kerf::MeshFileDataToPolyData(kerf::parseOBJ(bytes));
  }
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
  {
    throw kerf::Error("the file is larger than 2 GiB, more than VTK's " + extension + " reader reads");
  }
  // VTK reads the very bytes that were checked, not the file again.
  if (extension == ".vtk")
  {
    kerf::checkLegacyVTK(bytes);
    vtkNew<vtkPolyDataReader> reader;
    reader->ReadFromInputStringOn();
    reader->SetBinaryInputString(bytes.data(), static_cast<int>(bytes.size()));
    return runVTKReader(reader, "");
  }
  kerf::checkVTP(bytes, decompressBlock);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(bytes);
  // Debian 12's expat security update (reparse deferral) breaks VTK 9.2's parsing of VTP files
  // with appended data, the format ParaView writes by default.
  const bool appended = bytes.find("<AppendedData") != std::string::npos;
  return runVTKReader(reader,
    appended ? " (this VTK cannot read appended data with the system's expat: save the file again "
               "with binary or ASCII data mode)"
             : "");
}

// A sentence naming the first problem of a cell array's offsets (they start at 0, never decrease
// and end at the number of point ids) or point ids (each names a point), or "".
template <typename Offset>
std::string checkCellArray(const Offset* offsets, vtkIdType offsetCount, const Offset* ids, vtkIdType idCount,
  vtkIdType points, const char* kind)
{
  std::ostringstream out;
  for (vtkIdType i = 0; i < offsetCount; ++i)
  {
    if ((i == 0 && offsets[0] != 0) || (i > 0 && offsets[i] < offsets[i - 1]) || offsets[i] > idCount)
    {
      out << kind << " offset " << i << " is " << offsets[i] << ", out of order or past the " << idCount
          << " point ids";
      return out.str();
    }
  }
  if (offsetCount > 0 && offsets[offsetCount - 1] != idCount)
  {
    out << "the " << kind << " offsets end at " << offsets[offsetCount - 1] << ", not at the " << idCount
        << " point ids";
    return out.str();
  }
  for (vtkIdType i = 0; i < idCount; ++i)
  {
    if (ids[i] < 0 || ids[i] >= points)
    {
      out << "a cell uses point " << ids[i] << ", but the file has " << points << " points";
      return out.str();
    }
  }
  return "";
}

// The first problem of the mesh's cell arrays, or "". Cells like these would crash whatever
// reads them next.
std::string checkCells(vtkPolyData* mesh)
{
  const char* kinds[] = { "vertex", "line", "polygon", "triangle strip" };
  vtkCellArray* cellArrays[] = { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() };
  for (int k = 0; k < 4; ++k)
  {
    vtkCellArray* cells = cellArrays[k];
    if (!cells)
    {
      continue;
    }
    const std::string problem = cells->IsStorage64Bit()
      ? checkCellArray(cells->GetOffsetsArray64()->GetPointer(0), cells->GetOffsetsArray64()->GetNumberOfValues(),
          cells->GetConnectivityArray64()->GetPointer(0), cells->GetConnectivityArray64()->GetNumberOfValues(),
          mesh->GetNumberOfPoints(), kinds[k])
      : checkCellArray(cells->GetOffsetsArray32()->GetPointer(0), cells->GetOffsetsArray32()->GetNumberOfValues(),
          cells->GetConnectivityArray32()->GetPointer(0), cells->GetConnectivityArray32()->GetNumberOfValues(),
          mesh->GetNumberOfPoints(), kinds[k]);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return "";
}
} // namespace

vtkKerfMeshFileReader::vtkKerfMeshFileReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkKerfMeshFileReader::~vtkKerfMeshFileReader()
{
  this->SetFileName(nullptr);
}

int vtkKerfMeshFileReader::IsSupportedExtension(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  const std::string extension = lowerExtension(fileName);
  for (const char* e : Extensions)
  {
    if (extension == e)
    {
      return 1;
    }
  }
  return 0;
}

int vtkKerfMeshFileReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
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
  if (!IsSupportedExtension(this->FileName))
  {
    vtkErrorMacro("Unsupported mesh file extension '" << lowerExtension(this->FileName) << "' (" << this->FileName
                                                      << "); use .off, .ply, .obj, .stl, .vtp or .vtk.");
    return 0;
  }
  vtkSmartPointer<vtkPolyData> result;
  std::string problem;
  try
  {
    result = readFile(lowerExtension(this->FileName), this->FileName);
    problem = checkCells(result);
  }
  catch (const kerf::Error& e)
  {
    problem = e.what();
  }
  catch (const std::bad_alloc&)
  {
    problem = "out of memory";
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  if (!problem.empty())
  {
    const std::string prefix = std::string("Cannot read ") + this->FileName;
    if (problem.compare(0, prefix.size(), prefix) == 0)
    {
      vtkErrorMacro(<< problem);
    }
    else
    {
      vtkErrorMacro(<< prefix << ": " << problem);
    }
    return 0;
  }
  if (result->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The file " << this->FileName << " holds no points.");
    return 0;
  }
  output->ShallowCopy(result);
  return 1;
}

void vtkKerfMeshFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
