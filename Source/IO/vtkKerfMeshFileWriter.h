/**
 * @class vtkKerfMeshFileWriter
 * @brief Writes a surface mesh in the format its file extension names.
 *
 * .vtp (vtkXMLPolyDataWriter, raw appended blocks compressed with LZ4: fast to write and read), .vtk
 * (vtkPolyDataWriter, binary), .ply (vtkPLYWriter, binary), .obj (vtkOBJWriter), .stl
 * (vtkSTLWriter, binary) and .off (vtkKerfOFFWriter). Only .vtp and .vtk keep every data array; the
 * other formats hold the geometry. Unknown extensions and write failures are reported with
 * vtkErrorMacro and Write() returns 0.
 */
#ifndef vtkKerfMeshFileWriter_h
#define vtkKerfMeshFileWriter_h

#include "KerfIOModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class KERFIO_EXPORT vtkKerfMeshFileWriter : public vtkWriter
{
public:
  static vtkKerfMeshFileWriter* New();
  vtkTypeMacro(vtkKerfMeshFileWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write; its extension chooses the format.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// 1 if the extension of fileName is one this writer handles.
  static int IsSupportedExtension(const char* fileName);

protected:
  vtkKerfMeshFileWriter() = default;
  ~vtkKerfMeshFileWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkKerfMeshFileWriter(const vtkKerfMeshFileWriter&) = delete;
  void operator=(const vtkKerfMeshFileWriter&) = delete;
};

#endif
