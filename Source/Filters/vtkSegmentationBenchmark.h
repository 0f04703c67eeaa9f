/**
 * @class vtkSegmentationBenchmark
 * @brief Runs a segmentation method over models of a Princeton benchmark folder and scores it
 * against the human segmentations.
 *
 * The folder has the benchmark's layout: off/N.off, seg/N/N_j.seg and nSeg-ByModel.txt. For each
 * requested model (all by default) the method runs and its segmentation is compared with
 * vtkSegmentationMetrics' metrics; the output table has one row per model with the mean of every
 * metric over the comparisons. Methods and their protocols:
 * - "human": the humans against each other: every unordered pair of the model's human
 *   segmentations (the benchmark's human baseline). Missing and false-alarm rates are averaged
 *   over both orders of each pair.
 * - "harmonic-cuts": SeamCut's cuts from strokes, with simulated input made from human 0: one
 *   stroke along each boundary between two of its segments (kerf::boundaryStrokes, points about
 *   `spacing` of the diagonal apart), one harmonic field per stroke (its constraints as in
 *   vtkStrokeConstraints), the isoline f = 0 nearest each stroke as that stroke's cut, and the
 *   segments all cuts bound together (kerf::labelCuts). Scored against humans 1 to n-1, so the
 *   input human is never a reference. Parameters: weighting (cotangent, uniform, concavity,
 *   smooth-concavity; default cotangent), samples (N_S, 4), offset (eps_C, 0.01 of the
 *   diagonal), spacing (0.03 of the diagonal), weight (soft-constraint weight, 1).
 *
 * Output 0 (vtkTable): Model, Category, Method, Parameters, Comparisons, CutDiscrepancy,
 * HammingDistance, MissingRate, FalseAlarmRate, RandIndexError, GlobalConsistencyError,
 * LocalConsistencyError, Segments (mean number of segments the method produced), Seconds (time
 * the method took, 0 for "human").
 * Output 1 (vtkPolyData): the last model's mesh with the cell arrays "Method" (the method's
 * segmentation; for "human", human 0) and "Human" (the human it is shown beside: human 1 for
 * "human", the input human 0 for the interactive methods), for pictures. "Method" is renumbered with kerf::matchLabels so that
 * each segment carries the label of the human segment it overlaps most and colours match.
 *
 * A missing folder, an unknown method, a requested model that is not in the folder, a model with
 * too few human segmentations, and unreadable files are reported with vtkErrorMacro.
 */
#ifndef vtkSegmentationBenchmark_h
#define vtkSegmentationBenchmark_h

#include "KerfFiltersModule.h"
#include "vtkTableAlgorithm.h"

#include <string>
#include <vector>

class KERFFILTERS_EXPORT vtkSegmentationBenchmark : public vtkTableAlgorithm
{
public:
  static vtkSegmentationBenchmark* New();
  vtkTypeMacro(vtkSegmentationBenchmark, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The benchmark folder (holding off/, seg/ and nSeg-ByModel.txt).
  vtkSetFilePathMacro(DataDirectory);
  vtkGetFilePathMacro(DataDirectory);
  ///@}

  ///@{
  /// The method to evaluate. Default "human". See the class comment for the list.
  vtkSetStringMacro(Method);
  vtkGetStringMacro(Method);
  ///@}

  ///@{
  /// The method's parameters as "name=value" pairs separated by ';' (recorded in the table).
  vtkSetStringMacro(MethodParameters);
  vtkGetStringMacro(MethodParameters);
  ///@}

  ///@{
  /// Models to run, by id; none (the default) means every model in the folder.
  void AddModel(int id);
  void ClearModels();
  ///@}

  /// The methods this class can run.
  static std::vector<std::string> GetMethodNames();

  /// The ids of the models in a benchmark folder, sorted; empty (and `error` set) if the folder
  /// cannot be read.
  static std::vector<int> FindModels(const std::string& directory, std::string& error);

protected:
  vtkSegmentationBenchmark();
  ~vtkSegmentationBenchmark() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* DataDirectory = nullptr;
  char* Method = nullptr;
  char* MethodParameters = nullptr;
  std::vector<int> Models;

private:
  vtkSegmentationBenchmark(const vtkSegmentationBenchmark&) = delete;
  void operator=(const vtkSegmentationBenchmark&) = delete;
};

#endif
