// 1 - Rand index between two partitions from their contingency table.
#include "Segmentation/PartitionDistance.h"

#include "Error.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace kerf
{

namespace
{

// Labels renumbered 0..m-1 in order of first appearance: through a table when the largest label
// is below a few times the faces (the segmentations' labels always are), else a hash map.
std::vector<int> compact(const std::vector<int>& labels, int& count)
{
  std::vector<int> result(labels.size());
  int largest = 0;
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    if (labels[f] < 0)
    {
      throw Error("a partition has the negative label " + std::to_string(labels[f]) + " at face " + std::to_string(f));
    }
    largest = std::max(largest, labels[f]);
  }
  count = 0;
  if (static_cast<std::size_t>(largest) <= 4 * labels.size() + 64)
  {
    std::vector<int> dense(static_cast<std::size_t>(largest) + 1, -1);
    for (std::size_t f = 0; f < labels.size(); ++f)
    {
      int& label = dense[static_cast<std::size_t>(labels[f])];
      if (label < 0)
      {
        label = count++;
      }
      result[f] = label;
    }
    return result;
  }
  std::unordered_map<int, int> dense;
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    result[f] = dense.emplace(labels[f], static_cast<int>(dense.size())).first->second;
  }
  count = static_cast<int>(dense.size());
  return result;
}

double pairs(double n)
{
  return n * (n - 1.0) / 2.0;
}

} // namespace

double randIndexError(const std::vector<int>& a, const std::vector<int>& b)
{
  if (a.size() != b.size())
  {
    throw Error("comparing partitions of " + std::to_string(a.size()) + " and " + std::to_string(b.size()) + " faces");
  }
  int rows = 0, columns = 0;
  const std::vector<int> row = compact(a, rows);
  const std::vector<int> column = compact(b, columns);
  if (a.size() < 2)
  {
    return 0.0;
  }
  std::vector<double> rowSizes(rows, 0.0), columnSizes(columns, 0.0);
  // The contingency table's cells: a dense table when it is no larger than a few times the faces,
  // else a hash map of the cells that occur.
  std::vector<double> table;
  std::unordered_map<long long, double> cells;
  const bool dense = static_cast<double>(rows) * columns <= 4.0 * static_cast<double>(a.size()) + 4096.0;
  if (dense)
  {
    table.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns), 0.0);
  }
  for (std::size_t f = 0; f < a.size(); ++f)
  {
    rowSizes[row[f]] += 1.0;
    columnSizes[column[f]] += 1.0;
    const long long cell = static_cast<long long>(row[f]) * columns + column[f];
    if (dense)
    {
      table[static_cast<std::size_t>(cell)] += 1.0;
    }
    else
    {
      cells[cell] += 1.0;
    }
  }
  // Pairs together in a plus pairs together in b minus twice the pairs together in both: the pairs
  // on which they disagree. Every term and partial sum is a whole number of at most n (n - 1), exact
  // in a double for n below 9.4e7 faces, so the cells' order (a hash map's) does not change it.
  double disagreeing = 0.0;
  for (double size : rowSizes)
  {
    disagreeing += pairs(size);
  }
  for (double size : columnSizes)
  {
    disagreeing += pairs(size);
  }
  for (const double size : table)
  {
    disagreeing -= 2.0 * pairs(size);
  }
  for (const auto& cell : cells)
  {
    disagreeing -= 2.0 * pairs(cell.second);
  }
  return disagreeing / pairs(static_cast<double>(a.size()));
}

} // namespace kerf
