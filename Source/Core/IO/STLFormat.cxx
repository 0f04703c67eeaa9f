// STL parsing: binary facets or the ASCII solid/facet/loop structure, corners merged by coordinates.
#include "IO/STLFormat.h"

#include "Error.h"
#include "IO/BinaryData.h"
#include "IO/LineCursor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>

namespace kerf
{

namespace
{
// The bits of a corner's three floats, -0 folded onto +0 so that equal coordinates merge.
struct CornerKey
{
  std::uint32_t bits[3];
  bool operator==(const CornerKey& other) const
  {
    return this->bits[0] == other.bits[0] && this->bits[1] == other.bits[1] && this->bits[2] == other.bits[2];
  }
};

struct CornerHash
{
  std::size_t operator()(const CornerKey& key) const
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint32_t b : key.bits)
    {
      h ^= b;
      h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
  }
};

// Collects facets, merging corners with identical coordinates into one point.
class FacetCollector
{
public:
  explicit FacetCollector(MeshFileData& mesh, std::size_t expectedFacets)
    : Mesh(mesh)
  {
    this->Ids.reserve(expectedFacets);
    mesh.singlePrecision = true;
    mesh.points.reserve(3 * expectedFacets);
    mesh.polygons.offsets.reserve(expectedFacets + 1);
    mesh.polygons.indices.reserve(3 * expectedFacets);
  }

  void add(const float corners[9])
  {
    std::int64_t ids[3];
    for (int c = 0; c < 3; ++c)
    {
      CornerKey key;
      for (int k = 0; k < 3; ++k)
      {
        const float value = corners[3 * c + k] == 0.0f ? 0.0f : corners[3 * c + k];
        std::memcpy(&key.bits[k], &value, sizeof value);
      }
      const auto inserted = this->Ids.emplace(key, static_cast<std::int64_t>(this->Mesh.pointCount()));
      if (inserted.second)
      {
        this->Mesh.points.insert(this->Mesh.points.end(), { corners[3 * c], corners[3 * c + 1], corners[3 * c + 2] });
      }
      ids[c] = inserted.first->second;
    }
    if (ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2])
    {
      this->Mesh.polygons.indices.insert(this->Mesh.polygons.indices.end(), ids, ids + 3);
      this->Mesh.polygons.close();
    }
  }

private:
  MeshFileData& Mesh;
  std::unordered_map<CornerKey, std::int64_t, CornerHash> Ids;
};

// A double as a float; values beyond float's range become infinities (a plain cast is undefined).
float toFloat(double value)
{
  constexpr double largest = std::numeric_limits<float>::max();
  if (value > largest)
  {
    return std::numeric_limits<float>::infinity();
  }
  if (value < -largest)
  {
    return -std::numeric_limits<float>::infinity();
  }
  return static_cast<float>(value);
}

bool equalsIgnoringCase(std::string_view word, const char* keyword)
{
  const std::size_t n = std::strlen(keyword);
  if (word.size() != n)
  {
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const char c = word[i] >= 'A' && word[i] <= 'Z' ? static_cast<char>(word[i] - 'A' + 'a') : word[i];
    if (c != keyword[i])
    {
      return false;
    }
  }
  return true;
}

// ASCII if, after leading blanks, the file says "solid" and its first kilobyte is plain text.
bool looksLikeText(std::string_view bytes)
{
  std::size_t start = 0;
  while (start < bytes.size() && LineCursor::isSpace(bytes[start]))
  {
    ++start;
  }
  if (bytes.size() - start < 5 || !equalsIgnoringCase(bytes.substr(start, 5), "solid"))
  {
    return false;
  }
  for (std::size_t i = 0; i < bytes.size() && i < 1024; ++i)
  {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (!(c >= 32 && c < 127) && !LineCursor::isSpace(static_cast<char>(c)))
    {
      return false;
    }
  }
  return true;
}

