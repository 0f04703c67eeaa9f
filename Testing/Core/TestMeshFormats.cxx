// OFF and .seg parsing: valid variants, malformed and truncated files, lossless round trips.
#include "Error.h"
#include "IO/MeshFormats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace kerf;

namespace
{
std::string errorOf(const std::string& text)
{
  try
  {
    parseOFF(text);
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}

std::string temporaryPath(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("kerf-core-" + name)).string();
}
} // namespace

TEST(OFF, ParsesTrianglesAndPolygons)
{
  const PolygonMesh mesh = parseOFF("OFF\n# a comment\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                                    "2 2 0 # trailing comment\n\n3 0 1 4\n4 0 1 2 3\n");
  ASSERT_EQ(mesh.points.size(), 5u);
  ASSERT_EQ(mesh.polygonCount(), 2);
  EXPECT_EQ(mesh.polygonOffsets, (std::vector<int>{ 0, 3, 7 }));
  EXPECT_EQ(mesh.polygonIndices, (std::vector<int>{ 0, 1, 4, 0, 1, 2, 3 }));
  EXPECT_EQ(mesh.points[4], Vector3(2, 2, 0));
}

TEST(OFF, HeaderVariantsAndExtraColumns)
{
  // Counts on the header line, per-vertex colours and per-face colours.
  const PolygonMesh coloured =
    parseOFF("COFF 3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 9 9 9\n");
  EXPECT_EQ(coloured.points.size(), 3u);
  EXPECT_EQ(coloured.polygonIndices, (std::vector<int>{ 0, 1, 2 }));
  // Homogeneous coordinates are divided by w.
  const PolygonMesh homogeneous = parseOFF("4OFF\n3 1 0\n2 4 6 2\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
  EXPECT_EQ(homogeneous.points[0], Vector3(1, 2, 3));
  // A missing header is tolerated.
  EXPECT_EQ(parseOFF("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").polygonCount(), 1);
}

TEST(OFF, NonFiniteCoordinatesAreReadForValidationToRefuse)
{
  const PolygonMesh mesh = parseOFF("OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 inf\n3 0 1 2\n");
  EXPECT_TRUE(std::isnan(mesh.points[0].x()));
  EXPECT_TRUE(std::isinf(mesh.points[2].z()));
}

TEST(OFF, MalformedFilesNameTheProblemAndLine)
{
  EXPECT_EQ(errorOf(""), "OFF: the file is empty");
  EXPECT_NE(errorOf("PLY\n3 1 0\n").find("expected the OFF header"), std::string::npos);
  EXPECT_NE(errorOf("OFF BINARY\n").find("binary OFF"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n-3 1 0\n").find("invalid vertex or face count"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n").find("ends after 2 of 3 vertices"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").find("ends after 1 of 2 faces"), std::string::npos);
  EXPECT_NE(
    errorOf("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n").find("line 4: expected a number"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").find("index 7 is out of range"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n").find("at least 3 vertices"), std::string::npos);
  EXPECT_NE(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n").find("expected an integer"), std::string::npos);
  EXPECT_NE(errorOf("\x7f\x45\x4c\x46\x02\x01\x01\x00\x00\x00").find("expected the OFF header"), std::string::npos);
}

TEST(OFF, WriteThenReadIsLossless)
{
  PolygonMesh mesh;
  mesh.points = { { 0.1, 1.0 / 3.0, -2e-17 }, { 1e10, std::sqrt(2.0), 3.0 }, { -0.7, 0.25, 1e-300 }, { 5, 6, 7 } };
  mesh.polygonIndices = { 0, 1, 2, 0, 2, 3, 1 };
  mesh.polygonOffsets = { 0, 3, 7 };
  const std::string path = temporaryPath("roundtrip.off");
  writeOFF(path, mesh);
  const PolygonMesh back = readOFF(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.points, mesh.points);
  EXPECT_EQ(back.polygonIndices, mesh.polygonIndices);
  EXPECT_EQ(back.polygonOffsets, mesh.polygonOffsets);
}

TEST(OFF, MissingFileIsAnError)
{
  EXPECT_THROW(readOFF("/nonexistent/kerf/mesh.off"), Error);
}

TEST(OFF, ReadsTheBundledCamel)
{
  const PolygonMesh camel = readOFF(std::string(KERF_SOURCE_DIR) + "/Data/camel.off");
  EXPECT_EQ(camel.points.size(), 9770u);
  EXPECT_EQ(camel.polygonCount(), 19536);
}

TEST(Segmentation, ParseWriteRoundTrip)
{
  EXPECT_EQ(parseSegmentation("0\n1\n\n1\n2\n"), (std::vector<int>{ 0, 1, 1, 2 }));
  EXPECT_EQ(parseSegmentation("3\r\n-1\r\n"), (std::vector<int>{ 3, -1 }));
  const std::vector<int> labels{ 4, 0, 0, 17, -1, 2 };
  const std::string path = temporaryPath("labels.seg");
  writeSegmentation(path, labels);
  EXPECT_EQ(readSegmentation(path), labels);
  std::remove(path.c_str());
}

TEST(Segmentation, GarbageNamesTheLine)
{
  try
  {
    parseSegmentation("0\n1\nthree\n");
    FAIL() << "garbage was accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseSegmentation("1 2\n"), Error);
  EXPECT_THROW(parseSegmentation("1.5\n"), Error);
  EXPECT_THROW(parseSegmentation("99999999999999\n"), Error);
}

TEST(Segmentation, ReadsPrincetonBenchmarkFiles)
{
  const std::filesystem::path root = std::filesystem::path(KERF_SHARED_DATA) / "psb-dev";
  if (!std::filesystem::exists(root / "off" / "1.off"))
  {
    GTEST_SKIP() << "../shared/data/psb-dev is absent";
  }
  const PolygonMesh mesh = readOFF((root / "off" / "1.off").string());
  EXPECT_EQ(mesh.points.size(), 4706u);
  EXPECT_EQ(mesh.polygonCount(), 9408);
  const std::vector<int> labels = readSegmentation((root / "seg" / "1" / "1_0.seg").string());
  EXPECT_EQ(static_cast<int>(labels.size()), mesh.polygonCount());
}
