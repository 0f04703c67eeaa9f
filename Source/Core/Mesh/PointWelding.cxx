// Exact coincident-point detection with an open-addressing hash table on the coordinates' bits.
#include "Mesh/PointWelding.h"

#include <cstdint>
#include <cstring>

namespace kerf
{

namespace
{
// Bit pattern of a coordinate, with -0.0 turned into 0.0 so that both compare equal.
std::uint64_t bits(double value)
{
  value += 0.0;
  std::uint64_t b;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

std::uint64_t mix(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ull;
  h ^= h >> 33;
  return h;
}
} // namespace

std::vector<int> findCoincidentPoints(const std::vector<Vector3>& points)
{
  const std::size_t n = points.size();
  std::vector<int> representative(n);
  std::size_t capacity = 16;
  while (capacity < 2 * n)
  {
    capacity *= 2;
  }
  std::vector<int> table(capacity, -1); // point index, or -1 for an empty slot
  const std::size_t mask = capacity - 1;
  for (std::size_t i = 0; i < n; ++i)
  {
    representative[i] = static_cast<int>(i);
    const Vector3& p = points[i];
    if (!p.allFinite())
    {
      continue;
    }
    const std::uint64_t x = bits(p.x()), y = bits(p.y()), z = bits(p.z());
    std::size_t slot = static_cast<std::size_t>(mix(x ^ mix(y ^ mix(z)))) & mask;
    while (true)
    {
      const int other = table[slot];
      if (other < 0)
      {
        table[slot] = static_cast<int>(i);
        break;
      }
      const Vector3& q = points[other];
      if (bits(q.x()) == x && bits(q.y()) == y && bits(q.z()) == z)
      {
        representative[i] = other;
        break;
      }
      slot = (slot + 1) & mask;
    }
  }
  return representative;
}

void weldTriangles(const std::vector<int>& representative, std::vector<Triangle>& triangles)
{
  for (Triangle& t : triangles)
  {
    for (int& corner : t)
    {
      corner = representative[corner];
    }
  }
}

} // namespace kerf
