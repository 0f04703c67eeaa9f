// PLY, STL and OBJ parsing and the legacy VTK and VTP checks: valid variants read exactly, malformed
// files (overflowing counts, out-of-range indices, wrong types, truncation) give a located error.
#include "Error.h"
#include "IO/LegacyVTKValidation.h"
#include "IO/OBJFormat.h"
#include "IO/PLYFormat.h"
#include "IO/STLFormat.h"
#include "IO/VTPValidation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace kerf;

namespace
{
// The message of the kerf::Error that `parse` throws, or "" if it does not throw.
template <typename Parse>
std::string errorOf(Parse parse)
{
  try
  {
    parse();
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}

#define EXPECT_ERROR(call, text)                                                                                       \
  do                                                                                                                   \
  {                                                                                                                    \
    const std::string message = errorOf([&] { call; });                                                                \
    EXPECT_NE(message.find(text), std::string::npos) << "message: " << message;                                        \
  } while (false)

// A square pyramid: 5 points, 4 triangles and a quad.
const std::vector<double> PyramidPoints = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1 };
const std::vector<std::int64_t> PyramidIndices = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 3, 2, 1 };
const std::vector<std::int64_t> PyramidOffsets = { 0, 3, 6, 9, 12, 16 };

template <typename T>
void append(std::string& out, T value, bool bigEndian)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i)
  {
    out += static_cast<char>(bytes[bigEndian ? sizeof(T) - 1 - i : i]);
  }
}

std::string pyramidPLY(const std::string& format)
{
  std::string ply = "ply\nformat " + format +
    " 1.0\ncomment a pyramid\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 5\nproperty list uchar int vertex_indices\nend_header\n";
  const bool big = format == "binary_big_endian";
  for (std::size_t i = 0; i < PyramidPoints.size(); ++i)
  {
    if (format == "ascii")
    {
      ply += std::to_string(PyramidPoints[i]) + (i % 3 == 2 ? "\n" : " ");
    }
    else
    {
      append(ply, static_cast<float>(PyramidPoints[i]), big);
    }
  }
  for (std::size_t f = 0; f + 1 < PyramidOffsets.size(); ++f)
  {
    const auto n = static_cast<unsigned char>(PyramidOffsets[f + 1] - PyramidOffsets[f]);
    if (format == "ascii")
    {
      ply += std::to_string(n);
    }
    else
    {
      ply += static_cast<char>(n);
    }
    for (auto k = PyramidOffsets[f]; k < PyramidOffsets[f + 1]; ++k)
    {
      if (format == "ascii")
      {
        ply += " " + std::to_string(PyramidIndices[static_cast<std::size_t>(k)]);
      }
      else
      {
        append(ply, static_cast<std::int32_t>(PyramidIndices[static_cast<std::size_t>(k)]), big);
      }
    }
    ply += format == "ascii" ? "\n" : "";
  }
  return ply;
}

void expectPyramid(const MeshFileData& mesh)
{
  EXPECT_EQ(mesh.points, PyramidPoints);
  EXPECT_EQ(mesh.polygons.offsets, PyramidOffsets);
  EXPECT_EQ(mesh.polygons.indices, PyramidIndices);
}
} // namespace

// ---- PLY ----------------------------------------------------------------------------------------

TEST(PLY, AsciiAndBothByteOrdersReadTheSameMesh)
{
  for (const char* format : { "ascii", "binary_little_endian", "binary_big_endian" })
  {
    SCOPED_TRACE(format);
    const MeshFileData mesh = parsePLY(pyramidPLY(format));
    expectPyramid(mesh);
    EXPECT_TRUE(mesh.singlePrecision);
  }
}

