// Plane geometry shared by polygon triangulation, chart packing and chart parameterization.
#pragma once

#include <Eigen/Core>

namespace kerf
{

/// The z component of the cross product of two plane vectors: twice the signed area of the
/// triangle they span, positive when b lies counter-clockwise of a.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

} // namespace kerf
