/**
 * @class vtkKerfSegmentationWriter
 * @brief Writes a per-cell label array as a Princeton Segmentation Benchmark .seg file.
 *
 * One integer per line, line i holding the label of cell i. The cell array is chosen by name
 * with SetArrayName (default "Segment"). It must have one component and hold finite integral
 * values; otherwise nothing is written and the error is reported.
 */
#ifndef vtkKerfSegmentationWriter_h
#define vtkKerfSegmentationWriter_h

#include "KerfIOModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class KERFIO_EXPORT vtkKerfSegmentationWriter : public vtkWriter
{
public:
  static vtkKerfSegmentationWriter* New();
  vtkTypeMacro(vtkKerfSegmentationWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .seg file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /// Name of the cell array to write. Default "Segment".
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

protected:
  vtkKerfSegmentationWriter();
  ~vtkKerfSegmentationWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char* ArrayName = nullptr;

private:
  vtkKerfSegmentationWriter(const vtkKerfSegmentationWriter&) = delete;
  void operator=(const vtkKerfSegmentationWriter&) = delete;
};

#endif
