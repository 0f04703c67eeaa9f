/**
 * @class vtkSegmentationWriter
 * @brief Writes a per-cell label array as a Princeton Segmentation Benchmark .seg file.
 *
 * One integer per line, line i holding the label of cell i. The cell array is chosen by name
 * with SetArrayName (default "Segment"). It must have one component and hold finite integral
 * values; otherwise nothing is written and the error is reported.
 */
#ifndef vtkSegmentationWriter_h
#define vtkSegmentationWriter_h

#include "KerfIOModule.h"
#include "vtkWriter.h"

class vtkPolyData;

class KERFIO_EXPORT vtkSegmentationWriter : public vtkWriter
{
public:
  static vtkSegmentationWriter* New();
  vtkTypeMacro(vtkSegmentationWriter, vtkWriter);
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
  vtkSegmentationWriter();
  ~vtkSegmentationWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char* ArrayName = nullptr;

private:
  vtkSegmentationWriter(const vtkSegmentationWriter&) = delete;
  void operator=(const vtkSegmentationWriter&) = delete;
};

#endif
