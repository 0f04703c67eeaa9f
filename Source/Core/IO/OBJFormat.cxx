// OBJ parsing: statements line by line, indices resolved and checked, consistent attributes kept.
#include "IO/OBJFormat.h"

#include "Error.h"
#include "IO/LineCursor.h"

#include <string>
#include <vector>

namespace kerf
{

namespace
{
// An index that names an element defined later in the file, checked once the file is read.
struct ForwardReference
{
  std::int64_t index = -1; // zero-based
  int line = 0;
};

// Resolves OBJ indices (1-based, or negative counting back) against what is defined so far.
class IndexResolver
{
public:
  IndexResolver(LineCursor& cursor, const char* what, const char* plural)
    : Cursor(cursor)
    , What(what)
    , Plural(plural)
  {
  }

  std::int64_t resolve(std::string_view word, std::int64_t definedSoFar)
  {
    long long index = 0;
    if (!LineCursor::parseInteger(word, index))
    {
      this->Cursor.fail(std::string("expected a ") + this->What + " index, found " + quoted(word));
    }
    if (index == 0)
    {
      this->Cursor.fail(std::string(this->What) + " index 0 (OBJ indices start at 1)");
    }
    if (index < 0)
    {
      if (index < -definedSoFar)
      {
        this->Cursor.fail(std::string(this->What) + " index " + std::to_string(index) + " reaches before the first " +
          this->What + " (" + std::to_string(definedSoFar) + " " + (definedSoFar == 1 ? this->What : this->Plural) +
          " defined so far)");
      }
      return definedSoFar + index;
    }
    if (index > definedSoFar && index - 1 > this->Forward.index)
    {
      this->Forward = { index - 1, this->Cursor.line() };
    }
    return index - 1;
  }

