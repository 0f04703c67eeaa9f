// results.csv and summary.csv: rows formatted and parsed, the per-category means, the progress line.
#include "Evaluation/BenchmarkResults.h"

#include "Error.h"

#include <algorithm>
#include <exception>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

namespace kerf
{

namespace
{
// A CSV field in quotes, with "" for a quote.
std::string quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + "\"";
}

// Splits one CSV line (fields may be quoted, with "" for a quote).
std::vector<std::string> splitCsv(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool inQuotes = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (c == '"')
    {
      if (inQuotes && i + 1 < line.size() && line[i + 1] == '"')
      {
        field += '"';
        ++i;
      }
      else
      {
        inQuotes = !inQuotes;
      }
    }
    else if (c == ',' && !inQuotes)
    {
      fields.push_back(field);
      field.clear();
    }
    else
    {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}
} // namespace

const std::vector<std::string>& benchmarkMetricColumns()
{
  static const std::vector<std::string> columns = { "Comparisons", "CutDiscrepancy", "HammingDistance", "MissingRate",
    "FalseAlarmRate", "RandIndexError", "GlobalConsistencyError", "LocalConsistencyError", "Segments", "Seconds",
    "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" };
  return columns;
}

const std::vector<std::string>& benchmarkSummaryColumns()
{
  static const std::vector<std::string> columns = { "CutDiscrepancy", "HammingDistance", "RandIndexError",
    "GlobalConsistencyError", "LocalConsistencyError", "Fidelity", "InputSegmentsMatched", "Seconds" };
  return columns;
}

std::string resultsHeader()
{
  std::string header = "Model,Category,Method,Parameters";
  for (const std::string& column : benchmarkMetricColumns())
  {
    header += "," + column;
  }
  return header;
}

std::string formatResultRow(const BenchmarkRow& row)
{
  std::ostringstream line;
  line << std::setprecision(10) << row.model << "," << row.category << "," << row.method << ","
       << quoted(row.parameters);
  for (const std::string& column : benchmarkMetricColumns())
  {
    const auto found = row.values.find(column);
    line << "," << (found == row.values.end() ? 0.0 : found->second);
  }
  return line.str();
}

BenchmarkRow parseResultRow(const std::string& line)
{
  const std::vector<std::string> fields = splitCsv(line);
  const std::vector<std::string>& columns = benchmarkMetricColumns();
  if (fields.size() != 4 + columns.size())
  {
    throw Error("a malformed result line: " + line);
  }
  BenchmarkRow row;
  try
  {
    row.model = std::stoi(fields[0]);
    row.category = fields[1];
    row.method = fields[2];
    row.parameters = fields[3];
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
      row.values[columns[c]] = std::stod(fields[4 + c]);
    }
  }
  catch (const std::exception&)
  {
    throw Error("a malformed result line: " + line);
  }
  return row;
}

void writeResults(const std::vector<BenchmarkRow>& rows, const std::string& fileName)
{
  std::ofstream csv(fileName);
  csv << resultsHeader() << "\n";
  for (const BenchmarkRow& row : rows)
  {
    csv << formatResultRow(row) << "\n";
  }
  if (!csv)
  {
    throw Error("cannot write " + fileName);
  }
}

std::string writeSummary(const std::vector<BenchmarkRow>& rows, const std::string& method, const std::string& fileName)
{
  std::vector<std::pair<std::string, std::vector<const BenchmarkRow*>>> groups;
  for (const BenchmarkRow& row : rows)
  {
    auto group = std::find_if(groups.begin(), groups.end(), [&row](const auto& g) { return g.first == row.category; });
    if (group == groups.end())
    {
      groups.emplace_back(row.category, std::vector<const BenchmarkRow*>());
      group = groups.end() - 1;
    }
    group->second.push_back(&row);
  }
  std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const BenchmarkRow*> all;
  for (const BenchmarkRow& row : rows)
  {
    all.push_back(&row);
  }
  groups.emplace_back("all", all);

  std::ofstream csv(fileName);
  std::ostringstream table;
  csv << "Category,Method,Models";
  for (const std::string& column : benchmarkSummaryColumns())
  {
    csv << "," << column;
  }
  csv << "\n";
  // Terminal headings of the summary columns: the fidelity is 1 - RI against the input human.
  const std::map<std::string, std::string> headings = { { "CutDiscrepancy", "CD" }, { "HammingDistance", "HD" },
    { "RandIndexError", "1-RI" }, { "GlobalConsistencyError", "GCE" }, { "LocalConsistencyError", "LCE" },
    { "Fidelity", "fidelity" }, { "InputSegmentsMatched", "k-match" }, { "Seconds", "seconds" } };
  table << std::left << std::setw(11) << "category" << std::right << std::setw(7) << "models";
  for (const std::string& column : benchmarkSummaryColumns())
  {
    table << std::setw(column == "Seconds" ? 10 : 9) << headings.at(column);
  }
  table << "\n";
  for (const auto& group : groups)
  {
    csv << group.first << "," << method << "," << group.second.size();
    table << std::left << std::setw(11) << group.first << std::right << std::setw(7) << group.second.size();
    for (const std::string& column : benchmarkSummaryColumns())
    {
      double sum = 0.0;
      for (const BenchmarkRow* row : group.second)
      {
        sum += row->values.at(column);
      }
      const double mean = group.second.empty() ? 0.0 : sum / static_cast<double>(group.second.size());
      csv << "," << std::setprecision(10) << mean;
      table << std::fixed << std::setprecision(3) << std::setw(column == "Seconds" ? 10 : 9) << mean;
      table.unsetf(std::ios::fixed);
    }
    csv << "\n";
    table << "\n";
  }
  if (!csv)
  {
    throw Error("cannot write " + fileName);
  }
  return table.str();
}

std::string progressLine(std::size_t done, std::size_t total, const BenchmarkRow& row)
{
  std::ostringstream line;
  line << "[" << std::setw(3) << done << "/" << total << "] model " << std::setw(4) << row.model << " " << std::left
       << std::setw(10) << row.category << std::right << " 1-RI " << std::fixed << std::setprecision(3)
       << row.values.at("RandIndexError") << "  CD " << row.values.at("CutDiscrepancy") << "  HD "
       << row.values.at("HammingDistance") << "  (" << std::setprecision(2) << row.values.at("Seconds") << " s)";
  return line.str();
}

} // namespace kerf
