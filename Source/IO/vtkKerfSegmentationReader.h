/**
 * @class vtkKerfSegmentationReader
 * @brief Attaches a Princeton Segmentation Benchmark .seg file to a mesh as a cell array.
 *
 * A .seg file holds one integer per line: line i is the segment id of face i, in the face
 * order of the mesh's OFF file (which vtkKerfOFFReader keeps as the cell order). The input mesh is
 * passed to the output with an integer cell array (default name "Segment") added. The number of
 * labels must equal the number of cells; otherwise, and for unreadable or malformed files, the
 * filter reports the problem with vtkErrorMacro and fails.
 */
#ifndef vtkKerfSegmentationReader_h
#define vtkKerfSegmentationReader_h

#include "KerfIOModule.h"
#include "vtkPolyDataAlgorithm.h"

class KERFIO_EXPORT vtkKerfSegmentationReader : public vtkPolyDataAlgorithm
{
public:
  static vtkKerfSegmentationReader* New();
  vtkTypeMacro(vtkKerfSegmentationReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .seg file to read.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /// Name of the cell array that receives the labels. Default "Segment".
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

protected:
  vtkKerfSegmentationReader();
  ~vtkKerfSegmentationReader() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* FileName = nullptr;
  char* ArrayName = nullptr;

private:
  vtkKerfSegmentationReader(const vtkKerfSegmentationReader&) = delete;
  void operator=(const vtkKerfSegmentationReader&) = delete;
};

#endif
