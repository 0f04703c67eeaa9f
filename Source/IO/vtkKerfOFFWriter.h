/**
 * @class vtkKerfOFFWriter
 * @brief Writes the polygons and triangle strips of a vtkPolyData as ASCII OFF.
 *
 * Points are written with 17 significant digits, so that reading the file back gives the same
 * doubles. Strips are split into triangles; vertices and lines are not written. Data arrays are
 * not part of OFF: write a per-face segmentation with vtkKerfSegmentationWriter.
 */
#ifndef vtkKerfOFFWriter_h
#define vtkKerfOFFWriter_h

#include "KerfIOModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class KERFIO_EXPORT vtkKerfOFFWriter : public vtkWriter
{
public:
  static vtkKerfOFFWriter* New();
  vtkTypeMacro(vtkKerfOFFWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The OFF file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  vtkPolyData* GetInput();

protected:
  vtkKerfOFFWriter() = default;
  ~vtkKerfOFFWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkKerfOFFWriter(const vtkKerfOFFWriter&) = delete;
  void operator=(const vtkKerfOFFWriter&) = delete;
};

#endif
