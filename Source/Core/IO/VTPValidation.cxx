// VTP validation: a small XML scan, then every array VTK's PolyData reader reads, sized from its data.
#include "IO/VTPValidation.h"

#include "Error.h"
#include "IO/BinaryData.h"
#include "IO/LineCursor.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace kerf
{

namespace
{
constexpr std::uint64_t LargestCount = std::numeric_limits<int>::max();
constexpr std::uint64_t LargestComponents = 1u << 16; // VTK loops over components when creating an array
constexpr std::uint64_t LargestBlock = 1u << 30;
constexpr int DeepestNesting = 64;

[[noreturn]] void failAt(std::size_t offset, const std::string& message)
{
  throw Error("VTP byte " + std::to_string(offset) + ": " + message);
}

// ---- a small XML scanner: elements, attributes and where each element's content lies ----------

struct XMLNode
{
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<XMLNode> children;
  std::size_t offset = 0;       // of the '<' of the start tag
  std::size_t contentBegin = 0; // just past the start tag's '>'
  std::size_t contentEnd = 0;

  const std::string* attribute(std::string_view key) const
  {
    for (const auto& a : this->attributes)
    {
      if (a.first == key)
      {
        return &a.second;
      }
    }
    return nullptr;
  }
};

class XMLScanner
{
public:
  explicit XMLScanner(std::string_view bytes)
    : Bytes(bytes)
  {
  }

  XMLNode document()
  {
    if (this->Bytes.substr(0, 3) == "\xEF\xBB\xBF")
    {
      this->Position = 3;
    }
    while (true)
    {
      this->skipSpace();
      if (this->Position >= this->Bytes.size())
      {
        failAt(this->Position, "no VTKFile element");
      }
      if (this->skipMarkup())
      {
        continue;
      }
      if (this->Bytes[this->Position] != '<')
      {
        failAt(this->Position, "text before the first element");
      }
      return this->element(0);
    }
  }

  // Where the appended data starts (just past its '_'), or npos if the file has none.
  std::size_t appendedStart() const { return this->Appended; }

private:
  void skipSpace()
  {
    while (this->Position < this->Bytes.size() && LineCursor::isSpace(this->Bytes[this->Position]))
    {
      ++this->Position;
    }
  }

  bool startsWith(std::string_view prefix) const { return this->Bytes.substr(this->Position, prefix.size()) == prefix; }

  void skipPast(std::string_view terminator, const char* what)
  {
    const std::size_t end = this->Bytes.find(terminator, this->Position);
    if (end == std::string_view::npos)
    {
      failAt(this->Position, std::string("an unterminated ") + what);
    }
    this->Position = end + terminator.size();
  }

  // Skips a comment, processing instruction, declaration or CDATA section; false if none is here.
  bool skipMarkup()
  {
    if (this->startsWith("<!--"))
    {
      this->skipPast("-->", "comment");
    }
    else if (this->startsWith("<![CDATA["))
    {
      this->skipPast("]]>", "CDATA section");
    }
    else if (this->startsWith("<?"))
    {
      this->skipPast("?>", "processing instruction");
    }
    else if (this->startsWith("<!"))
    {
      this->skipPast(">", "declaration");
    }
    else
    {
      return false;
    }
    return true;
  }

  static bool isNameCharacter(char c)
  {
    return !LineCursor::isSpace(c) && c != '=' && c != '>' && c != '/' && c != '<' && c != '"' && c != '\'';
  }

  std::string name()
  {
    const std::size_t start = this->Position;
    while (this->Position < this->Bytes.size() && isNameCharacter(this->Bytes[this->Position]))
    {
      ++this->Position;
    }
    if (this->Position == start)
    {
      failAt(start, "expected a name");
    }
    return std::string(this->Bytes.substr(start, this->Position - start));
  }

  // An attribute value with XML's five entities and character references decoded.
  std::string value(std::string_view raw, std::size_t at)
  {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i)
    {
      if (raw[i] == '<' || raw[i] == '>')
      {
        // VTK finds inline data by looking for the first '>' after the start of the element.
        failAt(at + i, "a '<' or '>' inside an attribute value");
      }
      if (raw[i] != '&')
      {
        out += raw[i];
        continue;
      }
      const std::size_t end = raw.find(';', i);
      const std::string_view entity = end == std::string_view::npos ? raw.substr(i) : raw.substr(i + 1, end - i - 1);
      if (entity == "lt" || entity == "gt")
      {
        failAt(at + i, "a '<' or '>' inside an attribute value");
      }
      if (entity == "amp" || entity == "quot" || entity == "apos")
      {
        out += entity == "amp" ? '&' : (entity == "quot" ? '"' : '\'');
      }
      else if (entity.size() > 1 && entity[0] == '#' && entity.size() < 10)
      {
        long long code = 0;
        const bool hex = entity[1] == 'x';
        const std::string_view digits = entity.substr(hex ? 2 : 1);
        if (digits.empty() ||
          std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10).ptr !=
            digits.data() + digits.size() ||
          code <= 0 || code > 127 || code == '<' || code == '>')
        {
          failAt(at + i, "an unsupported character reference in an attribute value");
        }
        out += static_cast<char>(code);
      }
      else
      {
        failAt(at + i, "an unknown entity in an attribute value");
      }
      i = end;
    }
    return out;
  }

  XMLNode element(int depth)
  {
    if (depth > DeepestNesting)
    {
      failAt(this->Position, "elements nested more than " + std::to_string(DeepestNesting) + " deep");
    }
    XMLNode node;
    node.offset = this->Position;
    ++this->Position; // '<'
    node.name = this->name();
    while (true)
    {
      this->skipSpace();
      if (this->Position >= this->Bytes.size())
      {
        failAt(node.offset, "the start tag of " + quoted(node.name) + " is not closed");
      }
      const char c = this->Bytes[this->Position];
      if (c == '/' || c == '>')
      {
        break;
      }
      const std::string key = this->name();
      this->skipSpace();
      if (this->Position >= this->Bytes.size() || this->Bytes[this->Position] != '=')
      {
        failAt(this->Position, "attribute " + quoted(key) + " has no value");
      }
      ++this->Position;
      this->skipSpace();
      const char quote = this->Position < this->Bytes.size() ? this->Bytes[this->Position] : '\0';
      const std::size_t end =
        quote == '"' || quote == '\'' ? this->Bytes.find(quote, this->Position + 1) : std::string_view::npos;
      if (end == std::string_view::npos)
      {
        failAt(this->Position, "attribute " + quoted(key) + " has no quoted value");
      }
      if (node.attribute(key))
      {
        failAt(this->Position, "attribute " + quoted(key) + " appears twice");
      }
      node.attributes.emplace_back(
        key, this->value(this->Bytes.substr(this->Position + 1, end - this->Position - 1), this->Position + 1));
      this->Position = end + 1;
    }
    if (this->Bytes[this->Position] == '/')
    {
      if (this->Position + 1 >= this->Bytes.size() || this->Bytes[this->Position + 1] != '>')
      {
        failAt(this->Position, "expected '/>'");
      }
      this->Position += 2;
      node.contentBegin = node.contentEnd = this->Position;
      return node;
    }
    ++this->Position; // '>'
    node.contentBegin = this->Position;
    if (node.name == "AppendedData")
    {
      // Raw bytes follow '_'; VTK stops parsing XML here.
      this->skipSpace();
      if (this->Position >= this->Bytes.size() || this->Bytes[this->Position] != '_')
      {
        failAt(this->Position, "appended data does not start with '_'");
      }
      this->Appended = this->Position + 1;
      this->Position = this->Bytes.size();
      node.contentEnd = this->Bytes.size();
      return node;
    }
    while (true)
    {
      const std::size_t next = this->Bytes.find('<', this->Position);
      if (next == std::string_view::npos)
      {
        failAt(node.offset, "element " + quoted(node.name) + " is not closed");
      }
      this->Position = next;
      if (this->startsWith("</"))
      {
        node.contentEnd = next;
        this->Position += 2;
        const std::string closing = this->name();
        this->skipSpace();
        if (closing != node.name || this->Position >= this->Bytes.size() || this->Bytes[this->Position] != '>')
        {
          failAt(next, "element " + quoted(node.name) + " is closed by " + quoted(closing));
        }
        ++this->Position;
        return node;
      }
      if (this->skipMarkup())
      {
        continue;
      }
      node.children.push_back(this->element(depth + 1));
      if (this->Appended != std::string_view::npos)
      {
        node.contentEnd = this->Bytes.size();
        return node;
      }
    }
  }

  std::string_view Bytes;
  std::size_t Position = 0;
  std::size_t Appended = std::string_view::npos;
};