TEST(PLY, FacesBeforeVerticesAndAttributes)
{
  const std::string ply = "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                          "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                          "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                          "property float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
                          "property float v\nend_header\n3 0 1 2 255 128 0\n0 0 0 0 0 1 0 0\n"
                          "1 0 0 0 0 1 1 0\n0 1 0 0 0 1 0 1\n";
  const MeshFileData mesh = parsePLY(ply);
  EXPECT_EQ(mesh.points, (std::vector<double>{ 0, 0, 0, 1, 0, 0, 0, 1, 0 }));
  EXPECT_FALSE(mesh.singlePrecision);
  ASSERT_EQ(mesh.pointArrays.size(), 2u);
  EXPECT_EQ(mesh.pointArrays[0].name, "Normals");
  EXPECT_EQ(mesh.pointArrays[0].values, (std::vector<double>{ 0, 0, 1, 0, 0, 1, 0, 0, 1 }));
  EXPECT_EQ(mesh.pointArrays[1].name, "TCoords");
  EXPECT_EQ(mesh.pointArrays[1].values, (std::vector<double>{ 0, 0, 1, 0, 0, 1 }));
  ASSERT_EQ(mesh.polygonArrays.size(), 1u);
  EXPECT_EQ(mesh.polygonArrays[0].name, "RGB");
  EXPECT_EQ(mesh.polygonArrays[0].values, (std::vector<double>{ 255, 128, 0 }));
}

TEST(PLY, NonFiniteCoordinatesAreReadAsSuch)
{
  const MeshFileData mesh = parsePLY("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                     "property float y\nproperty float z\nelement face 1\n"
                                     "property list uchar int vertex_indices\nend_header\n"
                                     "nan 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(std::isnan(mesh.points[0]));
  EXPECT_TRUE(std::isinf(mesh.points[3]));
}

TEST(PLY, StructuralErrorsNameTheHeaderLine)
{
  const std::string start = "ply\nformat binary_little_endian 1.0\n";
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  EXPECT_ERROR(
    parsePLY(start + "element vertex 3\n" + xyz + "element face 1\nproperty int vertex_indices\nend_header\n"),
    "header line 7: 'vertex_indices' of the face element is a scalar");
  EXPECT_ERROR(parsePLY(start +
                 "element vertex 3\nproperty list uchar float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"),
    "property 'x' of the vertex element is a list");
  EXPECT_ERROR(parsePLY(start + "element vertex 3\n" + xyz +
                 "element face 1\nproperty list float int vertex_indices\nend_header\n"),
    "header line 8: the count of list property 'vertex_indices' must have an integer type");
  EXPECT_ERROR(parsePLY(start + "element vertex 3\nproperty float16 x\n"), "unknown property type 'float16'");
  EXPECT_ERROR(parsePLY(start + "element vertex -3\n"), "header line 3: expected 'element <name> <count>'");
  EXPECT_ERROR(parsePLY(start + "element vertex 3\n" + xyz + "element vertex 3\n"), "declared twice");
  EXPECT_ERROR(parsePLY(start + "element vertex 3\n" + xyz), "no end_header");
  EXPECT_ERROR(parsePLY("PLY\n"), "does not start with a line 'ply'");
  EXPECT_ERROR(parsePLY(start + "element vertex 3\n" + xyz + "end_header\n"), "no face element");
}

TEST(PLY, CountsBeyondTheFileAreRefusedBeforeAllocating)
{
  // 2^63 - 1 vertices of 12 bytes: the product overflows 64 bits; nothing is allocated.
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 9223372036854775807\n"
                             "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n";
  EXPECT_ERROR(parsePLY(header + std::string(40, '\0')),
    "the file ends inside the vertex element: 9223372036854775807 rows need at least 2^64 bytes, 40 remain");
  // A list length past the end of the file.
  std::string ply = pyramidPLY("binary_little_endian");
  ply[ply.size() - 17] = static_cast<char>(200);
  EXPECT_ERROR(parsePLY(ply), "face row 4 declares a list of 200 items");
  // ASCII: the row and line that run out.
  EXPECT_ERROR(
    parsePLY("ply\nformat ascii 1.0\nelement vertex 300000000000\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n"),
    "the file ends after 1 of 300000000000 vertex rows");
}

TEST(PLY, IndicesAndRowsAreChecked)
{
  std::string ply = pyramidPLY("ascii");
  EXPECT_ERROR(parsePLY(ply.replace(ply.rfind("3 2 1"), 5, "3 2 5")),
    "PLY line 20: face row 4 uses vertex 5, but the file has 5 vertices");
  ply = pyramidPLY("ascii");
  EXPECT_ERROR(parsePLY(ply.replace(ply.rfind("4 0 3 2 1"), 9, "4 0 -3 2 1")), "uses vertex -3");
  ply = pyramidPLY("ascii");
  EXPECT_ERROR(parsePLY(ply.replace(ply.rfind("4 0 3 2 1"), 9, "2 0 3")), "has 2 corners; a face needs at least 3");
  ply = pyramidPLY("ascii");
  EXPECT_ERROR(parsePLY(ply.replace(ply.find("1.000000 0.000000 0.000000"), 26, "1 0 0 7")),
    "vertex row 1 has more values than its 3 properties");
  ply = pyramidPLY("ascii");
  EXPECT_ERROR(parsePLY(ply.replace(ply.find("1.000000 0.000000 0.000000"), 26, "1 0")),
    "PLY line 12: vertex row 1 is incomplete");
  ply = pyramidPLY("binary_big_endian");
  EXPECT_ERROR(parsePLY(ply.substr(0, ply.size() - 3)),
    "PLY byte 296: face row 4 declares a list of 4 items for 'vertex_indices', more than the rest");
  ply = pyramidPLY("binary_little_endian");
  EXPECT_ERROR(parsePLY(ply.substr(0, ply.size() - 17)), "PLY byte 299: the file ends inside face row 4");
}

// ---- STL ----------------------------------------------------------------------------------------

namespace
{
// The pyramid's 6 triangles (the quad split) with float corners.
std::vector<std::array<float, 9>> pyramidFacets()
{
  const int triangles[6][3] = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 }, { 0, 3, 2 }, { 0, 2, 1 } };
  std::vector<std::array<float, 9>> facets;
  for (const auto& t : triangles)
  {
    std::array<float, 9> f{};
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        f[static_cast<std::size_t>(3 * c + k)] =
          static_cast<float>(PyramidPoints[static_cast<std::size_t>(3 * t[c] + k)]);
      }
    }
    facets.push_back(f);
  }
  return facets;
}

