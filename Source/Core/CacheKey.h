// Keys for cached derived data: exact text for the options a result depends on.
#pragma once

#include <cstdio>
#include <string>

namespace kerf
{

/// A key part for a floating-point option: exact (hexadecimal), so different values never share
/// a key.
inline std::string cacheKey(double value)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%a", value);
  return text;
}

} // namespace kerf