// ---- base64 -----------------------------------------------------------------------------------

int base64Value(char c)
{
  if (c >= 'A' && c <= 'Z')
  {
    return c - 'A';
  }
  if (c >= 'a' && c <= 'z')
  {
    return c - 'a' + 26;
  }
  if (c >= '0' && c <= '9')
  {
    return c - '0' + 52;
  }
  return c == '+' ? 62 : (c == '/' ? 63 : -1);
}

// Bytes that the leading run of base64 characters of `text` decodes to.
std::uint64_t base64Length(std::string_view text)
{
  std::size_t n = 0;
  while (n < text.size() && base64Value(text[n]) >= 0)
  {
    ++n;
  }
  return static_cast<std::uint64_t>(n) / 4 * 3 + (n % 4 == 0 ? 0 : (n % 4) - 1);
}

// The first `count` decoded bytes of `text` (fewer if it ends first).
std::string decodeBase64(std::string_view text, std::uint64_t count)
{
  std::string out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (std::size_t i = 0; i < text.size() && out.size() < count; ++i)
  {
    const int v = base64Value(text[i]);
    if (v < 0)
    {
      break;
    }
    buffer = (buffer << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xFF);
    }
  }
  return out;
}

// ---- the arrays ---------------------------------------------------------------------------------