std::string binarySTL(std::uint32_t declared, std::size_t facetCount)
{
  std::string stl(80, ' ');
  append(stl, declared, false);
  const auto facets = pyramidFacets();
  for (std::size_t i = 0; i < facetCount; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      append(stl, 0.0f, false);
    }
    for (float v : facets[i % facets.size()])
    {
      append(stl, v, false);
    }
    append(stl, std::uint16_t(0), false);
  }
  return stl;
}

std::string asciiSTL()
{
  std::string stl = "solid pyramid\n";
  for (const auto& f : pyramidFacets())
  {
    stl += "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c)
    {
      stl += "      vertex " + std::to_string(f[static_cast<std::size_t>(3 * c)]) + " " +
        std::to_string(f[static_cast<std::size_t>(3 * c + 1)]) + " " +
        std::to_string(f[static_cast<std::size_t>(3 * c + 2)]) + "\n";
    }
    stl += "    endloop\n  endfacet\n";
  }
  return stl + "endsolid pyramid\n";
}
} // namespace

TEST(STL, BinaryAndAsciiMergeCornersIntoPoints)
{
  for (const std::string& stl : { binarySTL(6, 6), asciiSTL() })
  {
    const MeshFileData mesh = parseSTL(stl);
    EXPECT_EQ(mesh.pointCount(), 5u);
    EXPECT_EQ(mesh.polygons.size(), 6u);
    EXPECT_TRUE(mesh.singlePrecision);
    // Every triangle's corners are the pyramid's points, in order.
    const auto facets = pyramidFacets();
    for (std::size_t f = 0; f < 6; ++f)
    {
      for (int c = 0; c < 3; ++c)
      {
        const auto p = static_cast<std::size_t>(mesh.polygons.indices[3 * f + static_cast<std::size_t>(c)]);
        for (int k = 0; k < 3; ++k)
        {
          EXPECT_EQ(mesh.points[3 * p + static_cast<std::size_t>(k)], facets[f][static_cast<std::size_t>(3 * c + k)]);
        }
      }
    }
  }
}

