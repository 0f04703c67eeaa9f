// The benchmark runner: segmentation methods run over a benchmark folder, scored, and written as results.csv/summary.csv.
#pragma once

#include "Evaluation/PrincetonBenchmark.h"
#include "Session/Surface.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace kerf
{

/// One model ready for a method: its surface and its human segmentations.
struct BenchmarkCase
{
  BenchmarkModel model;
  std::shared_ptr<const Surface> surface;
  std::vector<std::vector<int>> humans; ///< per face, in the order of model.humanSegmentations
};

/// Reads a model's mesh (OFF, triangles only; coincident points welded as every Kerf filter does)
/// and its human segmentations; throws kerf::Error naming the file and the problem.
BenchmarkCase loadBenchmarkCase(const BenchmarkModel& model);

/// A method's parameters, "name=value;name=value", parsed and checked against the names it knows.
class MethodParameters
{
public:
  MethodParameters(const std::string& text, const std::vector<std::string>& known);
  /// The value of a positive number parameter, or `fallback`; throws for anything else.
  double positive(const std::string& name, double fallback) const;
  /// The value of a number parameter (any finite number, the whole text), or `fallback`; throws for
  /// anything else ("0.5,x=1" is not 0.5).
  double number(const std::string& name, double fallback) const;
  /// The text of a parameter, or `fallback`.
  std::string text(const std::string& name, const std::string& fallback) const;

private:
  std::map<std::string, std::string> Values;
};

/// What a method did on one model: the mean of every metric over its comparisons, and what to
/// show in its picture.
struct ModelScores
{
  std::map<std::string, double> values; ///< every column of benchmarkMetricColumns()
  std::vector<int> shownMethod;         ///< the method's segmentation (per face)
  std::vector<int> shownHuman;          ///< the human it is shown beside
};

/// What a method made of one model.
struct MethodOutput
{
  std::vector<int> labels; ///< per face
  int inputs = 0;          ///< strokes or clicks it was given (interactive methods)
};

/// A segmentation method the runner knows, and the protocol it is scored with.
struct SegmentationMethod
{
  enum class Protocol
  {
    /// The humans against each other (the benchmark's human baseline); `segment` is unused.
    HumanBaseline,
    /// Input simulated from one human: every human of the model in turn is the input and the
    /// others the references (leave one out, as the human baseline); also scored against the
    /// input human itself (the fidelity: how well the user's intent is reproduced).
    Interactive,
    /// The mesh and the number of segments only (nSeg-ByModel.txt), scored against every human.
    Automatic
  };
  std::string name;
  std::string description;
  std::vector<std::string> parameters;
  Protocol protocol = Protocol::Interactive;
  /// Segments a model; `input` is the human the input is simulated from (Interactive) or null.
  std::function<MethodOutput(const BenchmarkCase&, const std::vector<int>* input, const MethodParameters&)> segment;
};

/// Every method, in the order the help lists them.
const std::vector<SegmentationMethod>& segmentationMethods();
/// The method of that name; throws kerf::Error listing the names for any other.
const SegmentationMethod& findSegmentationMethod(const std::string& name);

/// The columns a method fills for each model (after Model, Category, Method, Parameters): the
/// comparisons made, the benchmark's metrics against the reference humans, the number of
/// segments and the method's time per segmentation; for interactive methods also the fidelity
/// (1 - Rand index and Hamming distance against the input human), the inputs given (strokes or
/// clicks, mean per run) and the fraction of runs that made as many segments as the input human
/// (NaN for methods without input).
const std::vector<std::string>& benchmarkMetricColumns();
/// The columns summary.csv averages per category.
const std::vector<std::string>& benchmarkSummaryColumns();

/// One row of results.csv.
struct BenchmarkRow
{
  int model = 0;
  std::string category;
  std::string method;
  std::string parameters;
  std::map<std::string, double> values;
};

/// Runs `method` with `parameters` on one model; throws kerf::Error naming the model.
BenchmarkRow runBenchmarkModel(const BenchmarkCase& benchmarkCase, const SegmentationMethod& method,
  const std::string& parameters, ModelScores* scores = nullptr);

/// results.csv: the header and one line per row, numbers with 10 significant digits.
std::string resultsHeader();
std::string formatResultRow(const BenchmarkRow& row);
BenchmarkRow parseResultRow(const std::string& line);
void writeResults(const std::vector<BenchmarkRow>& rows, const std::string& fileName);

/// summary.csv (the means of benchmarkSummaryColumns per category, categories sorted, then
/// "all"); returns the same table formatted for a terminal.
std::string writeSummary(const std::vector<BenchmarkRow>& rows, const std::string& method, const std::string& fileName);

/// A progress line for a finished model: "[  3/40] model  142 Bearing    1-RI 0.123 ...".
std::string progressLine(std::size_t done, std::size_t total, const BenchmarkRow& row);

/// Runs `work` for every model in `jobs` worker processes (fork; 1 runs in this process), each
/// sending one results.csv line per model back through a pipe, and calls `finished` as rows
/// arrive. Returns the rows sorted by model; throws kerf::Error if any model failed (with the
/// first failure's message).
std::vector<BenchmarkRow> runInWorkers(const std::vector<int>& models, int jobs,
  const std::function<BenchmarkRow(int)>& work,
  const std::function<void(std::size_t done, const BenchmarkRow&)>& finished);

} // namespace kerf
