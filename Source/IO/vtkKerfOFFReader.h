/**
 * @class vtkKerfOFFReader
 * @brief Reads ASCII OFF meshes (Princeton Segmentation Benchmark, CGAL, Geomview).
 *
 * Produces a vtkPolyData with double-precision points and one polygon per OFF face, in file
 * order, so that face i of the file is cell i (as the benchmark's .seg files expect). Header
 * variants with per-vertex normals, colours or texture coordinates (NOFF, COFF, STOFF, 4OFF)
 * are read for their coordinates; the extra columns are skipped. Comments start with '#'.
 * Truncated or malformed files, binary OFF and out-of-range indices are reported with
 * vtkErrorMacro (naming the line) and produce an empty output and a failed update.
 */
#ifndef vtkKerfOFFReader_h
#define vtkKerfOFFReader_h

#include "KerfIOModule.h"
#include "vtkPolyDataAlgorithm.h"

class KERFIO_EXPORT vtkKerfOFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkKerfOFFReader* New();
  vtkTypeMacro(vtkKerfOFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The OFF file to read.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// 1 if the file starts like an OFF file, else 0.
  static int CanReadFile(const char* fileName);

protected:
  vtkKerfOFFReader();
  ~vtkKerfOFFReader() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkKerfOFFReader(const vtkKerfOFFReader&) = delete;
  void operator=(const vtkKerfOFFReader&) = delete;
};

#endif