TEST(STL, BinaryCountsAgainstTheFileSize)
{
  // A header count of 0 (written by streaming exporters), or too small, is replaced by the facets the file holds.
  EXPECT_EQ(parseSTL(binarySTL(0, 6)).polygons.size(), 6u);
  EXPECT_EQ(parseSTL(binarySTL(2, 6)).polygons.size(), 6u);
  // Trailing bytes that are not a whole facet are ignored.
  EXPECT_EQ(parseSTL(binarySTL(6, 6) + "xyz").polygons.size(), 6u);
  // 2^31 triangles in a 384-byte file.
  EXPECT_ERROR(parseSTL(binarySTL(2147483648u, 6)),
    "STL byte 80: the binary header declares 2147483648 triangles, but the file's 384 bytes hold 6");
  EXPECT_ERROR(parseSTL(binarySTL(7, 6)), "declares 7 triangles");
  EXPECT_ERROR(parseSTL(std::string(50, '\x01')), "fewer than a binary STL's 84-byte header");
  EXPECT_ERROR(parseSTL(""), "the file is empty");
  // A binary file whose header starts with "solid" is still binary.
  std::string solidHeader = binarySTL(6, 6);
  solidHeader.replace(0, 5, "solid");
  EXPECT_EQ(parseSTL(solidHeader).polygons.size(), 6u);
}

TEST(STL, AsciiErrorsNameTheLine)
{
  std::string stl = asciiSTL();
  EXPECT_ERROR(parseSTL(stl.replace(stl.find("    endloop"), 11, "    vertex 1 2 3")),
    "STL line 7: expected 'endloop' after 3 vertices, found 'vertex'");
  stl = asciiSTL();
  EXPECT_ERROR(parseSTL(stl.replace(stl.find("vertex 0.000000 0.000000 0.000000"), 33, "vertex 0 zero 0")),
    "STL line 4: expected a number (vertex coordinate)");
  const std::string ascii = asciiSTL();
  EXPECT_ERROR(parseSTL(ascii.substr(0, ascii.find("outer loop\n") + 11)), "STL line 3: the file ends inside a facet");
  EXPECT_ERROR(parseSTL("solid x\n  facet normal 0 0 1\n  outer loop\n   vertex 1 2\n"), "STL line 4");
  // Upper case, CRLF and no final endsolid are accepted; NaN stays NaN.
  std::string upper = "SOLID X\r\nFACET NORMAL 0 0 1\r\nOUTER LOOP\r\nVERTEX nan 0 0\r\nVERTEX 1 0 0\r\n"
                      "VERTEX 0 1 0\r\nENDLOOP\r\nENDFACET\r\n";
  const MeshFileData mesh = parseSTL(upper);
  ASSERT_EQ(mesh.polygons.size(), 1u);
  EXPECT_TRUE(std::isnan(mesh.points[0]));
}

// ---- OBJ ----------------------------------------------------------------------------------------

TEST(OBJ, FacesLinesPointsAndRelativeIndices)
{
  const MeshFileData mesh = parseOBJ("# a pyramid\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0 1.0\nv 0.5 0.5 1 0.2 0.3 0.4\n"
                                     "g side\nf 1 2 5\nf -4 -3 -1\nf 3 4 5\nf 4/1 1/1 5/1\nusemtl base\n"
                                     "f 1 4 3 2\nl 1 2 3\np 5\nvt 0 0\n");
  EXPECT_EQ(mesh.points, PyramidPoints);
  EXPECT_EQ(mesh.polygons.offsets, PyramidOffsets);
  EXPECT_EQ(mesh.polygons.indices, PyramidIndices);
  EXPECT_EQ(mesh.lines.indices, (std::vector<std::int64_t>{ 0, 1, 2 }));
  EXPECT_EQ(mesh.vertices.indices, (std::vector<std::int64_t>{ 4 }));
}

