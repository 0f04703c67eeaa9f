// How far apart two partitions of the same faces are: 1 - Rand index over face pairs.
#pragma once

#include <vector>

namespace kerf
{

/// 1 - Rand index of two partitions of the same n faces (any non-negative labels): the fraction
/// of the n (n - 1) / 2 unordered face pairs that one partition puts together and the other
/// apart, from the contingency table in O(n + distinct label pairs). 0 for n < 2. Throws
/// kerf::Error for partitions of different sizes or a negative label.
double randIndexError(const std::vector<int>& a, const std::vector<int>& b);

} // namespace kerf
