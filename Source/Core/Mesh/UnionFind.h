// Union-find with path halving: the one forest every Core algorithm merges with.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace kerf
{
/// The root of `i` in the forest `parent` (parent[r] == r at a root), halving the path on the way
/// (every node visited is pointed at its grandparent). `Parents` is anything indexed by int that
/// holds ints: a std::vector<int>, an int*, a HugePageVector<int>.
template <typename Parents>
int findRoot(Parents& parent, int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Joins the trees of `a` and `b` in `parent`, the smaller root becoming the root of both, so
/// that the forest does not depend on the order of a join's arguments. Returns false if they were
/// one tree already.
template <typename Parents>
bool joinRoots(Parents& parent, int a, int b)
{
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a == b)
  {
    return false;
  }
  parent[std::max(a, b)] = std::min(a, b);
  return true;
}

/// A union-find over 0 .. n-1 (findRoot and joinRoots on a forest of its own).
class UnionFind
{
public:
  explicit UnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int find(int a) { return findRoot(this->Parent, a); }
  bool join(int a, int b) { return joinRoots(this->Parent, a, b); }

private:
  std::vector<int> Parent;
};
} // namespace kerf
