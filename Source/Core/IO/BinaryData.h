// Byte-order decoding and overflow-safe size checks for the binary parts of mesh files.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

namespace kerf
{

/// True if `count` items of `itemBytes` bytes each fit in `availableBytes`, computed without
/// overflow (count * itemBytes is never formed).
inline bool fitsIn(std::uint64_t count, std::uint64_t itemBytes, std::uint64_t availableBytes)
{
  return itemBytes == 0 || count <= availableBytes / itemBytes;
}

/// The unsigned integer of `size` bytes (1 to 8) at `bytes`, little or big endian.
inline std::uint64_t decodeUnsigned(const unsigned char* bytes, int size, bool bigEndian)
{
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i)
  {
    const int shift = bigEndian ? 8 * (size - 1 - i) : 8 * i;
    value |= static_cast<std::uint64_t>(bytes[i]) << shift;
  }
  return value;
}

/// The two's-complement integer of `size` bytes at `bytes`.
inline std::int64_t decodeSigned(const unsigned char* bytes, int size, bool bigEndian)
{
  std::uint64_t value = decodeUnsigned(bytes, size, bigEndian);
  if (size < 8 && (value >> (8 * size - 1)) != 0)
  {
    value |= ~std::uint64_t(0) << (8 * size);
  }
  std::int64_t result;
  std::memcpy(&result, &value, sizeof result);
  return result;
}

inline float decodeFloat(const unsigned char* bytes, bool bigEndian)
{
  const auto bits = static_cast<std::uint32_t>(decodeUnsigned(bytes, 4, bigEndian));
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

inline double decodeDouble(const unsigned char* bytes, bool bigEndian)
{
  const std::uint64_t bits = decodeUnsigned(bytes, 8, bigEndian);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// The bytes of a string_view as unsigned char.
inline const unsigned char* bytesOf(std::string_view text, std::size_t offset = 0)
{
  return reinterpret_cast<const unsigned char*>(text.data()) + offset;
}

} // namespace kerf
