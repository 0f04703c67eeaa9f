// PLY parsing: the header, then every element row by row into points, faces and their arrays.
#include "IO/PLYFormat.h"

#include "Error.h"
#include "IO/BinaryData.h"
#include "IO/LineCursor.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

namespace kerf
{

namespace
{
enum class ValueType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64,
  Unknown
};

ValueType typeNamed(std::string_view name)
{
  if (name == "char" || name == "int8")
  {
    return ValueType::Int8;
  }
  if (name == "uchar" || name == "uint8")
  {
    return ValueType::UInt8;
  }
  if (name == "short" || name == "int16")
  {
    return ValueType::Int16;
  }
  if (name == "ushort" || name == "uint16")
  {
    return ValueType::UInt16;
  }
  if (name == "int" || name == "int32")
  {
    return ValueType::Int32;
  }
  if (name == "uint" || name == "uint32")
  {
    return ValueType::UInt32;
  }
  if (name == "float" || name == "float32")
  {
    return ValueType::Float32;
  }
  if (name == "double" || name == "float64")
  {
    return ValueType::Float64;
  }
  return ValueType::Unknown;
}

int sizeOf(ValueType type)
{
  switch (type)
  {
    case ValueType::Int8:
    case ValueType::UInt8:
      return 1;
    case ValueType::Int16:
    case ValueType::UInt16:
      return 2;
    case ValueType::Int32:
    case ValueType::UInt32:
    case ValueType::Float32:
      return 4;
    case ValueType::Float64:
      return 8;
    default:
      return 0;
  }
}

bool isInteger(ValueType type)
{
  return type != ValueType::Float32 && type != ValueType::Float64 && type != ValueType::Unknown;
}

// Where the values of a property go.
enum Target
{
  Ignored = -1,
  X,
  Y,
  Z,
  NormalX,
  NormalY,
  NormalZ,
  Red,
  Green,
  Blue,
  Alpha,
  TextureU,
  TextureV,
  Indices,
  Intensity,
  TargetCount
};

struct Property
{
  std::string name;
  bool list = false;
  ValueType countType = ValueType::Unknown;
  ValueType type = ValueType::Unknown; // the scalar's type or the list items' type
  int target = Ignored;
};

struct Element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  int headerLine = 0;

  Property* find(std::string_view propertyName)
  {
    for (Property& p : this->properties)
    {
      if (p.name == propertyName)
      {
        return &p;
      }
    }
    return nullptr;
  }
};

enum class Format
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct Header
{
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t dataOffset = 0;
  int headerLines = 0;
};

[[noreturn]] void failHeader(int line, const std::string& message)
{
  throw Error("PLY header line " + std::to_string(line) + ": " + message);
}