struct WordType
{
  int size = 0; // bytes; 0 for unknown
  bool isInteger = false;
  bool isSigned = false;
  bool isString = false;
};

WordType wordType(const std::string& name)
{
  if (name == "Int8" || name == "UInt8")
  {
    return { 1, true, name[0] == 'I', false };
  }
  if (name == "Int16" || name == "UInt16")
  {
    return { 2, true, name[0] == 'I', false };
  }
  if (name == "Int32" || name == "UInt32")
  {
    return { 4, true, name[0] == 'I', false };
  }
  if (name == "Int64" || name == "UInt64")
  {
    return { 8, true, name[0] == 'I', false };
  }
  if (name == "Float32")
  {
    return { 4, false, true, false };
  }
  if (name == "Float64")
  {
    return { 8, false, true, false };
  }
  if (name == "String")
  {
    return { 1, false, false, true };
  }
  return {};
}

std::uint64_t plainCount(const XMLNode& node, const char* key, bool required, std::uint64_t largest);

// VTK reads `length` values from Value children with index attributes 0 .. length - 1; a
// length it cannot find values for makes it index an empty vector.
void informationKey(const XMLNode& key)
{
  if (!key.attribute("length"))
  {
    return;
  }
  const std::uint64_t length = plainCount(key, "length", true, 1024);
  std::uint64_t values = 0;
  for (const XMLNode& child : key.children)
  {
    values += child.name == "Value" ? 1 : 0;
  }
  if (length > values)
  {
    failAt(key.offset,
      "an information key declares " + std::to_string(length) + " values but holds " + std::to_string(values));
  }
}

