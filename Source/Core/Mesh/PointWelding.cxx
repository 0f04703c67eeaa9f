// Exact coincident-point detection with a hash table on the coordinates' bit patterns.
#include "Mesh/PointWelding.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace kerf
{

namespace
{
struct Coordinates
{
  std::uint64_t bits[3];
  bool operator==(const Coordinates& other) const
  {
    return bits[0] == other.bits[0] && bits[1] == other.bits[1] && bits[2] == other.bits[2];
  }
};

struct CoordinatesHash
{
  std::size_t operator()(const Coordinates& c) const
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint64_t b : c.bits)
    {
      h ^= b + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h * 0xFF51AFD7ED558CCDull);
  }
};

Coordinates key(const Vector3& p)
{
  Coordinates c;
  for (int k = 0; k < 3; ++k)
  {
    const double value = p[k] + 0.0; // turns -0.0 into 0.0
    std::memcpy(&c.bits[k], &value, sizeof(double));
  }
  return c;
}
} // namespace

std::vector<int> findCoincidentPoints(const std::vector<Vector3>& points)
{
  std::vector<int> representative(points.size());
  std::unordered_map<Coordinates, int, CoordinatesHash> first;
  first.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    representative[i] = static_cast<int>(i);
    if (!points[i].allFinite())
    {
      continue;
    }
    const auto inserted = first.emplace(key(points[i]), static_cast<int>(i));
    representative[i] = inserted.first->second;
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
