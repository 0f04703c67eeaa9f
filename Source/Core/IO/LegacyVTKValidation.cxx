// Legacy VTK validation: a token walk that mirrors vtkDataReader and vtkPolyDataReader (VTK 9.2).
#include "IO/LegacyVTKValidation.h"

#include "Error.h"
#include "IO/BinaryData.h"
#include "IO/LineCursor.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace kerf
{

namespace
{
// How VTK's ReadArray stores a type name (it compares prefixes, in this order).
enum class Kind
{
  Bit,
  SignedInteger,
  UnsignedInteger,
  Float,
  Double,
  String,
  Unsupported
};

struct ArrayType
{
  Kind kind = Kind::Unsupported;
  int size = 0; // bytes per value in binary files
};

bool startsWith(std::string_view text, std::string_view prefix)
{
  return text.substr(0, prefix.size()) == prefix;
}

std::string lowered(std::string_view text)
{
  std::string out(text);
  for (char& c : out)
  {
    c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return out;
}

ArrayType arrayType(std::string_view name)
{
  const std::string t = lowered(name);
  if (startsWith(t, "bit"))
  {
    return { Kind::Bit, 0 };
  }
  if (t == "char" || t == "signed_char")
  {
    return { Kind::SignedInteger, 1 };
  }
  if (startsWith(t, "unsigned_char"))
  {
    return { Kind::UnsignedInteger, 1 };
  }
  if (startsWith(t, "short"))
  {
    return { Kind::SignedInteger, 2 };
  }
  if (startsWith(t, "unsigned_short"))
  {
    return { Kind::UnsignedInteger, 2 };
  }
  if (startsWith(t, "vtkidtype") || startsWith(t, "int"))
  {
    return { Kind::SignedInteger, 4 };
  }
  if (startsWith(t, "unsigned_int"))
  {
    return { Kind::UnsignedInteger, 4 };
  }
  if (startsWith(t, "long"))
  {
    return { Kind::SignedInteger, static_cast<int>(sizeof(long)) };
  }
  if (startsWith(t, "unsigned_long"))
  {
    return { Kind::UnsignedInteger, static_cast<int>(sizeof(long)) };
  }
  if (startsWith(t, "vtktypeint64"))
  {
    return { Kind::SignedInteger, 8 };
  }
  if (startsWith(t, "vtktypeuint64"))
  {
    return { Kind::UnsignedInteger, 8 };
  }
  if (startsWith(t, "float"))
  {
    return { Kind::Float, 4 };
  }
  if (startsWith(t, "double"))
  {
    return { Kind::Double, 8 };
  }
  if (startsWith(t, "string") || startsWith(t, "utf8_string"))
  {
    return { Kind::String, 0 };
  }
  return { Kind::Unsupported, 0 };
}

bool isHexDigit(char c)
{
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

// VTK's DecodeString reads two characters after every '%', past the end of the name if need be.
bool escapesAreComplete(std::string_view name)
{
  for (std::size_t i = 0; i < name.size(); ++i)
  {
    if (name[i] == '%')
    {
      if (i + 2 >= name.size() || !isHexDigit(name[i + 1]) || !isHexDigit(name[i + 2]))
      {
        return false;
      }
      i += 2;
    }
  }
  return true;
}

class LegacyWalker
{
public:
  explicit LegacyWalker(std::string_view bytes)
    : Bytes(bytes)
  {
  }

  void walk()
  {
    this->header();
    const std::string dataset = lowered(this->word("DATASET"));
    if (!startsWith(dataset, "dataset"))
    {
      this->fail("expected DATASET POLYDATA, found " + quoted(dataset));
    }
    const std::string type = lowered(this->word("the dataset type"));
    if (!startsWith(type, "polydata"))
    {
      this->fail("Kerf reads POLYDATA legacy files only, this one holds " + quoted(type));
    }
    while (this->skipToWord())
    {
      const std::string keyword = lowered(this->word("a section keyword"));
      if (startsWith(keyword, "field"))
      {
        this->fieldData();
      }
      else if (startsWith(keyword, "points"))
      {
        this->Points = this->count("the number of points");
        this->array(this->word("the points' type"), this->Points, 3, "POINTS");
      }
      else if (startsWith(keyword, "vertices") || startsWith(keyword, "lines") || startsWith(keyword, "polygons") ||
        startsWith(keyword, "triangle_strips"))
      {
        this->cells(keyword);
      }
      else if (startsWith(keyword, "cell_data") || startsWith(keyword, "point_data"))
      {
        this->attributes(keyword);
        return;
      }
      else
      {
        this->fail("unknown section keyword " + quoted(keyword));
      }
    }
  }

private:
  // ---- the stream ----------------------------------------------------------------------------

  [[noreturn]] void fail(const std::string& message) const
  {
    const std::size_t at = std::min(this->Position, this->Bytes.size());
    const auto line = 1 + std::count(this->Bytes.begin(), this->Bytes.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    throw Error("legacy VTK line " + std::to_string(line) + " (byte " + std::to_string(at) + "): " + message);
  }

  std::size_t remaining() const { return this->Bytes.size() - this->Position; }

  // Skips blanks; false at the end of the file.
  bool skipToWord()
  {
    while (this->Position < this->Bytes.size() && LineCursor::isSpace(this->Bytes[this->Position]))
    {
      ++this->Position;
    }
    return this->Position < this->Bytes.size();
  }

  // The next whitespace-separated word; VTK's ReadString keeps at most 255 characters.
  std::string_view word(const char* what)
  {
    if (!this->skipToWord())
    {
      this->fail(std::string("the file ends where ") + what + " should be");
    }
    const std::size_t start = this->Position;
    while (this->Position < this->Bytes.size() && !LineCursor::isSpace(this->Bytes[this->Position]))
    {
      ++this->Position;
    }
    if (this->Position - start > 255)
    {
      this->Position = start;
      this->fail(std::string("a word longer than 255 characters where ") + what + " should be");
    }
    return this->Bytes.substr(start, this->Position - start);
  }

  // A line as VTK's ReadLine gives it (without '\n' or a final '\r'); false at the end of the file.
  bool line(std::string_view& text)
  {
    if (this->Position >= this->Bytes.size())
    {
      return false;
    }
    const std::size_t end = this->Bytes.find('\n', this->Position);
    const std::size_t stop = end == std::string_view::npos ? this->Bytes.size() : end;
    text = this->Bytes.substr(this->Position, stop - this->Position);
    this->Position = end == std::string_view::npos ? this->Bytes.size() : end + 1;
    if (!text.empty() && text.back() == '\r')
    {
      text.remove_suffix(1);
    }
    return true;
  }

  std::uint64_t count(const char* what)
  {
    const std::string_view text = this->word(what);
    long long value = 0;
    if (!LineCursor::parseInteger(text, value) || value < 0)
    {
      this->fail(std::string("expected ") + what + " (an integer of 0 or more), found " + quoted(text));
    }
    return static_cast<std::uint64_t>(value);
  }

  std::string_view name(const char* what)
  {
    const std::string_view text = this->word(what);
    if (!escapesAreComplete(text))
    {
      this->fail(std::string("an incomplete %XX escape in ") + what + " " + quoted(text));
    }
    return text;
  }

  // Binary data starts after the rest of the header line, which VTK reads with getline(256).
  void startBinaryData(const char* what)
  {
    const std::size_t end = this->Bytes.find('\n', this->Position);
    if (end == std::string_view::npos || end - this->Position > 254)
    {
      this->fail(std::string("no line break before the binary data of ") + what);
    }
    this->Position = end + 1;
  }

  void requireBytes(std::uint64_t count, std::uint64_t size, const char* what)
  {
    if (!fitsIn(count, size, this->remaining()))
    {
      this->fail(std::string(what) + " declares " + std::to_string(count) + " values of " + std::to_string(size) +
        " bytes, but " + std::to_string(this->remaining()) + " bytes remain");
    }
  }

  // ---- arrays --------------------------------------------------------------------------------

  // One ASCII value of `kind`, checked the way istream >> would read it; its integer value.
  std::int64_t asciiValue(const ArrayType& type, const char* what)
  {
    const std::string_view text = this->word(what);
    if (type.kind == Kind::Float || type.kind == Kind::Double)
    {
      double value = 0.0;
      const double largest =
        type.kind == Kind::Float ? std::numeric_limits<float>::max() : std::numeric_limits<double>::max();
      const bool letters = text.find_first_of("nNiIxX") != std::string_view::npos;
      if (letters || !LineCursor::parseReal(text, value) || !(std::fabs(value) <= largest))
      {
        this->fail(std::string(what) + " holds " + quoted(text) + ", not a finite number VTK's legacy reader can read");
      }
      return 0;
    }
    long long value = 0;
    const bool isUnsigned = type.kind == Kind::UnsignedInteger;
    // VTK reads char types through an int, bits through a 64-bit id.
    const int bits = type.kind == Kind::Bit ? 64 : (type.size == 1 ? 32 : 8 * type.size);
    const long double low = isUnsigned ? 0.0L : -std::ldexp(1.0L, bits - 1);
    const long double high = std::ldexp(1.0L, isUnsigned ? bits : bits - 1) - 1.0L;
    if (!LineCursor::parseInteger(text, value) || static_cast<long double>(value) < low ||
      static_cast<long double>(value) > high)
    {
      this->fail(std::string(what) + " holds " + quoted(text) + ", not an integer of its type");
    }
    return value;
  }

  std::int64_t binaryValue(const ArrayType& type)
  {
    const unsigned char* b = bytesOf(this->Bytes, this->Position);
    this->Position += static_cast<std::size_t>(type.size);
    if (type.kind != Kind::UnsignedInteger)
    {
      return decodeSigned(b, type.size, true);
    }
    // Values past the signed range only need to compare as too large.
    const std::uint64_t value = decodeUnsigned(b, type.size, true);
    return value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
      ? std::numeric_limits<std::int64_t>::max()
      : static_cast<std::int64_t>(value);
  }

  // Checks an array as ReadArray reads it; calls `each` with the integer value of every entry of
  // an integer array when given (the cell sections need them).
  template <typename Each>
  void array(std::string_view typeName, std::uint64_t tuples, std::uint64_t components, const char* what, Each each)
  {
    const ArrayType type = arrayType(typeName);
    if (type.kind == Kind::Unsupported)
    {
      this->fail(std::string(what) + " has an unsupported data type " + quoted(typeName));
    }
    if (components > 0 && tuples > std::numeric_limits<std::uint64_t>::max() / components)
    {
      this->fail(std::string(what) + " declares more values than 2^64");
    }
    const std::uint64_t values = tuples * components;
    const bool integers =
      type.kind == Kind::SignedInteger || type.kind == Kind::UnsignedInteger || type.kind == Kind::Bit;
    if (type.kind == Kind::String)
    {
      this->strings(values, what);
    }
    else if (!this->Binary)
    {
      // An ASCII value takes at least a character and a separator.
      this->requireBytes(values, 2, what);
      for (std::uint64_t i = 0; i < values; ++i)
      {
        const std::int64_t v = this->asciiValue(type, what);
        if (integers)
        {
          each(v);
        }
      }
    }
    else if (values > 0)
    {
      this->startBinaryData(what);
      if (type.kind == Kind::Bit)
      {
        this->requireBytes((values + 7) / 8, 1, what);
        this->Position += static_cast<std::size_t>((values + 7) / 8);
      }
      else
      {
        this->requireBytes(values, static_cast<std::uint64_t>(type.size), what);
        if (!integers || std::is_same_v<Each, SkipValues>)
        {
          this->Position += static_cast<std::size_t>(values * static_cast<std::uint64_t>(type.size));
        }
        else
        {
          for (std::uint64_t i = 0; i < values; ++i)
          {
            each(this->binaryValue(type));
          }
        }
      }
    }
    this->metadata(components);
  }

  // For arrays whose values only need to be there (and parse, in ASCII).
  struct SkipValues
  {
    void operator()(std::int64_t) const {}
  };

  void array(std::string_view typeName, std::uint64_t tuples, std::uint64_t components, const char* what)
  {
    this->array(typeName, tuples, components, what, SkipValues());
  }

  void strings(std::uint64_t values, const char* what)
  {
    // Every string takes at least one byte (its length header, or its line's newline).
    this->requireBytes(values, 1, what);
    if (this->Binary)
    {
      this->startBinaryData(what);
      for (std::uint64_t i = 0; i < values; ++i)
      {
        if (this->remaining() == 0)
        {
          this->fail(std::string("the file ends inside the strings of ") + what);
        }
        const unsigned char first = *bytesOf(this->Bytes, this->Position);
        const int headerBytes = (first >> 6) == 3 ? 1 : ((first >> 6) == 2 ? 2 : ((first >> 6) == 1 ? 4 : 8));
        this->requireBytes(static_cast<std::uint64_t>(headerBytes), 1, what);
        std::uint64_t length = decodeUnsigned(bytesOf(this->Bytes, this->Position), headerBytes, true);
        if (headerBytes < 8)
        {
          length &= (std::uint64_t(1) << (8 * headerBytes - 2)) - 1;
        }
        this->Position += static_cast<std::size_t>(headerBytes);
        this->requireBytes(length, 1, what);
        this->Position += static_cast<std::size_t>(length);
      }
      return;
    }
    std::string_view text;
    this->line(text); // the rest of the header line
    for (std::uint64_t i = 0; i < values && this->line(text); ++i)
    {
      if (!escapesAreComplete(text))
      {
        this->fail(std::string("an incomplete %XX escape in a string of ") + what);
      }
    }
  }

  // After each array VTK skips blank lines and reads an optional METADATA block up to a blank
  // line; a run of 256 blanks without a line break makes it loop for ever.
  void metadata(std::uint64_t components)
  {
    while (true)
    {
      std::size_t i = this->Position;
      while (i < this->Bytes.size() && i - this->Position < 256 && (this->Bytes[i] == ' ' || this->Bytes[i] == '\r'))
      {
        ++i;
      }
      if (i - this->Position == 256)
      {
        this->fail("256 blanks without a line break after an array (VTK's reader would not return)");
      }
      if (i < this->Bytes.size() && this->Bytes[i] == '\n')
      {
        this->Position = i + 1;
        continue;
      }
      break;
    }
    if (this->remaining() < 8 || lowered(this->Bytes.substr(this->Position, 8)) != "metadata")
    {
      return;
    }
    std::string_view text;
    this->line(text);
    while (this->line(text))
    {
      const std::string lower = lowered(text);
      if (lower.empty())
      {
        return;
      }
      if (startsWith(lower, "component_names"))
      {
        for (std::uint64_t c = 0; c < components && this->line(text); ++c)
        {
          if (!escapesAreComplete(text))
          {
            this->fail("an incomplete %XX escape in a component name");
          }
        }
      }
      else if (startsWith(lower, "information"))
      {
        long long keys = -1;
        const std::string_view number = std::string_view(lower).substr(11);
        const std::size_t first = number.find_first_not_of(" \t");
        if (first == std::string_view::npos ||
          !LineCursor::parseInteger(number.substr(first, number.find_last_not_of(" \t") - first + 1), keys) ||
          keys < 0 || keys > 16)
        {
          this->fail("an INFORMATION line without a key count from 0 to 16: " + quoted(text));
        }
        for (long long k = 0; k < keys; ++k)
        {
          this->informationKey();
        }
      }
    }
  }

  // One key of an INFORMATION block. VTK's reader goes astray (and can loop for ever once its
  // stream fails) on keys whose values do not parse as their type, so only the range keys VTK
  // writes itself are accepted: "NAME <range key> LOCATION vtkDataArray" then "DATA n v1 .. vn".
  void informationKey()
  {
    std::string_view text;
    do
    {
      if (!this->line(text))
      {
        this->fail("the file ends inside an INFORMATION block");
      }
    } while (text.empty());
    const std::vector<std::string_view> key = splitWords(text);
    const bool known = key.size() == 4 && key[0] == "NAME" && key[2] == "LOCATION" && key[3] == "vtkDataArray" &&
      (key[1] == "L2_NORM_RANGE" || key[1] == "COMPONENT_RANGE" || key[1] == "L2_NORM_FINITE_RANGE" ||
        key[1] == "COMPONENT_FINITE_RANGE");
    if (!known)
    {
      this->fail("unsupported array information " + quoted(text) + " (Kerf accepts the range keys VTK writes)");
    }
    if (!this->line(text))
    {
      this->fail("the file ends inside an INFORMATION block");
    }
    const std::vector<std::string_view> data = splitWords(text);
    long long length = -1;
    bool numbers = data.size() >= 2 && data[0] == "DATA" && LineCursor::parseInteger(data[1], length) && length >= 0 &&
      length <= 64 && data.size() == static_cast<std::size_t>(length) + 2;
    for (std::size_t i = 2; numbers && i < data.size(); ++i)
    {
      double value = 0.0;
      numbers = data[i].find_first_of("nNiIxX") == std::string_view::npos && LineCursor::parseReal(data[i], value) &&
        std::fabs(value) <= std::numeric_limits<double>::max();
    }
    if (!numbers)
    {
      this->fail("expected 'DATA n v1 .. vn' with n finite numbers, found " + quoted(text));
    }
  }

  // ---- sections ------------------------------------------------------------------------------

  void header()
  {
    std::string_view text;
    if (!this->line(text) || !startsWith(text.substr(0, 255), "# vtk DataFile Version"))
    {
      this->Position = 0;
      this->fail("the file does not start with '# vtk DataFile Version'");
    }
    // sscanf("%d.%d") after the prefix; without two numbers VTK assumes version 0.0.
    // VTK's ReadLine keeps 255 characters.
    std::string_view version = text.substr(0, 255).substr(22);
    auto number = [&version](long long& value) {
      const std::size_t first = version.find_first_not_of(" \t\r\v\f");
      version = first == std::string_view::npos ? std::string_view() : version.substr(first);
      std::size_t digits = version.size() > 0 && (version[0] == '-' || version[0] == '+') ? 1 : 0;
      const std::size_t start = digits;
      while (digits < version.size() && version[digits] >= '0' && version[digits] <= '9')
      {
        ++digits;
      }
      if (digits == start || digits - start > 9 || !LineCursor::parseInteger(version.substr(0, digits), value))
      {
        return false;
      }
      version = version.substr(digits);
      return true;
    };
    long long major = 0;
    long long minor = 0;
    if (number(major) && !version.empty() && version[0] == '.' && (version = version.substr(1), number(minor)))
    {
      this->Major = major;
    }
    if (!this->line(text))
    {
      this->fail("the file ends before its title line");
    }
    const std::string type = lowered(this->word("ASCII or BINARY"));
    if (startsWith(type, "ascii"))
    {
      this->Binary = false;
    }
    else if (startsWith(type, "binary"))
    {
      this->Binary = true;
    }
    else
    {
      this->fail("expected ASCII or BINARY, found " + quoted(type));
    }
  }

  void fieldData()
  {
    this->name("the field's name");
    const std::uint64_t arrays = this->count("the number of field arrays");
    // Each array takes at least "a 1 1 int\n" (10 bytes).
    this->requireBytes(arrays, 10, "FIELD");
    for (std::uint64_t i = 0; i < arrays; ++i)
    {
      const std::string_view arrayName = this->name("a field array's name");
      if (arrayName == "NULL_ARRAY")
      {
        continue;
      }
      const std::uint64_t components = this->count("a field array's number of components");
      const std::uint64_t tuples = this->count("a field array's number of tuples");
      this->array(this->word("a field array's type"), tuples, components, "a FIELD array");
    }
  }

  void cells(const std::string& keyword)
  {
    const char* what = keyword.c_str();
    if (this->Major >= 5)
    {
      const std::uint64_t offsetCount = this->count("the number of cell offsets");
      const std::uint64_t connectivityCount = this->count("the connectivity size");
      if (offsetCount < 1)
      {
        return;
      }
      if (lowered(this->word("OFFSETS")) != "offsets")
      {
        this->fail("expected OFFSETS in the " + keyword + " section");
      }
      const std::string_view offsetType = this->word("the offsets' type");
      this->requireIntegers(offsetType, "cell offsets");
      std::uint64_t index = 0;
      std::int64_t previous = 0;
      this->array(offsetType, offsetCount, 1, "OFFSETS", [&](std::int64_t offset) {
        if ((index == 0 && offset != 0) || offset < previous || static_cast<std::uint64_t>(offset) > connectivityCount)
        {
          this->fail("cell offset " + std::to_string(index) + " is " + std::to_string(offset) +
            (index == 0 ? "; offsets start at 0"
                        : "; offsets never decrease and stay within the connectivity size " +
                  std::to_string(connectivityCount)));
        }
        if (index + 1 == offsetCount && static_cast<std::uint64_t>(offset) != connectivityCount)
        {
          this->fail("the last cell offset is " + std::to_string(offset) + ", not the connectivity size " +
            std::to_string(connectivityCount));
        }
        previous = offset;
        ++index;
      });
      if (lowered(this->word("CONNECTIVITY")) != "connectivity")
      {
        this->fail("expected CONNECTIVITY in the " + keyword + " section");
      }
      const std::string_view connectivityType = this->word("the connectivity's type");
      this->requireIntegers(connectivityType, "cell connectivity");
      this->array(connectivityType, connectivityCount, 1, "CONNECTIVITY");
      this->Cells += offsetCount - 1;
      return;
    }
    // 4.x: "n size" then size integers, each cell its point count followed by its points.
    const std::uint64_t declaredCells = this->count("the number of cells");
    const std::uint64_t size = this->count("the cell list size");
    std::uint64_t cellCount = 0;
    std::uint64_t left = 0; // indices still to come in the current cell
    std::uint64_t read = 0;
    auto walkCell = [&](std::int64_t value) {
      ++read;
      if (left > 0)
      {
        --left;
        return;
      }
      if (value < 0 || static_cast<std::uint64_t>(value) > size - read)
      {
        this->fail("cell " + std::to_string(cellCount) + " of " + keyword + " claims " + std::to_string(value) +
          " points, but " + std::to_string(size - read) + " values remain in its section");
      }
      left = static_cast<std::uint64_t>(value);
      ++cellCount;
    };
    if (!this->Binary)
    {
      this->requireBytes(size, 2, what);
      const ArrayType type{ Kind::SignedInteger, 4 };
      for (std::uint64_t i = 0; i < size; ++i)
      {
        walkCell(this->asciiValue(type, what));
      }
    }
    else
    {
      this->startBinaryData(what);
      this->requireBytes(size, 4, what);
      const ArrayType type{ Kind::SignedInteger, 4 };
      for (std::uint64_t i = 0; i < size; ++i)
      {
        walkCell(this->binaryValue(type));
      }
    }
    if (cellCount != declaredCells)
    {
      this->fail("the " + keyword + " section declares " + std::to_string(declaredCells) + " cells but holds " +
        std::to_string(cellCount));
    }
    this->Cells += cellCount;
  }

  void requireIntegers(std::string_view typeName, const char* what)
  {
    const Kind kind = arrayType(typeName).kind;
    if (kind != Kind::SignedInteger && kind != Kind::UnsignedInteger)
    {
      this->fail(std::string(what) + " must have an integer type, found " + quoted(typeName));
    }
  }

  // POINT_DATA / CELL_DATA and their attributes, to the end of the file.
  void attributes(std::string keyword)
  {
    while (true)
    {
      const bool pointData = startsWith(keyword, "point_data");
      const std::uint64_t declared =
        this->count(pointData ? "the number of point values" : "the number of cell values");
      const std::uint64_t expected = pointData ? this->Points : this->Cells;
      if (declared != expected)
      {
        this->fail(std::string(pointData ? "POINT_DATA" : "CELL_DATA") + " declares " + std::to_string(declared) +
          " values for " + std::to_string(expected) + (pointData ? " points" : " cells"));
      }
      keyword.clear();
      while (this->skipToWord())
      {
        const std::string section = lowered(this->word("an attribute keyword"));
        if (startsWith(section, "cell_data") || startsWith(section, "point_data"))
        {
          keyword = section;
          break;
        }
        this->attribute(section, declared);
      }
      if (keyword.empty())
      {
        return;
      }
    }
  }

  void attribute(const std::string& section, std::uint64_t tuples)
  {
    if (startsWith(section, "scalars"))
    {
      this->name("the scalars' name");
      const std::string_view type = this->word("the scalars' type");
      std::uint64_t components = 1;
      std::string key = lowered(this->word("LOOKUP_TABLE or a number of components"));
      if (key != "lookup_table")
      {
        long long value = 0;
        if (!LineCursor::parseInteger(key, value) || value < 1 || value > std::numeric_limits<int>::max())
        {
          this->fail("expected the scalars' number of components, found " + quoted(key));
        }
        components = static_cast<std::uint64_t>(value);
        key = lowered(this->word("LOOKUP_TABLE"));
      }
      if (key != "lookup_table")
      {
        this->fail("expected LOOKUP_TABLE after SCALARS, found " + quoted(key));
      }
      this->word("the lookup table's name");
      this->array(type, tuples, components, "SCALARS");
    }
    else if (startsWith(section, "vectors") || startsWith(section, "normals"))
    {
      this->name("the array's name");
      this->array(this->word("the array's type"), tuples, 3, section.c_str());
    }
    else if (startsWith(section, "tensors"))
    {
      this->name("the tensors' name");
      this->array(this->word("the tensors' type"), tuples, startsWith(section, "tensors6") ? 6 : 9, "TENSORS");
    }
    else if (startsWith(section, "texture_coordinates"))
    {
      this->name("the texture coordinates' name");
      const std::uint64_t dimension = this->count("the texture coordinates' dimension");
      if (dimension < 1 || dimension > 3)
      {
        this->fail("texture coordinates have 1 to 3 components, not " + std::to_string(dimension));
      }
      this->array(this->word("the texture coordinates' type"), tuples, dimension, "TEXTURE_COORDINATES");
    }
    else if (startsWith(section, "global_ids") || startsWith(section, "pedigree_ids") ||
      startsWith(section, "edge_flags"))
    {
      this->name("the array's name");
      this->array(this->word("the array's type"), tuples, 1, section.c_str());
    }
    else if (startsWith(section, "color_scalars"))
    {
      this->name("the color scalars' name");
      const std::uint64_t components = this->count("the color scalars' number of values");
      if (components < 1 || components > 4)
      {
        this->fail("color scalars have 1 to 4 values, not " + std::to_string(components));
      }
      this->array(this->Binary ? "unsigned_char" : "float", tuples, components, "COLOR_SCALARS");
    }
    else if (startsWith(section, "lookup_table"))
    {
      this->word("the lookup table's name");
      const std::uint64_t entries = this->count("the lookup table's size");
      if (entries > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) / 4)
      {
        this->fail("a lookup table of " + std::to_string(entries) + " entries");
      }
      if (this->Binary)
      {
        this->startBinaryData("LOOKUP_TABLE");
        this->requireBytes(entries, 4, "LOOKUP_TABLE");
        this->Position += static_cast<std::size_t>(4 * entries);
      }
      else
      {
        this->requireBytes(4 * entries, 2, "LOOKUP_TABLE");
        const ArrayType type{ Kind::Float, 4 };
        for (std::uint64_t i = 0; i < 4 * entries; ++i)
        {
          this->asciiValue(type, "LOOKUP_TABLE");
        }
      }
    }
    else if (startsWith(section, "field"))
    {
      this->fieldData();
    }
    else
    {
      this->fail("unknown attribute keyword " + quoted(section));
    }
  }

  std::string_view Bytes;
  std::size_t Position = 0;
  bool Binary = false;
  long long Major = 0;
  std::uint64_t Points = 0;
  std::uint64_t Cells = 0;
};
} // namespace

void checkLegacyVTK(std::string_view bytes)
{
  LegacyWalker(bytes).walk();
}

} // namespace kerf
