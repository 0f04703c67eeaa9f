// OFF and .seg parsing with line-numbered errors, and their writers.
#include "IO/MeshFormats.h"

#include "Error.h"
#include "IO/LineCursor.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <limits>

namespace kerf
{

std::string readTextFile(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary | std::ios::ate);
  if (!in)
  {
    throw Error("cannot open " + fileName);
  }
  const std::streamoff size = in.tellg();
  std::string bytes;
  if (size > 0)
  {
    bytes.resize(static_cast<std::size_t>(size));
    in.seekg(0);
    in.read(&bytes[0], size);
  }
  if (size < 0 || in.gcount() != size)
  {
    throw Error("cannot read " + fileName);
  }
  return bytes;
}

PolygonMesh parseOFF(const std::string& text)
{
  LineCursor cursor(text, "OFF");
  if (!cursor.next())
  {
    throw Error("OFF: the file is empty");
  }
  bool homogeneous = false;
  // The header is optional: a first word that is a plain integer is already the vertex count.
  if (!cursor.startsWithInteger())
  {
    const std::string header(cursor.word());
    if (header.size() < 3 || header.compare(header.size() - 3, 3, "OFF") != 0)
    {
      cursor.fail("expected the OFF header, found '" + header.substr(0, 40) + "'");
    }
    // Prefixes: ST (texture coordinates), C (colour), N (normal), 4 (homogeneous), n (dimension).
    const std::string prefix = header.substr(0, header.size() - 3);
    if (prefix.find('n') != std::string::npos)
    {
      cursor.fail("nOFF (arbitrary dimension) is not supported");
    }
    homogeneous = prefix.find('4') != std::string::npos;
    // Extra columns (normals, colours, texture coordinates) are skipped line by line.
    if (!cursor.atEndOfLine())
    {
      if (!cursor.startsWithInteger())
      {
        const std::string word(cursor.word());
        if (word == "BINARY")
        {
          cursor.fail("binary OFF is not supported; convert it to ASCII OFF");
        }
        cursor.fail("unexpected '" + word.substr(0, 40) + "' after the header");
      }
    }
    else if (!cursor.next())
    {
      throw Error("OFF: the file ends after its header");
    }
  }
  const long long vertexCount = cursor.integer("number of vertices");
  const long long faceCount = cursor.integer("number of faces");
  if (vertexCount < 0 || faceCount < 0 || vertexCount > std::numeric_limits<int>::max() / 2 ||
    faceCount > std::numeric_limits<int>::max() / 8)
  {
    cursor.fail("invalid vertex or face count");
  }
  // A vertex line takes at least 6 bytes ("0 0 0\n") and a face line 8 ("3 0 1 2\n"): the
  // allocations are sized by what the file can hold, not by what its header claims.
  const std::size_t bytes = text.size();
  PolygonMesh mesh;
  mesh.points.reserve(std::min(static_cast<std::size_t>(vertexCount), bytes / 6));
  mesh.polygonOffsets.reserve(std::min(static_cast<std::size_t>(faceCount), bytes / 8) + 1);
  mesh.polygonIndices.reserve(std::min(static_cast<std::size_t>(faceCount), bytes / 8) * 3);
  for (long long v = 0; v < vertexCount; ++v)
  {
    if (!cursor.next())
    {
      throw Error("OFF: the file ends after " + std::to_string(v) + " of " + std::to_string(vertexCount) + " vertices");
    }
    Vector3 p;
    p.x() = cursor.real("x coordinate");
    p.y() = cursor.real("y coordinate");
    p.z() = cursor.real("z coordinate");
    if (homogeneous)
    {
      p /= cursor.real("w coordinate");
    }
    mesh.points.push_back(p);
  }
  for (long long f = 0; f < faceCount; ++f)
  {
    if (!cursor.next())
    {
      throw Error("OFF: the file ends after " + std::to_string(f) + " of " + std::to_string(faceCount) + " faces");
    }
    const long long size = cursor.integer("number of face vertices");
    if (size < 3 || size > 1000000)
    {
      cursor.fail("a face must have at least 3 vertices, found " + std::to_string(size));
    }
    for (long long k = 0; k < size; ++k)
    {
      const long long index = cursor.integer("vertex index");
      if (index < 0 || index >= vertexCount)
      {
        cursor.fail(
          "vertex index " + std::to_string(index) + " is out of range [0, " + std::to_string(vertexCount) + ")");
      }
      mesh.polygonIndices.push_back(static_cast<int>(index));
    }
    mesh.polygonOffsets.push_back(static_cast<int>(mesh.polygonIndices.size()));
  }
  return mesh;
}

PolygonMesh readOFF(const std::string& fileName)
{
  try
  {
    return parseOFF(readTextFile(fileName));
  }
  catch (const Error& e)
  {
    throw Error(fileName + ": " + e.what());
  }
}

void writeOFF(const std::string& fileName, const PolygonMesh& mesh)
{
  std::ofstream out(fileName, std::ios::binary);
  if (!out)
  {
    throw Error("cannot write " + fileName);
  }
  out << "OFF\n" << mesh.points.size() << ' ' << mesh.polygonCount() << " 0\n";
  out << std::setprecision(17);
  for (const Vector3& p : mesh.points)
  {
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for (int f = 0; f < mesh.polygonCount(); ++f)
  {
    out << mesh.polygonOffsets[f + 1] - mesh.polygonOffsets[f];
    for (int k = mesh.polygonOffsets[f]; k < mesh.polygonOffsets[f + 1]; ++k)
    {
      out << ' ' << mesh.polygonIndices[k];
    }
    out << '\n';
  }
  if (!out)
  {
    throw Error("error while writing " + fileName);
  }
}

std::vector<int> parseSegmentation(const std::string& text)
{
  LineCursor cursor(text, "seg");
  std::vector<int> labels;
  while (cursor.next())
  {
    const long long label = cursor.integer("segment id");
    if (label < std::numeric_limits<int>::min() || label > std::numeric_limits<int>::max())
    {
      cursor.fail("segment id out of range");
    }
    if (!cursor.atEndOfLine())
    {
      cursor.fail("expected one segment id per line");
    }
    labels.push_back(static_cast<int>(label));
  }
  return labels;
}

std::vector<int> readSegmentation(const std::string& fileName)
{
  try
  {
    return parseSegmentation(readTextFile(fileName));
  }
  catch (const Error& e)
  {
    throw Error(fileName + ": " + e.what());
  }
}

void writeSegmentation(const std::string& fileName, const std::vector<int>& labels)
{
  std::ofstream out(fileName, std::ios::binary);
  if (!out)
  {
    throw Error("cannot write " + fileName);
  }
  for (int label : labels)
  {
    out << label << '\n';
  }
  if (!out)
  {
    throw Error("error while writing " + fileName);
  }
}

} // namespace kerf