TEST(OBJ, ConsistentTextureCoordinatesAndNormalsBecomePointArrays)
{
  const MeshFileData mesh = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.25\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                     "f 1/1/1 2/2/1 3/3/1\n");
  ASSERT_EQ(mesh.pointArrays.size(), 2u);
  EXPECT_EQ(mesh.pointArrays[0].name, "TCoords");
  EXPECT_EQ(mesh.pointArrays[0].values, (std::vector<double>{ 0.5, 0.25, 1, 0, 0, 1 }));
  EXPECT_EQ(mesh.pointArrays[1].values, (std::vector<double>{ 0, 0, 1, 0, 0, 1, 0, 0, 1 }));
  // A point seen with two texture coordinates (a seam): no TCoords array.
  const MeshFileData seam = parseOBJ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/1 2/1\n");
  EXPECT_TRUE(seam.pointArrays.empty());
}

TEST(OBJ, NonFiniteCoordinatesAreNotTurnedIntoZero)
{
  const MeshFileData mesh = parseOBJ("v nan 0 0\nv inf -inf 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(std::isnan(mesh.points[0]));
  EXPECT_TRUE(std::isinf(mesh.points[3]) && std::isinf(mesh.points[4]));
}

TEST(OBJ, IndicesOfEveryKindAreChecked)
{
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_ERROR(parseOBJ(v + "f 1/1/1 2/1/1 3/1/1\n"),
    "OBJ line 4: texture coordinate index 1 is out of range: the file has 0 texture coordinates");
  EXPECT_ERROR(parseOBJ(v + "vt 0 0\nf 1/99/1 2/1 3/1\n"), "OBJ line 5: texture coordinate index 99");
  EXPECT_ERROR(parseOBJ(v + "f 1//1 2//1 3//1\n"), "normal index 1 is out of range: the file has 0 normals");
  EXPECT_ERROR(parseOBJ(v + "f 1 2 9\n"), "OBJ line 4: vertex index 9 is out of range: the file has 3 vertices");
  EXPECT_ERROR(
    parseOBJ(v + "f 1 2 -4\n"), "vertex index -4 reaches before the first vertex (3 vertices defined so far)");
  EXPECT_ERROR(parseOBJ(v + "f 0 1 2\n"), "vertex index 0 (OBJ indices start at 1)");
  EXPECT_ERROR(parseOBJ(v + "f 1 2 99999999999999999999\n"), "expected a vertex index");
  EXPECT_ERROR(parseOBJ(v + "f 1 2\n"), "'f' needs at least 3 corners, found 2");
  EXPECT_ERROR(parseOBJ(v + "f 1/2/3/4 2 3\n"), "a corner has more than v/vt/vn");
  EXPECT_ERROR(parseOBJ(v + "f 1 2 \\\n3\n"), "line continuations");
  EXPECT_ERROR(parseOBJ("v 0 x 0\n"), "OBJ line 1: expected a number (y coordinate)");
  // A forward reference to a vertex defined later is fine.
  EXPECT_EQ(parseOBJ("f 1 2 3\n" + v).polygons.size(), 1u);
}

// ---- legacy VTK ---------------------------------------------------------------------------------

namespace
{
std::string legacyHeader(const std::string& version, const std::string& type)
{
  return "# vtk DataFile Version " + version + "\na triangle\n" + type + "\nDATASET POLYDATA\n";
}

std::string bigEndianInts(std::initializer_list<std::int32_t> values)
{
  std::string out;
  for (std::int32_t v : values)
  {
    append(out, v, true);
  }
  return out;
}
} // namespace

TEST(LegacyVTK, ValidFilesPass)
{
  const std::string ascii = legacyHeader("4.2", "ASCII") +
    "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nMETADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\n"
    "DATA 2 0 1 \n\nPOLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS d float 1\nLOOKUP_TABLE default\n0 1 2\n"
    "NORMALS n double\n0 0 1 0 0 1 0 0 1\nFIELD FieldData 1\nids 1 3 int\n0 1 2\nCELL_DATA 1\n"
    "COLOR_SCALARS c 3\n1 0 0\n";
  EXPECT_NO_THROW(checkLegacyVTK(ascii));
  const std::string modern = legacyHeader("5.1", "ASCII") +
    "POINTS 3 double\n0 0 0 1 0 0 0 1 0\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n";
  EXPECT_NO_THROW(checkLegacyVTK(modern));
  std::string binary = legacyHeader("4.2", "BINARY") + "POINTS 3 int\n" + bigEndianInts({ 0, 0, 0, 1, 0, 0, 0, 1, 0 }) +
    "\nPOLYGONS 1 4\n" + bigEndianInts({ 3, 0, 1, 2 }) + "\n";
  EXPECT_NO_THROW(checkLegacyVTK(binary));
}

TEST(LegacyVTK, CountsBeyondTheFileAreRefused)
{
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("4.2", "ASCII") + "POINTS 2147483648 float\n0 0 0\n"),
    "legacy VTK line 5 (byte 84): POINTS declares 6442450944 values of 2 bytes, but 7 bytes remain");
  EXPECT_ERROR(
    checkLegacyVTK(legacyHeader("4.2", "BINARY") + "POINTS 4611686018427387904 float\n" + std::string(36, '\0')),
    "POINTS declares 13835058055282163712 values of 4 bytes, but 36 bytes remain");
  EXPECT_ERROR(
    checkLegacyVTK(legacyHeader("4.2", "BINARY") + "POINTS 9223372036854775807 float\n" + std::string(36, '\0')),
    "POINTS declares more values than 2^64");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("4.2", "ASCII") + "POINTS -1 float\n"), "expected the number of points");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("4.2", "ASCII") + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nFIELD f 2147483647\n"),
    "FIELD declares 2147483647 values of 10 bytes");
  EXPECT_ERROR(
    checkLegacyVTK(legacyHeader("4.2", "ASCII") + "LOOKUP_TABLE t 5\n"), "unknown section keyword 'lookup_table'");
}