Header parseHeader(std::string_view bytes)
{
  Header header;
  bool ended = false;
  bool haveFormat = false;
  std::size_t position = 0;
  int line = 0;
  while (position < bytes.size() && !ended)
  {
    const std::size_t end = bytes.find('\n', position);
    const std::size_t stop = end == std::string_view::npos ? bytes.size() : end;
    const std::vector<std::string_view> words = splitWords(bytes.substr(position, stop - position));
    position = end == std::string_view::npos ? bytes.size() : end + 1;
    ++line;
    if (line == 1)
    {
      if (words.size() != 1 || words[0] != "ply")
      {
        throw Error("PLY: the file does not start with a line 'ply'");
      }
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info")
    {
      continue;
    }
    const std::string_view keyword = words[0];
    if (keyword == "format")
    {
      if (haveFormat)
      {
        failHeader(line, "a second format line");
      }
      if (words.size() != 3 || words[2] != "1.0")
      {
        failHeader(line, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      }
      if (words[1] == "ascii")
      {
        header.format = Format::Ascii;
      }
      else if (words[1] == "binary_little_endian")
      {
        header.format = Format::BinaryLittleEndian;
      }
      else if (words[1] == "binary_big_endian")
      {
        header.format = Format::BinaryBigEndian;
      }
      else
      {
        failHeader(line, "unknown format " + quoted(words[1]));
      }
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      Element element;
      const char* last = words.size() == 3 ? words[2].data() + words[2].size() : nullptr;
      if (!last || std::from_chars(words[2].data(), last, element.count).ptr != last)
      {
        failHeader(line, "expected 'element <name> <count>' with a count of 0 or more");
      }
      element.name = std::string(words[1]);
      element.headerLine = line;
      for (const Element& other : header.elements)
      {
        if (other.name == element.name)
        {
          failHeader(line, "element " + quoted(element.name) + " is declared twice");
        }
      }
      header.elements.push_back(std::move(element));
    }
    else if (keyword == "property")
    {
      if (header.elements.empty())
      {
        failHeader(line, "a property before any element");
      }
      Property property;
      if (words.size() == 5 && words[1] == "list")
      {
        property.list = true;
        property.countType = typeNamed(words[2]);
        property.type = typeNamed(words[3]);
        property.name = std::string(words[4]);
        if (property.countType == ValueType::Unknown || property.type == ValueType::Unknown)
        {
          failHeader(line, "unknown type in list property " + quoted(property.name));
        }
        if (!isInteger(property.countType))
        {
          failHeader(line, "the count of list property " + quoted(property.name) + " must have an integer type");
        }
      }
      else if (words.size() == 3 && words[1] != "list")
      {
        property.type = typeNamed(words[1]);
        property.name = std::string(words[2]);
        if (property.type == ValueType::Unknown)
        {
          failHeader(line, "unknown property type " + quoted(words[1]));
        }
      }
      else
      {
        failHeader(line, "expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
      }
      Element& element = header.elements.back();
      if (element.find(property.name))
      {
        failHeader(line, "property " + quoted(property.name) + " is declared twice in element " + quoted(element.name));
      }
      element.properties.push_back(std::move(property));
    }
    else if (keyword == "end_header")
    {
      ended = true;
    }
    else
    {
      failHeader(line, "unknown keyword " + quoted(keyword));
    }
  }
  if (!ended)
  {
    throw Error("PLY: the header has no end_header line");
  }
  if (!haveFormat)
  {
    throw Error("PLY: the header has no format line");
  }
  header.dataOffset = position;
  header.headerLines = line;
  return header;
}

Element* findElement(Header& header, std::string_view name)
{
  for (Element& e : header.elements)
  {
    if (e.name == name)
    {
      return &e;
    }
  }
  return nullptr;
}

// Gives each property of the vertex and face elements its target; false if a group (say nx, ny,
// nz) is incomplete, so that none of it is read.
bool assign(Element& element, std::initializer_list<const char*> names, int firstTarget)
{
  std::vector<Property*> found;
  for (const char* name : names)
  {
    Property* p = element.find(name);
    if (!p || p->list)
    {
      return false;
    }
    found.push_back(p);
  }
  for (std::size_t i = 0; i < found.size(); ++i)
  {
    found[i]->target = firstTarget + static_cast<int>(i);
  }
  return true;
}

// Reads values of the data section, binary or ASCII, keeping the position for error messages.
class RowReader
{
public:
  RowReader(std::string_view bytes, const Header& header)
    : Bytes(bytes)
    , Position(header.dataOffset)
    , BigEndian(header.format == Format::BinaryBigEndian)
    , Ascii(header.format == Format::Ascii)
    , Lines(bytes, "PLY", '\0')
  {
    if (this->Ascii)
    {
      this->Lines.jump(header.dataOffset, header.headerLines);
    }
  }

  bool ascii() const { return this->Ascii; }
  std::size_t remaining() const { return this->Bytes.size() - (this->Ascii ? this->Lines.offset() : this->Position); }

  // "PLY byte 1234" or "PLY line 12": where the current row starts.
  std::string where() const
  {
    return this->Ascii ? "PLY line " + std::to_string(this->Lines.line())
                       : "PLY byte " + std::to_string(this->RowStart);
  }

  // Starts row `row` of `element`.
  void beginRow(const Element& element, std::uint64_t row)
  {
    this->ElementName = &element.name;
    this->Row = row;
    if (!this->Ascii)
    {
      this->RowStart = this->Position;
      return;
    }
    if (!this->Lines.next())
    {
      throw Error("PLY: the file ends after " + std::to_string(row) + " of " + std::to_string(element.count) + " " +
        element.name + " rows");
    }
  }

  void endRow(std::size_t properties)
  {
    if (this->Ascii && !this->Lines.atEndOfLine())
    {
      this->fail("has more values than its " + std::to_string(properties) + " properties");
    }
  }

  double real(ValueType type)
  {
    if (this->Ascii)
    {
      const std::string_view word = this->Lines.word();
      double value = 0.0;
      if (word.empty())
      {
        this->fail("is incomplete");
      }
      if (isInteger(type) ? !this->asciiInteger(word, value) : !LineCursor::parseReal(word, value))
      {
        this->fail("holds " + quoted(word) + ", not a number of its property's type");
      }
      return value;
    }
    const int size = sizeOf(type);
    if (this->Bytes.size() - this->Position < static_cast<std::size_t>(size))
    {
      throw Error("PLY byte " + std::to_string(this->Position) + ": the file ends inside " + *this->ElementName +
        " row " + std::to_string(this->Row));
    }
    const unsigned char* b = bytesOf(this->Bytes, this->Position);
    this->Position += static_cast<std::size_t>(size);
    switch (type)
    {
      case ValueType::Int8:
      case ValueType::Int16:
      case ValueType::Int32:
        return static_cast<double>(decodeSigned(b, size, this->BigEndian));
      case ValueType::UInt8:
      case ValueType::UInt16:
      case ValueType::UInt32:
        return static_cast<double>(decodeUnsigned(b, size, this->BigEndian));
      case ValueType::Float32:
        return decodeFloat(b, this->BigEndian);
      default:
        return decodeDouble(b, this->BigEndian);
    }
  }

  // A list's length, checked against what the rest of the file can hold.
  std::uint64_t listLength(const Property& p)
  {
    const double value = this->real(p.countType);
    if (value < 0)
    {
      this->fail("has a negative list length for " + quoted(p.name));
    }
    const auto length = static_cast<std::uint64_t>(value);
    const std::uint64_t itemBytes = this->Ascii ? 2 : static_cast<std::uint64_t>(sizeOf(p.type));
    if (!fitsIn(length, itemBytes, this->remaining() + 1))
    {
      this->fail("declares a list of " + std::to_string(length) + " items for " + quoted(p.name) +
        ", more than the rest of the file holds");
    }
    return length;
  }

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Error(this->where() + ": " + *this->ElementName + " row " + std::to_string(this->Row) + " " + message);
  }

private:
  static bool asciiInteger(std::string_view word, double& value)
  {
    long long integer = 0;
    if (!LineCursor::parseInteger(word, integer))
    {
      return false;
    }
    value = static_cast<double>(integer);
    return true;
  }

  std::string_view Bytes;
  std::size_t Position;
  std::size_t RowStart = 0;
  bool BigEndian;
  bool Ascii;
  LineCursor Lines;
  const std::string* ElementName = nullptr;
  std::uint64_t Row = 0;
};

// The fewest bytes a row of the element can take: fixed sizes in binary, one character and one
// separator per value in ASCII.
std::uint64_t smallestRow(const Element& element, bool ascii)
{
  std::uint64_t bytes = 0;
  for (const Property& p : element.properties)
  {
    bytes += ascii ? 2 : static_cast<std::uint64_t>(sizeOf(p.list ? p.countType : p.type));
  }
  return bytes;
}

MeshFileArray makeArray(const char* name, MeshFileArray::Role role, int components)
{
  MeshFileArray array;
  array.name = name;
  array.role = role;
  array.components = components;
  return array;
}
} // namespace

MeshFileData parsePLY(std::string_view bytes)
{
  Header header = parseHeader(bytes);
  Element* vertex = findElement(header, "vertex");
  if (!vertex || !vertex->find("x") || !vertex->find("y") || !vertex->find("z"))
  {
    throw Error("PLY: no vertex element with x, y and z");
  }
  for (const char* axis : { "x", "y", "z" })
  {
    if (vertex->find(axis)->list)
    {
      failHeader(vertex->headerLine,
        std::string("property '") + axis + "' of the vertex element is a list; it must be a scalar");
    }
  }
  Element* face = findElement(header, "face");
  Property* indices = face ? face->find("vertex_indices") : nullptr;
  indices = indices ? indices : (face ? face->find("vertex_index") : nullptr);
  if (!indices)
  {
    throw Error("PLY: no face element with a vertex_indices list");
  }
  if (!indices->list)
  {
    failHeader(face->headerLine, "'" + indices->name + "' of the face element is a scalar; it must be a list");
  }
  if (!isInteger(indices->type))
  {
    failHeader(face->headerLine, "'" + indices->name + "' of the face element must have an integer type");
  }

  assign(*vertex, { "x", "y", "z" }, X);
  const bool normals = assign(*vertex, { "nx", "ny", "nz" }, NormalX);
  const bool colors = assign(*vertex, { "red", "green", "blue" }, Red) ||
    assign(*vertex, { "diffuse_red", "diffuse_green", "diffuse_blue" }, Red);
  const bool alpha = colors && assign(*vertex, { "alpha" }, Alpha);
  const bool textures =
    assign(*vertex, { "u", "v" }, TextureU) || assign(*vertex, { "texture_u", "texture_v" }, TextureU);
  indices->target = Indices;
  const bool faceColors = assign(*face, { "red", "green", "blue" }, Red);
  const bool faceAlpha = faceColors && assign(*face, { "alpha" }, Alpha);
  const bool intensity = assign(*face, { "intensity" }, Intensity);

  MeshFileData mesh;
  mesh.singlePrecision = true;
  for (const char* axis : { "x", "y", "z" })
  {
    mesh.singlePrecision = mesh.singlePrecision && vertex->find(axis)->type != ValueType::Float64 &&
      vertex->find(axis)->type != ValueType::Int32 && vertex->find(axis)->type != ValueType::UInt32;
  }
  const std::uint64_t vertexCount = vertex->count;
  RowReader reader(bytes, header);

  std::vector<double> values(TargetCount, 0.0);
  std::vector<MeshFileArray> pointArrays;
  std::vector<MeshFileArray> faceArrays;
  for (Element& element : header.elements)
  {
    const std::uint64_t rowBytes = smallestRow(element, reader.ascii());
    if (element.count > 0 && element.properties.empty())
    {
      failHeader(element.headerLine,
        "element " + quoted(element.name) + " has " + std::to_string(element.count) + " rows but no properties");
    }
    // Binary rows have a known smallest size, checked up front; ASCII rows are read until the
    // text runs out, which names the row and line. Either way allocations follow the file's size.
    const std::uint64_t possibleRows =
      rowBytes == 0 ? element.count : (reader.remaining() + (reader.ascii() ? 1 : 0)) / rowBytes;
    if (!reader.ascii() && element.count > possibleRows)
    {
      throw Error("PLY: the file ends inside the " + element.name + " element: " + std::to_string(element.count) +
        " rows need at least " +
        (rowBytes > 0 && element.count > UINT64_MAX / rowBytes ? std::string("2^64")
                                                               : std::to_string(element.count * rowBytes)) +
        " bytes, " + std::to_string(reader.remaining()) + " remain");
    }
    const bool isVertex = &element == vertex;
    const bool isFace = &element == face;
    const auto rows = static_cast<std::size_t>(std::min(element.count, possibleRows));
    if (isVertex)
    {
      mesh.points.reserve(3 * rows);
      if (normals)
      {
        pointArrays.push_back(makeArray("Normals", MeshFileArray::Role::Normals, 3));
      }
      if (colors)
      {
        pointArrays.push_back(makeArray(alpha ? "RGBA" : "RGB", MeshFileArray::Role::Colors, alpha ? 4 : 3));
      }
      if (textures)
      {
        pointArrays.push_back(makeArray("TCoords", MeshFileArray::Role::TextureCoordinates, 2));
      }
      for (MeshFileArray& a : pointArrays)
      {
        a.values.reserve(rows * static_cast<std::size_t>(a.components));
      }
    }
    if (isFace)
    {
      mesh.polygons.offsets.reserve(rows + 1);
      mesh.polygons.indices.reserve(std::min<std::size_t>(3 * rows, reader.remaining() / 2));
      if (faceColors)
      {
        faceArrays.push_back(makeArray(faceAlpha ? "RGBA" : "RGB", MeshFileArray::Role::Colors, faceAlpha ? 4 : 3));
      }
      if (intensity)
      {
        faceArrays.push_back(makeArray("intensity", MeshFileArray::Role::Colors, 1));
      }
    }
    for (std::uint64_t row = 0; row < element.count; ++row)
    {
      reader.beginRow(element, row);
      for (const Property& p : element.properties)
      {
        if (!p.list)
        {
          const double value = reader.real(p.type);
          if (p.target != Ignored && (isVertex || isFace))
          {
            values[static_cast<std::size_t>(p.target)] = value;
          }
          continue;
        }
        const std::uint64_t length = reader.listLength(p);
        const bool keep = isFace && p.target == Indices;
        if (keep && length < 3)
        {
          reader.fail("has " + std::to_string(length) + " corners; a face needs at least 3");
        }
        for (std::uint64_t k = 0; k < length; ++k)
        {
          const double index = reader.real(p.type);
          if (keep)
          {
            if (index < 0 || index >= static_cast<double>(vertexCount))
            {
              reader.fail("uses vertex " + std::to_string(static_cast<long long>(index)) + ", but the file has " +
                std::to_string(vertexCount) + " vertices");
            }
            mesh.polygons.indices.push_back(static_cast<std::int64_t>(index));
          }
        }
        if (keep)
        {
          mesh.polygons.close();
        }
      }
      reader.endRow(element.properties.size());
      if (isVertex)
      {
        mesh.points.insert(mesh.points.end(), { values[X], values[Y], values[Z] });
        std::size_t a = 0;
        if (normals)
        {
          std::vector<double>& n = pointArrays[a++].values;
          n.insert(n.end(), { values[NormalX], values[NormalY], values[NormalZ] });
        }
        if (colors)
        {
          std::vector<double>& c = pointArrays[a++].values;
          c.insert(c.end(), { values[Red], values[Green], values[Blue] });
          if (alpha)
          {
            c.push_back(values[Alpha]);
          }
        }
        if (textures)
        {
          std::vector<double>& t = pointArrays[a].values;
          t.insert(t.end(), { values[TextureU], values[TextureV] });
        }
      }
      else if (isFace)
      {
        std::size_t a = 0;
        if (faceColors)
        {
          std::vector<double>& c = faceArrays[a++].values;
          c.insert(c.end(), { values[Red], values[Green], values[Blue] });
          if (faceAlpha)
          {
            c.push_back(values[Alpha]);
          }
        }
        if (intensity)
        {
          faceArrays[a].values.push_back(values[Intensity]);
        }
      }
    }
  }
  mesh.pointArrays = std::move(pointArrays);
  mesh.polygonArrays = std::move(faceArrays);
  return mesh;
}

} // namespace kerf
