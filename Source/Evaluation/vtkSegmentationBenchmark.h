/**
 * @class vtkSegmentationBenchmark
 * @brief The benchmark runner: a segmentation method over the models of a Princeton benchmark
 * folder, scored against the human segmentations.
 *
 * The folder has the benchmark's layout: off/N.off, seg/N/N_j.seg and nSeg-ByModel.txt. For each
 * requested model (all by default) the method runs and its segmentation is compared with the
 * benchmark's metrics (Chen et al. 2009; see vtkSegmentationMetrics); the output table has one
 * row per model with the mean of every metric over the comparisons. The methods, their
 * protocols and parameters are listed by `kerf benchmark --help` and GetMethodNames(); they run
 * in Core (kerf::segmentationMethods):
 * - "human": every unordered pair of the model's human segmentations (the benchmark's human
 *   baseline). Missing and false-alarm rates are averaged over both orders of each pair.
 * - "harmonic-cuts": SeamCut's cuts from strokes, with simulated input made from human 0: one
 *   stroke along each boundary between two of its segments, one harmonic field per stroke, the
 *   isoline nearest each stroke as its cut, and the segments all cuts bound together; scored
 *   against humans 1 to n-1, so the input human is never a reference. Parameters: weighting
 *   (cotangent, uniform, concavity, smooth-concavity; default cotangent), samples (4), offset
 *   (0.005 of the diagonal), spacing (0.03 of the diagonal), weight (soft-constraint weight, 1).
 * - "region-growing" and "region-growing+snakes": Easy Mesh Cutting (Ji et al. 2006), each human
 *   in turn giving the input: one stroke per segment along its innermost faces
 *   (kerf::innermostStrokes), region growing under the isophotic metric, then `corrections`
 *   rounds adding a stroke inside the wrongly labelled faces of each segment, as a user corrects
 *   the result; the second refines the boundaries as snakes at the end. Parameters:
 *   normal-weight (w, 5), curvature-weight (w*, 5), augmentation (exponential, linear, square),
 *   curvature-term (per-length, per-edge), placement (random-walks, minimum-cut, fronts: where the
 *   boundaries go), cut-band (0.3, with placement=minimum-cut or random-walks), depth (0.2: the stroke keeps
 *   to faces at least this fraction as far inside as the innermost), corrections (3), overrides
 *   (0: rounds of override strokes along the input human's boundaries), override-radius (0.02),
 *   spacing (0.03).
 * - "roi-scissor": ROI Scissor from simulated clicks (kerf::selectByClicks), each human in turn
 *   giving the input: each piece of a segment but the largest selected by a click with a disc
 *   that holds it, corrected by added or subtracted discs while its region is wrong; the largest
 *   piece is the rest (Documentation/filters/SegmentationMetrics.md lists its parameters).
 *
 * With an OutputDirectory the runner writes results.csv (one row per model), summary.csv (means
 * per category and overall) and, with WritePictures, pictures/N.png (the method's segmentation
 * beside a human's, coloured alike). NumberOfJobs > 1 runs the models in that many worker
 * processes. Both `kerf benchmark` and `python3 -m kerf.benchmark` are front ends of this class.
 *
 * Output 0 (vtkTable): Model, Category, Method, Parameters, then kerf::benchmarkMetricColumns():
 * Comparisons, CutDiscrepancy, HammingDistance, MissingRate, FalseAlarmRate, RandIndexError,
 * GlobalConsistencyError, LocalConsistencyError, Segments (mean number of segments the method
 * produced), Seconds (time the method took, 0 for "human").
 * Output 1 (vtkPolyData, with one job only): the last model's mesh with the cell arrays "Method"
 * (the method's segmentation, renumbered with kerf::matchLabels so that colours match) and
 * "Human" (the human it is shown beside).
 *
 * A missing folder, an unknown method or parameter, a requested model that is not in the
 * folder, a model with too few human segmentations, and unreadable files are reported with
 * vtkErrorMacro.
 */
#ifndef vtkSegmentationBenchmark_h
#define vtkSegmentationBenchmark_h

#include "KerfEvaluationModule.h"
#include "vtkTableAlgorithm.h"

#include <string>
#include <vector>

class vtkTable;

class KERFEVALUATION_EXPORT vtkSegmentationBenchmark : public vtkTableAlgorithm
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
  /// The method to evaluate. Default "human". See GetMethodNames().
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

  ///@{
  /// Worker processes. Default 1 (the models run in this process).
  vtkSetClampMacro(NumberOfJobs, int, 1, 64);
  vtkGetMacro(NumberOfJobs, int);
  ///@}

  ///@{
  /// Folder for results.csv, summary.csv and pictures/ (created if needed); none (the default)
  /// writes nothing.
  vtkSetFilePathMacro(OutputDirectory);
  vtkGetFilePathMacro(OutputDirectory);
  ///@}

  ///@{
  /// Whether pictures/N.png are drawn into the OutputDirectory (they need a display: run under
  /// xvfb-run -a on a headless machine). Default on.
  vtkSetMacro(WritePictures, bool);
  vtkGetMacro(WritePictures, bool);
  vtkBooleanMacro(WritePictures, bool);
  ///@}

  ///@{
  /// Whether a line per finished model is printed on the standard output. Default off.
  vtkSetMacro(PrintProgress, bool);
  vtkGetMacro(PrintProgress, bool);
  vtkBooleanMacro(PrintProgress, bool);
  ///@}

  /// The summary table of the last run (means per category), as printed by the front ends.
  const std::string& GetSummary() const { return this->Summary; }

  /// The methods this class can run, and one line saying what each does.
  static std::vector<std::string> GetMethodNames();
  static std::string GetMethodDescription(const std::string& method);

  /// The ids of the models in a benchmark folder, sorted; empty (and `error` set) if the folder
  /// cannot be read.
  static std::vector<int> FindModels(const std::string& directory, std::string& error);

  /// Writes results.csv and summary.csv of `table` (output 0 of runs on parts of the models,
  /// appended) into `directory`; returns the summary table, or an empty string and sets `error`.
  static std::string WriteResults(vtkTable* table, const std::string& directory, std::string& error);

protected:
  vtkSegmentationBenchmark();
  ~vtkSegmentationBenchmark() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* DataDirectory = nullptr;
  char* Method = nullptr;
  char* MethodParameters = nullptr;
  std::vector<int> Models;
  int NumberOfJobs = 1;
  char* OutputDirectory = nullptr;
  bool WritePictures = true;
  bool PrintProgress = false;
  std::string Summary;

private:
  vtkSegmentationBenchmark(const vtkSegmentationBenchmark&) = delete;
  void operator=(const vtkSegmentationBenchmark&) = delete;
};

#endif
