/**
 * @class vtkKerfMeshFileReader
 * @brief Reads a surface mesh from any format Kerf supports, chosen by the file extension.
 *
 * .off (vtkKerfOFFReader), .ply, .obj and .stl (Kerf's own parsers, which check every count and
 * index against the file before allocating anything), .vtp (vtkXMLPolyDataReader) and legacy .vtk
 * (vtkPolyDataReader), the last two after a check of the file's declared counts and structure
 * against its data (kerf::checkVTP, kerf::checkLegacyVTK); extensions are compared without regard
 * to case. Any byte sequence gives either a mesh or an error: an unknown extension, a missing
 * file, a malformed file (the message names the line or byte offset and the problem), cells whose
 * offsets or point ids are out of range, or a file with no points is reported with vtkErrorMacro
 * and fails the update, so scripts and the command-line program can rely on the result.
 * Non-finite coordinates are read as such (Kerf's filters refuse them with their own message).
 */
#ifndef vtkKerfMeshFileReader_h
#define vtkKerfMeshFileReader_h

#include "KerfIOModule.h"
#include "vtkPolyDataAlgorithm.h"

class KERFIO_EXPORT vtkKerfMeshFileReader : public vtkPolyDataAlgorithm
{
public:
  static vtkKerfMeshFileReader* New();
  vtkTypeMacro(vtkKerfMeshFileReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh file to read.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// 1 if the extension of fileName is one this reader handles.
  static int IsSupportedExtension(const char* fileName);

protected:
  vtkKerfMeshFileReader();
  ~vtkKerfMeshFileReader() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkKerfMeshFileReader(const vtkKerfMeshFileReader&) = delete;
  void operator=(const vtkKerfMeshFileReader&) = delete;
};

#endif
