// Nested dissection by coordinate bisection (George 1973; Miller, Teng, Thurston and Vavasis 1998).
#include "Harmonic/NestedDissection.h"

#include "Error.h"

#include <algorithm>
#include <array>

namespace kerf
{

std::vector<int> geometricNestedDissection(
  const std::vector<Vector3>& points, const Eigen::SparseMatrix<double>& lowerPattern, int leafSize)
{
  const int n = static_cast<int>(points.size());
  if (lowerPattern.rows() != n || lowerPattern.cols() != n)
  {
    throw Error("the ordering needs one point per row of a square matrix");
  }
  leafSize = std::max(leafSize, 1);

  // Symmetric adjacency without the diagonal, in compressed rows.
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
  for (int c = 0; c < lowerPattern.outerSize(); ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lowerPattern, c); it; ++it)
    {
      const int r = static_cast<int>(it.row()), col = static_cast<int>(it.col());
      if (r != col)
      {
        ++start[r + 1];
        ++start[col + 1];
      }
    }
  }
  for (int v = 0; v < n; ++v)
  {
    start[v + 1] += start[v];
  }
  std::vector<int> adjacency(static_cast<std::size_t>(start[n]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int c = 0; c < lowerPattern.outerSize(); ++c)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(lowerPattern, c); it; ++it)
      {
        const int r = static_cast<int>(it.row()), col = static_cast<int>(it.col());
        if (r != col)
        {
          adjacency[fill[r]++] = col;
          adjacency[fill[col]++] = r;
        }
      }
    }
  }

  // ids[begin, end) is a part to order into perm[begin, end): its halves first, its separator
  // last. side[v] tells, while a part is split, which half v is in (stamped per split).
  std::vector<int> ids(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
  {
    ids[v] = v;
  }
  std::vector<int> perm(static_cast<std::size_t>(n));
  std::vector<int> side(static_cast<std::size_t>(n), -1);
  std::vector<std::array<int, 2>> parts{ { 0, n } };
  int stamp = 0;
  while (!parts.empty())
  {
    const auto [begin, end] = parts.back();
    parts.pop_back();
    const int size = end - begin;
    if (size <= leafSize)
    {
      std::sort(ids.begin() + begin, ids.begin() + end);
      std::copy(ids.begin() + begin, ids.begin() + end, perm.begin() + begin);
      continue;
    }
    const int middle = begin + size / 2;
    auto splitAt = [&](int axis) {
      std::nth_element(ids.begin() + begin, ids.begin() + middle, ids.begin() + end, [&](int a, int b) {
        const double pa = points[a][axis], pb = points[b][axis];
        return pa < pb || (pa == pb && a < b);
      });
    };
    // Halves stamped 2s (first) and 2s + 1 (second); the separator is the half's rows with a
    // neighbour in the other half, taken from the half where it is smaller.
    int first = 0, second = 0;
    auto touchesOther = [&](int v, int other) {
      for (int k = start[v]; k < start[v + 1]; ++k)
      {
        if (side[adjacency[k]] == other)
        {
          return true;
        }
      }
      return false;
    };
    int firstSeparator = 0, secondSeparator = 0;
    auto separators = [&]() {
      first = 2 * stamp;
      second = 2 * stamp + 1;
      ++stamp;
      for (int i = begin; i < end; ++i)
      {
        side[ids[i]] = i < middle ? first : second;
      }
      firstSeparator = secondSeparator = 0;
      for (int i = begin; i < end; ++i)
      {
        const int v = ids[i];
        if (i < middle ? touchesOther(v, second) : touchesOther(v, first))
        {
          ++(i < middle ? firstSeparator : secondSeparator);
        }
      }
      return std::min(firstSeparator, secondSeparator);
    };
    // The axis whose median plane gives the smallest separator.
    int bestAxis = 0, bestSize = -1;
    for (int axis = 0; axis < 3; ++axis)
    {
      splitAt(axis);
      const int separatorSize = separators();
      if (bestSize < 0 || separatorSize < bestSize)
      {
        bestAxis = axis;
        bestSize = separatorSize;
      }
    }
    if (bestAxis != 2)
    {
      splitAt(bestAxis);
      separators();
    }
    const bool cutFirst = firstSeparator <= secondSeparator;
    // Stable partition of the part into [first half][second half][separator].
    std::array<std::vector<int>, 3> groups;
    for (int i = begin; i < end; ++i)
    {
      const int v = ids[i];
      const bool inFirst = i < middle;
      const bool separator = inFirst == cutFirst && touchesOther(v, inFirst ? second : first);
      groups[separator ? 2 : (inFirst ? 0 : 1)].push_back(v);
    }
    int at = begin;
    for (const std::vector<int>& group : groups)
    {
      std::copy(group.begin(), group.end(), ids.begin() + at);
      at += static_cast<int>(group.size());
    }
    const int firstEnd = begin + static_cast<int>(groups[0].size());
    const int secondEnd = firstEnd + static_cast<int>(groups[1].size());
    // The separator keeps increasing index order, eliminated last.
    std::sort(ids.begin() + secondEnd, ids.begin() + end);
    std::copy(ids.begin() + secondEnd, ids.begin() + end, perm.begin() + secondEnd);
    for (int i = begin; i < end; ++i)
    {
      side[ids[i]] = -1;
    }
    if (secondEnd > firstEnd)
    {
      parts.push_back({ firstEnd, secondEnd });
    }
    if (firstEnd > begin)
    {
      parts.push_back({ begin, firstEnd });
    }
  }
  return perm;
}

} // namespace kerf