TEST(LegacyVTK, CellsMustFitTheirSection)
{
  const std::string points = "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("4.2", "ASCII") + points + "POLYGONS 1 4\n9 0 1 2\n"),
    "cell 0 of polygons claims 9 points, but 3 values remain in its section");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("4.2", "BINARY") + points.substr(0, 15) +
                 bigEndianInts({ 0, 0, 0, 0, 0, 0, 0, 0, 0 }) + "\nPOLYGONS 1 4\n" + bigEndianInts({ 3, 0, 1 })),
    "legacy VTK line 8 (byte 127): polygons declares 4 values of 4 bytes, but 12 bytes remain");
  EXPECT_ERROR(
    checkLegacyVTK(legacyHeader("4.2", "ASCII") + points + "POLYGONS 2 4\n3 0 1 2\n"), "declares 2 cells but holds 1");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("5.1", "ASCII") + points +
                 "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 4 3\nCONNECTIVITY vtktypeint64\n0 1 2 0 1 2\n"),
    "cell offset 2 is 3");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("5.1", "ASCII") + points +
                 "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 4611686018427387904\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
    "cell offset 1 is 4611686018427387904");
  EXPECT_ERROR(checkLegacyVTK(legacyHeader("5.1", "ASCII") + points +
                 "POLYGONS 2 3\nOFFSETS float\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
    "cell offsets must have an integer type");
}