  // Throws if a forward reference names an element the file never defines.
  void check(std::int64_t defined) const
  {
    if (this->Forward.index >= defined)
    {
      throw Error("OBJ line " + std::to_string(this->Forward.line) + ": " + this->What + " index " +
        std::to_string(this->Forward.index + 1) + " is out of range: the file has " + std::to_string(defined) + " " +
        (defined == 1 ? this->What : this->Plural));
    }
  }

private:
  LineCursor& Cursor;
  const char* What;
  const char* Plural;
  ForwardReference Forward;
};

// The v, vt and vn indices of one corner word ("7", "7/3", "7/3/2", "7//2"); -1 where absent.
struct Corner
{
  std::int64_t vertex = -1;
  std::int64_t texture = -1;
  std::int64_t normal = -1;
};

// One value per point from the corners that name it: -1 unknown, -2 after two corners disagree.
void assignPerPoint(std::vector<std::int64_t>& perPoint, std::int64_t point, std::int64_t value)
{
  if (point >= static_cast<std::int64_t>(perPoint.size()))
  {
    perPoint.resize(static_cast<std::size_t>(point) + 1, -1);
  }
  std::int64_t& slot = perPoint[static_cast<std::size_t>(point)];
  slot = slot == -1 || slot == value ? value : -2;
}

// A point array from per-point element indices, or false if a corner lacked one or two disagreed.
bool gatherPerPoint(const std::vector<std::int64_t>& perPoint, bool everyCorner, const std::vector<double>& elements,
  int components, std::size_t pointCount, MeshFileArray& array)
{
  if (!everyCorner)
  {
    return false;
  }
  for (std::int64_t e : perPoint)
  {
    if (e == -2)
    {
      return false;
    }
  }
  array.components = components;
  array.values.assign(pointCount * static_cast<std::size_t>(components), 0.0);
  for (std::size_t p = 0; p < perPoint.size() && p < pointCount; ++p)
  {
    if (perPoint[p] >= 0)
    {
      for (int k = 0; k < components; ++k)
      {
        array.values[p * static_cast<std::size_t>(components) + static_cast<std::size_t>(k)] =
          elements[static_cast<std::size_t>(perPoint[p]) * static_cast<std::size_t>(components) +
            static_cast<std::size_t>(k)];
      }
    }
  }
  return true;
}
} // namespace

MeshFileData parseOBJ(std::string_view bytes)
{
  LineCursor cursor(bytes, "OBJ");
  MeshFileData mesh;
  std::vector<double> textures; // u, v per vt
  std::vector<double> normals;  // x, y, z per vn
  IndexResolver vertexIndices(cursor, "vertex", "vertices");
  IndexResolver textureIndices(cursor, "texture coordinate", "texture coordinates");
  IndexResolver normalIndices(cursor, "normal", "normals");
  std::vector<std::int64_t> texturePerPoint;
  std::vector<std::int64_t> normalPerPoint;
  bool everyCornerTextured = true;
  bool everyCornerNormal = true;
  mesh.points.reserve(bytes.size() / 16);
  mesh.polygons.indices.reserve(bytes.size() / 16);

  auto corner = [&](std::string_view word) {
    Corner c;
    const std::size_t first = word.find('/');
    const std::size_t second = first == std::string_view::npos ? first : word.find('/', first + 1);
    if (second != std::string_view::npos && word.find('/', second + 1) != std::string_view::npos)
    {
      cursor.fail("a corner has more than v/vt/vn: " + quoted(word));
    }
    const auto defined = [](const std::vector<double>& v, std::size_t n) {
      return static_cast<std::int64_t>(v.size() / n);
    };
    c.vertex = vertexIndices.resolve(word.substr(0, first), static_cast<std::int64_t>(mesh.pointCount()));
    if (first != std::string_view::npos)
    {
      const std::string_view texture =
        word.substr(first + 1, second == std::string_view::npos ? std::string_view::npos : second - first - 1);
      if (!texture.empty())
      {
        c.texture = textureIndices.resolve(texture, defined(textures, 2));
      }
      if (second != std::string_view::npos)
      {
        c.normal = normalIndices.resolve(word.substr(second + 1), defined(normals, 3));
      }
    }
    return c;
  };

  while (cursor.next())
  {
    const std::string_view rest = cursor.rest();
    const std::size_t lastSolid = rest.find_last_not_of(" \t\r\v\f");
    if (lastSolid != std::string_view::npos && rest[lastSolid] == '\\')
    {
      cursor.fail("line continuations ('\\') are not supported");
    }
    const std::string_view keyword = cursor.word();
    if (keyword == "v")
    {
      const double x = cursor.real("x coordinate");
      const double y = cursor.real("y coordinate");
      const double z = cursor.real("z coordinate");
      mesh.points.insert(mesh.points.end(), { x, y, z });
    }
    else if (keyword == "vt")
    {
      const double u = cursor.real("texture coordinate u");
      const double v = cursor.atEndOfLine() ? 0.0 : cursor.real("texture coordinate v");
      textures.insert(textures.end(), { u, v });
    }
    else if (keyword == "vn")
    {
      const double x = cursor.real("normal x");
      const double y = cursor.real("normal y");
      const double z = cursor.real("normal z");
      normals.insert(normals.end(), { x, y, z });
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      CellList& cells = keyword == "f" ? mesh.polygons : (keyword == "l" ? mesh.lines : mesh.vertices);
      const std::size_t smallest = keyword == "f" ? 3 : (keyword == "l" ? 2 : 1);
      const std::size_t first = cells.indices.size();
      while (!cursor.atEndOfLine())
      {
        const Corner c = corner(cursor.word());
        cells.indices.push_back(c.vertex);
        if (keyword == "f")
        {
          everyCornerTextured = everyCornerTextured && c.texture >= 0;
          everyCornerNormal = everyCornerNormal && c.normal >= 0;
          if (c.texture >= 0)
          {
            assignPerPoint(texturePerPoint, c.vertex, c.texture);
          }
          if (c.normal >= 0)
          {
            assignPerPoint(normalPerPoint, c.vertex, c.normal);
          }
        }
      }
      if (cells.indices.size() - first < smallest)
      {
        cursor.fail("'" + std::string(keyword) + "' needs at least " + std::to_string(smallest) +
          (smallest == 1 ? " corner" : " corners") + ", found " + std::to_string(cells.indices.size() - first));
      }
      cells.close();
    }
  }
  vertexIndices.check(static_cast<std::int64_t>(mesh.pointCount()));
  textureIndices.check(static_cast<std::int64_t>(textures.size() / 2));
  normalIndices.check(static_cast<std::int64_t>(normals.size() / 3));

  // Point arrays only for files of polygons alone, as VTK's cell order would not match otherwise.
  if (mesh.lines.size() == 0 && mesh.vertices.size() == 0 && mesh.polygons.size() > 0)
  {
    struct Attribute
    {
      const char* name;
      MeshFileArray::Role role;
      const std::vector<std::int64_t>& perPoint;
      bool everyCorner;
      const std::vector<double>& elements;
      int components;
    };
    const Attribute attributes[] = {
      { "TCoords", MeshFileArray::Role::TextureCoordinates, texturePerPoint, everyCornerTextured, textures, 2 },
      { "Normals", MeshFileArray::Role::Normals, normalPerPoint, everyCornerNormal, normals, 3 },
    };
    for (const Attribute& a : attributes)
    {
      MeshFileArray array;
      array.name = a.name;
      array.role = a.role;
      if (gatherPerPoint(a.perPoint, a.everyCorner, a.elements, a.components, mesh.pointCount(), array))
      {
        mesh.pointArrays.push_back(std::move(array));
      }
    }
  }
  return mesh;
}

} // namespace kerf
