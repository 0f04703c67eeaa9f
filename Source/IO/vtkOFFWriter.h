/**
 * @class vtkOFFWriter
 * @brief Writes the polygons and triangle strips of a vtkPolyData as ASCII OFF.
 *
 * Points are written with 17 significant digits, so that reading the file back gives the same
 * doubles. Strips are split into triangles; vertices and lines are not written. Data arrays are
 * not part of OFF: write a per-face segmentation with vtkSegmentationWriter.
 */
#ifndef vtkOFFWriter_h
#define vtkOFFWriter_h

#include "KerfIOModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class KERFIO_EXPORT vtkOFFWriter : public vtkWriter
{
public:
  static vtkOFFWriter* New();
  vtkTypeMacro(vtkOFFWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The OFF file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  vtkPolyData* GetInput();

protected:
  vtkOFFWriter() = default;
  ~vtkOFFWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkOFFWriter(const vtkOFFWriter&) = delete;
  void operator=(const vtkOFFWriter&) = delete;
};

#endif