TEST(LegacyVTK, ValuesVTKCannotParseAndAttributeCountsAreRefused)
{
  const std::string head = legacyHeader("4.2", "ASCII");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 nan 1 0 0 0 1 0\n"),
    "POINTS holds 'nan', not a finite number VTK's legacy reader can read");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 1e39 1 0 0 0 1 0\n"), "'1e39'");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOINT_DATA 4\n"),
    "POINT_DATA declares 4 values for 3 points");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOINT_DATA 3\nSCALARS a float 2147483648\n"),
    "expected the scalars' number of components");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOINT_DATA 3\nSCALARS a% float\n"),
    "an incomplete %XX escape");
  EXPECT_ERROR(checkLegacyVTK(head + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n" + std::string(300, ' ') + "\n"),
    "256 blanks without a line break");
  EXPECT_ERROR(checkLegacyVTK(head +
                 "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nMETADATA\nINFORMATION 1\n"
                 "NAME GUI_HIDE LOCATION vtkAbstractArray\nDATA 1\n\n"),
    "unsupported array information");
  EXPECT_ERROR(checkLegacyVTK("# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"),
    "Kerf reads POLYDATA legacy files only");
  EXPECT_ERROR(checkLegacyVTK("# vtk DataFile\n"), "does not start with '# vtk DataFile Version'");
}

// ---- VTP ----------------------------------------------------------------------------------------

