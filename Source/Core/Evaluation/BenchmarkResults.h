// The benchmark's results: the columns, one row per model, results.csv and summary.csv written and read.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace kerf
{

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

} // namespace kerf