// `textual`: the file looks like text, so the reader may have meant ASCII.
MeshFileData parseBinary(std::string_view bytes, bool textual)
{
  constexpr std::uint64_t headerBytes = 84;
  constexpr std::uint64_t facetBytes = 50;
  if (bytes.size() < headerBytes)
  {
    throw Error("STL: the file does not start with 'solid', and its " + std::to_string(bytes.size()) +
      " bytes are fewer than a binary STL's 84-byte header");
  }
  const std::uint64_t declared = decodeUnsigned(bytesOf(bytes, 80), 4, false);
  const std::uint64_t whole = (bytes.size() - headerBytes) / facetBytes;
  if (declared > whole)
  {
    throw Error("STL byte 80: " + std::string(textual ? "the file does not start with 'solid', and " : "") +
      "the binary header declares " + std::to_string(declared) + " triangles, but the file's " +
      std::to_string(bytes.size()) + " bytes hold " + std::to_string(whole) + " (84 + 50 bytes per triangle)");
  }
  const bool exactFit = (bytes.size() - headerBytes) % facetBytes == 0;
  const std::uint64_t facets = declared < whole && exactFit ? whole : declared;
  MeshFileData mesh;
  FacetCollector collector(mesh, static_cast<std::size_t>(facets));
  float corners[9];
  for (std::uint64_t f = 0; f < facets; ++f)
  {
    // Skip the normal (12 bytes); read 9 coordinates; skip the 2-byte attribute.
    const unsigned char* facet = bytesOf(bytes, static_cast<std::size_t>(headerBytes + f * facetBytes + 12));
    for (int k = 0; k < 9; ++k)
    {
      corners[k] = decodeFloat(facet + 4 * k, false);
    }
    collector.add(corners);
  }
  return mesh;
}

MeshFileData parseAscii(std::string_view bytes)
{
  enum class Expect
  {
    Solid,
    Facet,
    Loop,
    Vertex,
    EndLoop,
    EndFacet
  };
  LineCursor cursor(bytes, "STL", '\0');
  MeshFileData mesh;
  FacetCollector collector(mesh, bytes.size() / 256);
  Expect expect = Expect::Solid;
  float corners[9];
  int corner = 0;
  int solids = 0;
  while (cursor.next())
  {
    const std::string_view keyword = cursor.word();
    switch (expect)
    {
      case Expect::Solid:
        if (!equalsIgnoringCase(keyword, "solid"))
        {
          cursor.fail("expected 'solid', found " + quoted(keyword));
        }
        expect = Expect::Facet;
        ++solids;
        break;
      case Expect::Facet:
        if (equalsIgnoringCase(keyword, "facet"))
        {
          expect = Expect::Loop;
        }
        else if (equalsIgnoringCase(keyword, "endsolid"))
        {
          expect = Expect::Solid;
        }
        else if (!equalsIgnoringCase(keyword, "color"))
        {
          cursor.fail("expected 'facet' or 'endsolid', found " + quoted(keyword));
        }
        break;
      case Expect::Loop:
        if (!equalsIgnoringCase(keyword, "outer") || !equalsIgnoringCase(cursor.word(), "loop"))
        {
          cursor.fail("expected 'outer loop', found " + quoted(keyword));
        }
        expect = Expect::Vertex;
        corner = 0;
        break;
      case Expect::Vertex:
        if (!equalsIgnoringCase(keyword, "vertex"))
        {
          cursor.fail("expected 'vertex', found " + quoted(keyword));
        }
        for (int k = 0; k < 3; ++k)
        {
          corners[3 * corner + k] = toFloat(cursor.real("vertex coordinate"));
        }
        if (!cursor.atEndOfLine())
        {
          cursor.fail("a vertex has 3 coordinates, found more: " + quoted(cursor.rest()));
        }
        if (++corner == 3)
        {
          expect = Expect::EndLoop;
        }
        break;
      case Expect::EndLoop:
        if (!equalsIgnoringCase(keyword, "endloop"))
        {
          cursor.fail("expected 'endloop' after 3 vertices, found " + quoted(keyword));
        }
        expect = Expect::EndFacet;
        break;
      case Expect::EndFacet:
        if (!equalsIgnoringCase(keyword, "endfacet"))
        {
          cursor.fail("expected 'endfacet', found " + quoted(keyword));
        }
        collector.add(corners);
        expect = Expect::Facet;
        break;
    }
  }
  if (solids == 0)
  {
    throw Error("STL: the file holds only blank lines");
  }
  if (expect != Expect::Facet && expect != Expect::Solid)
  {
    throw Error("STL line " + std::to_string(cursor.line()) + ": the file ends inside a facet");
  }
  return mesh;
}
} // namespace

MeshFileData parseSTL(std::string_view bytes)
{
  if (bytes.empty())
  {
    throw Error("STL: the file is empty");
  }
  if (bytes.size() >= 84)
  {
    const std::uint64_t declared = decodeUnsigned(bytesOf(bytes, 80), 4, false);
    if (declared <= (bytes.size() - 84) / 50 && 84 + 50 * declared == bytes.size())
    {
      return parseBinary(bytes, false);
    }
  }
  if (looksLikeText(bytes))
  {
    return parseAscii(bytes);
  }
  std::size_t text = 0;
  while (text < bytes.size() && text < 84 && bytes[text] >= 9 && bytes[text] < 127)
  {
    ++text;
  }
  return parseBinary(bytes, text == std::min<std::size_t>(bytes.size(), 84));
}

} // namespace kerf