namespace
{
// A stand-in for VTK's compressors: the "compressed" bytes are the data itself.
bool copyBlock(const std::string&, std::string_view compressed, std::size_t size, std::string& out)
{
  out = std::string(compressed);
  return out.size() == size;
}

std::string base64(const std::string& bytes)
{
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3)
  {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k)
    {
      group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    }
    for (std::size_t k = 0; k < 4; ++k)
    {
      out += k <= n ? alphabet[(group >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

// An inline binary array: [byte count][data], or a compressed one with one "block".
std::string binaryArray(const std::string& data, bool compressed, std::uint32_t declared)
{
  std::string header;
  if (!compressed)
  {
    append(header, declared, false);
    return base64(header + data);
  }
  for (std::uint32_t word :
    { 1u, static_cast<std::uint32_t>(data.size()), declared, static_cast<std::uint32_t>(data.size()) })
  {
    append(header, word, false);
  }
  return base64(header) + base64(data);
}

std::string int64s(std::initializer_list<std::int64_t> values)
{
  std::string out;
  for (std::int64_t v : values)
  {
    append(out, v, false);
  }
  return out;
}

std::string vtp(const std::string& points, const std::string& offsets, const std::string& connectivity,
  const std::string& format, const std::string& rootExtra = "", const std::string& pieceExtra = "")
{
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\"" +
    rootExtra + ">\n<PolyData>\n<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\"" + pieceExtra +
    ">\n<Points><DataArray type=\"Int64\" NumberOfComponents=\"3\" format=\"" + format + "\">" + points +
    "</DataArray></Points>\n<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"" + format + "\">" +
    connectivity + "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"" + format + "\">" + offsets +
    "</DataArray></Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

const std::string TrianglePoints = int64s({ 0, 0, 0, 1, 0, 0, 0, 1, 0 });
} // namespace

TEST(VTP, ValidAsciiBinaryAndCompressedPass)
{
  EXPECT_NO_THROW(checkVTP(vtp("0 0 0 1 0 0 0 1 0", "3", "0 1 2", "ascii"), copyBlock));
  EXPECT_NO_THROW(checkVTP(vtp(binaryArray(TrianglePoints, false, 72), binaryArray(int64s({ 3 }), false, 8),
                             binaryArray(int64s({ 0, 1, 2 }), false, 24), "binary"),
    copyBlock));
  EXPECT_NO_THROW(
    checkVTP(vtp(binaryArray(TrianglePoints, true, 72), binaryArray(int64s({ 3 }), true, 8),
               binaryArray(int64s({ 0, 1, 2 }), true, 24), "binary", " compressor=\"vtkZLibDataCompressor\""),
      copyBlock));
}

TEST(VTP, DeclaredCountsMustMatchTheData)
{
  std::string huge = vtp("0 0 0 1 0 0 0 1 0", "3", "0 1 2", "ascii");
  huge.replace(huge.find("NumberOfPoints=\"3\""), 18, "NumberOfPoints=\"2147483647\"");
  EXPECT_ERROR(
    checkVTP(huge, copyBlock), "needs 6442450941 values (2147483647 tuples of 3), but its data holds 9 words");
  huge = vtp("0 0 0 1 0 0 0 1 0", "3", "0 1 2", "ascii");
  huge.replace(huge.find("NumberOfPoints=\"3\""), 18, "NumberOfPoints=\"4294967299\"");
  EXPECT_ERROR(checkVTP(huge, copyBlock), "NumberOfPoints='4294967299' is not a count from 0 to 2147483647");
  // The last offset sizes the connectivity.
  EXPECT_ERROR(checkVTP(vtp("0 0 0 1 0 0 0 1 0", "1099511627776", "0 1 2", "ascii"), copyBlock),
    "array 'connectivity' in cell connectivity needs 1099511627776 values");
  EXPECT_ERROR(checkVTP(vtp(binaryArray(TrianglePoints, false, 72), binaryArray(int64s({ 3000000 }), false, 8),
                          binaryArray(int64s({ 0, 1, 2 }), false, 24), "binary"),
                 copyBlock),
    "needs 3000000 values");
  // A binary header claiming more bytes than there are.
  EXPECT_ERROR(checkVTP(vtp(binaryArray(TrianglePoints.substr(0, 40), false, 4000000000u),
                          binaryArray(int64s({ 3 }), false, 8), binaryArray(int64s({ 0, 1, 2 }), false, 24), "binary"),
                 copyBlock),
    "needs 9 values (3 tuples of 3), but its data holds 5 values");
  // A compression header whose last block is larger than its blocks.
  EXPECT_ERROR(
    checkVTP(vtp(binaryArray(TrianglePoints, true, 1u << 31), binaryArray(int64s({ 3 }), true, 8),
               binaryArray(int64s({ 0, 1, 2 }), true, 24), "binary", " compressor=\"vtkZLibDataCompressor\""),
      copyBlock),
    "inconsistent compression header");
}

TEST(VTP, UnknownTypesAndMalformedXMLAreRefused)
{
  const std::string good = vtp("0 0 0 1 0 0 0 1 0", "3", "0 1 2", "ascii");
  std::string bad = good;
  EXPECT_ERROR(checkVTP(bad.replace(bad.find("Int64"), 5, "Int128"), copyBlock), "unsupported type 'Int128'");
  bad = good;
  EXPECT_ERROR(
    checkVTP(bad.replace(bad.find("</Piece>"), 8, ""), copyBlock), "element 'Piece' is closed by 'PolyData'");
  bad = good;
  EXPECT_ERROR(checkVTP(bad.replace(bad.find("LittleEndian"), 12, "MiddleEndian"), copyBlock), "unknown byte_order");
  bad = good;
  EXPECT_ERROR(checkVTP(bad.replace(bad.find("header_type=\"UInt32\""), 20, "compressor=\"vtkNone\""), copyBlock),
    "unknown compressor 'vtkNone'");
  EXPECT_ERROR(checkVTP(std::string(100, '<'), copyBlock), "expected a name");
  std::string deep = "<VTKFile type=\"PolyData\">";
  for (int i = 0; i < 100; ++i)
  {
    deep += "<a>";
  }
  EXPECT_ERROR(checkVTP(deep, copyBlock), "nested more than 64 deep");
  bad = good;
  EXPECT_ERROR(checkVTP(bad.replace(bad.find("NumberOfComponents=\"3\""), 22, "NumberOfComponents=\"2\""), copyBlock),
    "the points array has 2 components, not 3");
}