std::uint64_t plainCount(const XMLNode& node, const char* key, bool required, std::uint64_t largest)
{
  const std::string* text = node.attribute(key);
  if (!text)
  {
    if (required)
    {
      failAt(node.offset, quoted(node.name) + " has no " + key + " attribute");
    }
    return 0;
  }
  std::uint64_t value = 0;
  const char* end = text->data() + text->size();
  if (text->empty() || std::from_chars(text->data(), end, value).ptr != end || value > largest)
  {
    failAt(
      node.offset, std::string(key) + "=" + quoted(*text) + " is not a count from 0 to " + std::to_string(largest));
  }
  return value;
}

class VTPChecker
{
public:
  VTPChecker(std::string_view bytes, const XMLBlockDecompressor& decompress)
    : Bytes(bytes)
    , Decompress(decompress)
  {
  }

  void check()
  {
    XMLScanner scanner(this->Bytes);
    const XMLNode root = scanner.document();
    if (root.name != "VTKFile")
    {
      failAt(root.offset, "the root element is " + quoted(root.name) + ", not VTKFile");
    }
    const std::string* type = root.attribute("type");
    if (!type || *type != "PolyData")
    {
      failAt(root.offset, "Kerf reads VTKFile type=\"PolyData\" only");
    }
    const std::string* order = root.attribute("byte_order");
    if (order && *order != "LittleEndian" && *order != "BigEndian")
    {
      failAt(root.offset, "unknown byte_order " + quoted(*order));
    }
    this->BigEndian = order && *order == "BigEndian";
    const std::string* header = root.attribute("header_type");
    if (header && *header != "UInt32" && *header != "UInt64")
    {
      failAt(root.offset, "unknown header_type " + quoted(*header));
    }
    this->HeaderWord = header && *header == "UInt64" ? 8 : 4;
    if (const std::string* compressor = root.attribute("compressor"))
    {
      if (*compressor != "vtkZLibDataCompressor" && *compressor != "vtkLZ4DataCompressor" &&
        *compressor != "vtkLZMADataCompressor")
      {
        failAt(root.offset, "unknown compressor " + quoted(*compressor));
      }
      this->Compressor = *compressor;
    }
    this->AppendedStart = scanner.appendedStart();
    for (const XMLNode& child : root.children)
    {
      if (child.name == "AppendedData")
      {
        const std::string* encoding = child.attribute("encoding");
        this->AppendedBase64 = !encoding || *encoding != "raw";
      }
    }
    bool found = false;
    for (const XMLNode& polyData : root.children)
    {
      if (polyData.name != "PolyData")
      {
        continue;
      }
      found = true;
      std::uint64_t totalPoints = 0;
      for (const XMLNode& child : polyData.children)
      {
        if (child.name == "Piece")
        {
          totalPoints += this->piece(child);
          if (totalPoints > LargestCount)
          {
            failAt(child.offset, "the pieces hold more than 2^31 - 1 points together");
          }
        }
        else if (child.name == "FieldData")
        {
          this->fieldData(child);
        }
      }
    }
    if (!found)
    {
      failAt(root.offset, "no PolyData element");
    }
  }

private:
  std::uint64_t piece(const XMLNode& piece)
  {
    const std::uint64_t points = plainCount(piece, "NumberOfPoints", true, LargestCount);
    std::uint64_t cells = 0;
    for (const char* kind : { "Verts", "Lines", "Strips", "Polys" })
    {
      const std::string key = std::string("NumberOf") + kind;
      const std::uint64_t n = plainCount(piece, key.c_str(), false, LargestCount);
      cells += n;
      for (const XMLNode& child : piece.children)
      {
        if (child.name == kind && n > 0)
        {
          this->cellArrays(child, n);
        }
      }
    }
    for (const XMLNode& child : piece.children)
    {
      if (child.name == "Points" || child.name == "PointData" || child.name == "CellData")
      {
        const std::uint64_t tuples = child.name == "CellData" ? cells : points;
        for (std::size_t i = 0; i < child.children.size(); ++i)
        {
          const std::uint64_t components = this->array(child.children[i], tuples, child.name.c_str()).components;
          if (child.name == "Points" && i == 0 && points > 0 && components != 3)
          {
            failAt(
              child.children[i].offset, "the points array has " + std::to_string(components) + " components, not 3");
          }
        }
      }
    }
    return points;
  }

