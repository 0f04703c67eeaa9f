/**
 * @class vtkMeshFileReader
 * @brief Reads a surface mesh from any format Kerf supports, chosen by the file extension.
 *
 * .off (vtkOFFReader), .ply (vtkPLYReader), .obj (vtkOBJReader), .stl (vtkSTLReader),
 * .vtp (vtkXMLPolyDataReader) and legacy .vtk (vtkPolyDataReader); extensions are compared
 * without regard to case. An unknown extension, a missing file, a reader error or a file with no
 * points is reported with vtkErrorMacro and fails the update, so scripts and the command-line
 * program can rely on the result. PLY files are checked for completeness before VTK's PLY reader
 * sees them, since it crashes on truncated files.
 */
#ifndef vtkMeshFileReader_h
#define vtkMeshFileReader_h

#include "KerfIOModule.h"
#include "vtkPolyDataAlgorithm.h"

class KERFIO_EXPORT vtkMeshFileReader : public vtkPolyDataAlgorithm
{
public:
  static vtkMeshFileReader* New();
  vtkTypeMacro(vtkMeshFileReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh file to read.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// 1 if the extension of fileName is one this reader handles.
  static int IsSupportedExtension(const char* fileName);

protected:
  vtkMeshFileReader();
  ~vtkMeshFileReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkMeshFileReader(const vtkMeshFileReader&) = delete;
  void operator=(const vtkMeshFileReader&) = delete;
};

#endif
