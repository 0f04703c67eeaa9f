// A streaming walk over a PLY file's header and body, checking sizes and counts only.
#include "IO/PLYValidation.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace kerf
{

namespace
{
struct Property
{
  std::string name;
  int size = 0;      // bytes of a scalar, or of each list entry
  int countSize = 0; // bytes of a list's count (0 for scalars)
  bool countSigned = false;
};

struct Element
{
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

int typeSize(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
  {
    return 1;
  }
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
  {
    return 2;
  }
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
    type == "float32")
  {
    return 4;
  }
  if (type == "double" || type == "float64")
  {
    return 8;
  }
  return 0;
}

bool isSigned(const std::string& type)
{
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
    type == "int32";
}

bool hasProperty(const Element& element, const char* name)
{
  for (const Property& p : element.properties)
  {
    if (p.name == name)
    {
      return true;
    }
  }
  return false;
}

// Reads an unsigned/signed little or big endian integer of `size` bytes.
long long decodeCount(const unsigned char* bytes, int size, bool isSignedType, bool bigEndian)
{
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i)
  {
    const int shift = bigEndian ? 8 * (size - 1 - i) : 8 * i;
    value |= static_cast<std::uint64_t>(bytes[i]) << shift;
  }
  if (isSignedType && size < 8 && (value >> (8 * size - 1)) != 0)
  {
    value |= ~std::uint64_t(0) << (8 * size);
  }
  return static_cast<long long>(value);
}
} // namespace

std::string checkPLYStructure(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    return "cannot open " + fileName;
  }
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply")
  {
    return "the file does not start with 'ply'";
  }
  std::string format;
  std::vector<Element> elements;
  bool ended = false;
  int lines = 1;
  while (std::getline(in, line))
  {
    ++lines;
    if (lines > 100000)
    {
      break;
    }
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
    {
      words >> format;
    }
    else if (keyword == "element")
    {
      Element element;
      if (!(words >> element.name >> element.count) || element.count < 0)
      {
        return "header line " + std::to_string(lines) + ": malformed element";
      }
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        return "header line " + std::to_string(lines) + ": property before any element";
      }
      Property property;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType >> property.name;
        property.countSize = typeSize(countType);
        property.countSigned = isSigned(countType);
        property.size = typeSize(itemType);
        if (property.countSize == 0 || property.size == 0 || property.countSize == 8)
        {
          return "header line " + std::to_string(lines) + ": unknown list type";
        }
      }
      else
      {
        words >> property.name;
        property.size = typeSize(type);
        if (property.size == 0)
        {
          return "header line " + std::to_string(lines) + ": unknown property type '" + type + "'";
        }
      }
      elements.back().properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      ended = true;
      break;
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      return "header line " + std::to_string(lines) + ": unknown keyword '" + keyword.substr(0, 40) + "'";
    }
  }
  if (!ended)
  {
    return "the header has no end_header line";
  }
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
  {
    return "unknown format '" + format + "'";
  }
  const Element* vertices = nullptr;
  const Element* faces = nullptr;
  for (const Element& e : elements)
  {
    vertices = e.name == "vertex" ? &e : vertices;
    faces = e.name == "face" ? &e : faces;
  }
  if (!vertices || !hasProperty(*vertices, "x") || !hasProperty(*vertices, "y") ||
    !hasProperty(*vertices, "z"))
  {
    return "no vertex element with x, y and z";
  }
  if (!faces || !(hasProperty(*faces, "vertex_indices") || hasProperty(*faces, "vertex_index")))
  {
    return "no face element with a vertex_indices list";
  }

  if (format == "ascii")
  {
    for (const Element& element : elements)
    {
      for (long long row = 0; row < element.count; ++row)
      {
        if (!std::getline(in, line))
        {
          return "the file ends after " + std::to_string(row) + " of " +
            std::to_string(element.count) + " " + element.name + " rows";
        }
        std::istringstream words(line);
        for (const Property& p : element.properties)
        {
          double value;
          if (!(words >> value))
          {
            return element.name + " row " + std::to_string(row) + " is incomplete";
          }
          if (p.countSize > 0)
          {
            if (value < 0 || value != static_cast<long long>(value))
            {
              return element.name + " row " + std::to_string(row) + " has an invalid list size";
            }
            for (long long k = 0; k < static_cast<long long>(value); ++k)
            {
              double item;
              if (!(words >> item))
              {
                return element.name + " row " + std::to_string(row) + " is incomplete";
              }
            }
          }
        }
      }
    }
    return "";
  }

  const bool bigEndian = format == "binary_big_endian";
  std::vector<unsigned char> buffer(8);
  for (const Element& element : elements)
  {
    long long fixed = 0;
    bool hasLists = false;
    for (const Property& p : element.properties)
    {
      fixed += p.countSize > 0 ? 0 : p.size;
      hasLists = hasLists || p.countSize > 0;
    }
    if (!hasLists)
    {
      in.seekg(fixed * element.count, std::ios::cur);
      if (!in || in.peek() == EOF)
      {
        // Peek at the last byte of this element instead, so an exactly sized file passes.
        in.clear();
        in.seekg(-1, std::ios::cur);
        if (!in || in.get() == EOF)
        {
          return "the file ends inside the " + element.name + " element";
        }
      }
      continue;
    }
    for (long long row = 0; row < element.count; ++row)
    {
      for (const Property& p : element.properties)
      {
        if (p.countSize == 0)
        {
          in.seekg(p.size, std::ios::cur);
          continue;
        }
        if (!in.read(reinterpret_cast<char*>(buffer.data()), p.countSize))
        {
          return "the file ends inside " + element.name + " row " + std::to_string(row);
        }
        const long long n = decodeCount(buffer.data(), p.countSize, p.countSigned, bigEndian);
        if (n < 0)
        {
          return element.name + " row " + std::to_string(row) + " has a negative list size";
        }
        in.seekg(n * p.size, std::ios::cur);
      }
      if (!in)
      {
        return "the file ends inside " + element.name + " row " + std::to_string(row);
      }
    }
    // Seeking past the end is not an error by itself; confirm the last byte exists.
    in.seekg(-1, std::ios::cur);
    if (!in || in.get() == EOF)
    {
      return "the file ends inside the " + element.name + " element";
    }
  }
  return "";
}

} // namespace kerf