  void cellArrays(const XMLNode& cells, std::uint64_t count)
  {
    const XMLNode* offsets = nullptr;
    const XMLNode* connectivity = nullptr;
    for (const XMLNode& child : cells.children)
    {
      const std::string* name = child.attribute("Name");
      if (name && *name == "offsets" && !offsets)
      {
        offsets = &child;
      }
      if (name && *name == "connectivity" && !connectivity)
      {
        connectivity = &child;
      }
    }
    if (!offsets || !connectivity)
    {
      failAt(cells.offset, quoted(cells.name) + " lacks its offsets or connectivity array");
    }
    const ArrayFacts facts = this->array(*offsets, count, "cell offsets", true);
    if (facts.components != 1 || !facts.integer)
    {
      failAt(offsets->offset, "cell offsets need one component of an integer type");
    }
    if (facts.last < 0)
    {
      failAt(offsets->offset, "the last cell offset is negative");
    }
    const ArrayFacts links = this->array(*connectivity, static_cast<std::uint64_t>(facts.last), "cell connectivity");
    if (links.components != 1 || !links.integer)
    {
      failAt(connectivity->offset, "cell connectivity needs one component of an integer type");
    }
  }

  void fieldData(const XMLNode& field)
  {
    for (const XMLNode& child : field.children)
    {
      // VTK reads one tuple of every named field array when it first opens the file.
      const std::uint64_t tuples = plainCount(child, "NumberOfTuples", false, LargestCount);
      this->array(child, tuples, "FieldData");
    }
  }

  struct ArrayFacts
  {
    std::uint64_t components = 1;
    bool integer = false;
    std::int64_t last = -1; // the last value, when asked for
  };

  // Checks that the array's data holds tuples * components values; reads the last if asked.
  ArrayFacts array(const XMLNode& node, std::uint64_t tuples, const char* where, bool wantLast = false)
  {
    const std::string* typeName = node.attribute("type");
    const WordType type = typeName ? wordType(*typeName) : WordType{};
    if (type.size == 0)
    {
      failAt(node.offset,
        std::string("an array in ") + where + " has an unsupported type " + quoted(typeName ? *typeName : "(none)"));
    }
    for (const XMLNode& child : node.children)
    {
      if (child.name == "InformationKey")
      {
        informationKey(child);
      }
    }
    ArrayFacts facts;
    facts.integer = type.isInteger;
    facts.components =
      node.attribute("NumberOfComponents") ? plainCount(node, "NumberOfComponents", true, LargestComponents) : 1;
    if (facts.components == 0)
    {
      failAt(node.offset, "NumberOfComponents=\"0\"");
    }
    const std::uint64_t values = tuples * facts.components;
    const std::uint64_t bytes = values * static_cast<std::uint64_t>(type.size);
    const std::string arrayName = node.attribute("Name") ? *node.attribute("Name") : "(unnamed)";
    auto tooShort = [&](std::uint64_t available, const char* unit) {
      failAt(node.offset,
        "array " + quoted(arrayName) + " in " + where + " needs " + std::to_string(values) + " values (" +
          std::to_string(tuples) + " tuples of " + std::to_string(facts.components) + "), but its data holds " +
          std::to_string(available) + " " + unit);
    };
    const std::string* format = node.attribute("format");
    if (!node.attribute("offset") && !(format && *format == "binary"))
    {
      // ASCII: VTK parses words from the start of the content.
      std::string_view content = this->Bytes.substr(node.contentBegin, node.contentEnd - node.contentBegin);
      std::uint64_t words = 0;
      std::string_view lastWord;
      std::size_t position = 0;
      for (std::string_view w = nextWord(content, position); !w.empty() && words < values;
           w = nextWord(content, position))
      {
        ++words;
        lastWord = w;
      }
      if (words < values)
      {
        tooShort(words, "words");
      }
      if (wantLast && values > 0)
      {
        long long value = -1;
        if (!LineCursor::parseInteger(lastWord, value))
        {
          failAt(node.offset, "the last cell offset " + quoted(lastWord) + " is not an integer");
        }
        facts.last = value;
      }
      else if (wantLast)
      {
        facts.last = 0;
      }
      return facts;
    }

    // Binary: inline base64, or appended (raw or base64) at an offset.
    std::string_view source;
    bool base64 = true;
    if (node.attribute("offset"))
    {
      const std::uint64_t offset = plainCount(node, "offset", true, std::numeric_limits<std::int64_t>::max());
      if (this->AppendedStart == std::string_view::npos)
      {
        failAt(node.offset, "an array refers to appended data the file does not have");
      }
      const std::uint64_t size = this->Bytes.size() - this->AppendedStart;
      if (offset >= size)
      {
        failAt(node.offset,
          "appended-data offset " + std::to_string(offset) + " lies past its end (" + std::to_string(size) + " bytes)");
      }
      source = this->Bytes.substr(this->AppendedStart + static_cast<std::size_t>(offset));
      base64 = this->AppendedBase64;
    }
    else
    {
      std::size_t start = node.contentBegin;
      while (start < node.contentEnd && LineCursor::isSpace(this->Bytes[start]))
      {
        ++start;
      }
      source = this->Bytes.substr(start, node.contentEnd - start);
    }
    const auto word = [this](const std::string& header, std::size_t index) {
      return decodeUnsigned(
        bytesOf(header, index * static_cast<std::size_t>(this->HeaderWord)), this->HeaderWord, this->BigEndian);
    };
    const std::uint64_t headerWord = static_cast<std::uint64_t>(this->HeaderWord);
    const std::uint64_t sourceBytes = base64 ? base64Length(source) : source.size();
    std::string lastValue; // the bytes of the last value, when it is wanted

    if (this->Compressor.empty())
    {
      if (sourceBytes < headerWord)
      {
        failAt(node.offset, "array " + quoted(arrayName) + " lacks its binary header");
      }
      const std::string header =
        base64 ? decodeBase64(source, headerWord) : std::string(source.substr(0, this->HeaderWord));
      const std::uint64_t declared = word(header, 0);
      const std::uint64_t available = std::min(declared, sourceBytes - headerWord);
      if (available / static_cast<std::uint64_t>(type.size) < values)
      {
        tooShort(available / static_cast<std::uint64_t>(type.size), "values");
      }
      if (wantLast && values > 0)
      {
        const std::string decoded = base64
          ? decodeBase64(source, headerWord + bytes)
          : std::string(source.substr(0, static_cast<std::size_t>(headerWord + bytes)));
        lastValue = decoded.substr(decoded.size() - static_cast<std::size_t>(type.size));
      }
    }
    else
    {
      // Compressed: [blocks, block size, last block size, compressed sizes...], then the blocks.
      if (sourceBytes < 3 * headerWord)
      {
        failAt(node.offset, "array " + quoted(arrayName) + " lacks its compression header");
      }
      const std::string start =
        base64 ? decodeBase64(source, 3 * headerWord) : std::string(source.substr(0, 3 * this->HeaderWord));
      const std::uint64_t blocks = word(start, 0);
      const std::uint64_t blockSize = word(start, 1);
      const std::uint64_t lastSize = word(start, 2);
      if (!fitsIn(blocks, headerWord, sourceBytes - 3 * headerWord))
      {
        failAt(node.offset,
          "array " + quoted(arrayName) + " declares " + std::to_string(blocks) +
            " compressed blocks, more than its data can list");
      }
      if (blocks > 0 && (blockSize == 0 || blockSize > LargestBlock || lastSize > blockSize))
      {
        failAt(node.offset,
          "array " + quoted(arrayName) + " has an inconsistent compression header (block size " +
            std::to_string(blockSize) + ", last block " + std::to_string(lastSize) + ")");
      }
      const std::uint64_t headerBytes = (3 + blocks) * headerWord;
      const std::string header = base64 ? decodeBase64(source, headerBytes)
                                        : std::string(source.substr(0, static_cast<std::size_t>(headerBytes)));
      const std::string_view blockSource = base64
        ? source.substr(static_cast<std::size_t>(std::min<std::uint64_t>(source.size(), (headerBytes + 2) / 3 * 4)))
        : source.substr(static_cast<std::size_t>(headerBytes));
      const std::uint64_t blockBytes = base64 ? base64Length(blockSource) : blockSource.size();
      std::uint64_t compressedTotal = 0;
      const std::uint64_t ratio = this->Compressor == "vtkLZMADataCompressor" ? (1u << 16) : 1032;
      for (std::uint64_t b = 0; b < blocks; ++b)
      {
        const std::uint64_t compressed = word(header, static_cast<std::size_t>(3 + b));
        const std::uint64_t size = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
        if (compressed > blockBytes - compressedTotal || size / ratio > compressed + 64)
        {
          failAt(node.offset,
            "compressed block " + std::to_string(b) + " of array " + quoted(arrayName) + " claims " +
              std::to_string(compressed) + " bytes for " + std::to_string(size) + ", which the data cannot hold");
        }
        compressedTotal += compressed;
      }
      const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastSize != 0 ? lastSize : blockSize);
      if (total / static_cast<std::uint64_t>(type.size) < values)
      {
        tooShort(total / static_cast<std::uint64_t>(type.size), "values");
      }
      if (wantLast && values > 0)
      {
        // The block holding the last value, decompressed.
        const std::uint64_t at = bytes - static_cast<std::uint64_t>(type.size);
        const std::uint64_t b = at / blockSize;
        std::uint64_t skip = 0;
        for (std::uint64_t k = 0; k < b; ++k)
        {
          skip += word(header, static_cast<std::size_t>(3 + k));
        }
        const std::uint64_t compressed = word(header, static_cast<std::size_t>(3 + b));
        const std::string packed = base64
          ? decodeBase64(blockSource, skip + compressed).substr(static_cast<std::size_t>(skip))
          : std::string(blockSource.substr(static_cast<std::size_t>(skip), static_cast<std::size_t>(compressed)));
        const std::uint64_t size = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
        std::string block;
        if (!this->Decompress(this->Compressor, packed, static_cast<std::size_t>(size), block) || block.size() != size)
        {
          failAt(node.offset,
            "compressed block " + std::to_string(b) + " of array " + quoted(arrayName) + " does not decompress to " +
              std::to_string(size) + " bytes");
        }
        lastValue = block.substr(static_cast<std::size_t>(at - b * blockSize), static_cast<std::size_t>(type.size));
      }
    }
    if (wantLast)
    {
      facts.last = 0;
      if (values > 0)
      {
        if (!type.isInteger || lastValue.size() != static_cast<std::size_t>(type.size))
        {
          failAt(node.offset, "cannot read the last cell offset");
        }
        const unsigned char* b = bytesOf(lastValue);
        if (type.isSigned)
        {
          facts.last = decodeSigned(b, type.size, this->BigEndian);
        }
        else
        {
          const std::uint64_t u = decodeUnsigned(b, type.size, this->BigEndian);
          facts.last = u > LargestCount * 16 ? std::numeric_limits<std::int64_t>::max() : static_cast<std::int64_t>(u);
        }
        if (facts.last > static_cast<std::int64_t>(LargestCount) * 16)
        {
          failAt(node.offset, "the last cell offset " + std::to_string(facts.last) + " is beyond what Kerf reads");
        }
      }
    }
    return facts;
  }

  std::string_view Bytes;
  const XMLBlockDecompressor& Decompress;
  bool BigEndian = false;
  int HeaderWord = 4;
  std::string Compressor;
  std::size_t AppendedStart = std::string_view::npos;
  bool AppendedBase64 = true;
};
} // namespace

void checkVTP(std::string_view bytes, const XMLBlockDecompressor& decompress)
{
  VTPChecker(bytes, decompress).check();
}

} // namespace kerf
