// Bad input never crashes, never corrupts, and is reported: hand-made defects and the xatlas
// edge cases fed to every Kerf filter, and malformed files fed to the readers.
#include "KerfFilterList.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkKerfMeshFileReader.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>

#include <functional>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> makeMesh(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<vtkIdType>>& cells)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& c : cells)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
}

struct BadMesh
{
  std::string name;
  vtkSmartPointer<vtkPolyData> mesh;
  std::string expected; // a phrase the error must contain
};

std::vector<BadMesh> handMadeDefects()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<BadMesh> cases;
  cases.push_back({ "empty", vtkSmartPointer<vtkPolyData>::New(), "no triangles" });
  {
    auto lines = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    pts->InsertNextPoint(1, 0, 0);
    vtkNew<vtkCellArray> cells;
    const vtkIdType ids[2] = { 0, 1 };
    cells->InsertNextCell(2, ids);
    lines->SetPoints(pts);
    lines->SetLines(cells);
    cases.push_back({ "lines only", lines, "no triangles" });
  }
  cases.push_back(
    { "NaN coordinate", makeMesh({ { 0, 0, 0 }, { 1, nan, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } }), "NaN or infinite" });
  cases.push_back({ "infinite coordinate", makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, inf } }, { { 0, 1, 2 } }),
    "NaN or infinite" });
  cases.push_back({ "non-manifold edge",
    makeMesh(
      { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } }, { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } }),
    "non-manifold" });
  cases.push_back({ "bowtie vertex",
    makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 0, 0 }, { -1, -1, 0 } }, { { 0, 1, 2 }, { 0, 3, 4 } }),
    "vertex is non-manifold" });
  cases.push_back({ "flipped neighbour",
    makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 3, 2 } }),
    "inconsistently oriented" });
  cases.push_back({ "duplicate triangle",
    makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 1, 2, 0 } }), "duplicates another" });
  cases.push_back({ "repeated point", makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 0, 1 } }),
    "same point twice" });
  cases.push_back(
    { "point id out of range", makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 7 } }), "uses point 7" });
  cases.push_back({ "polygon with a negative id",
    makeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }, { { 0, 1, 3, -2 } }), "uses point -2" });
  return cases;
}

using Filter = kerf::test::SurfaceFilter;

std::vector<Filter> filters()
{
  return kerf::test::SurfaceFilters();
}
} // namespace

int TestBadInput(int argc, char* argv[])
{
  bool ok = true;
  for (const Filter& filter : filters())
  {
    for (const BadMesh& bad : handMadeDefects())
    {
      const vtkIdType points = bad.mesh->GetNumberOfPoints();
      const vtkIdType cells = bad.mesh->GetNumberOfCells();
      const vtkMTimeType time = bad.mesh->GetMTime();
      vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = filter.make();
      algorithm->SetInputData(bad.mesh);
      int succeeded = 1;
      const std::string error = kerf::test::UpdateAndCaptureError(algorithm, &succeeded);
      std::cout << filter.name << " on " << bad.name << ": " << error << std::endl;
      ok &= KERF_CHECK(succeeded == 0);
      ok &= KERF_CHECK(error.find(bad.expected) != std::string::npos);
      ok &= KERF_CHECK(algorithm->GetOutput()->GetNumberOfPoints() == 0);
      // The input is untouched.
      ok &= KERF_CHECK(bad.mesh->GetNumberOfPoints() == points);
      ok &= KERF_CHECK(bad.mesh->GetNumberOfCells() == cells);
      ok &= KERF_CHECK(bad.mesh->GetMTime() == time);
      ok &= KERF_CHECK(bad.mesh->GetPointData()->GetNumberOfArrays() == 0);
    }

    if (!filter.alone)
    {
      continue;
    }
    // Several components are accepted, and every component gets values.
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> polys;
    for (int copy = 0; copy < 2; ++copy)
    {
      const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 2);
      const vtkIdType offset = pts->GetNumberOfPoints();
      for (int v = 0; v < sphere.vertexCount(); ++v)
      {
        kerf::Vector3 p = sphere.point(v) + kerf::Vector3(3.0 * copy, 0, 0);
        pts->InsertNextPoint(p.data());
      }
      for (const kerf::Triangle& t : sphere.triangles())
      {
        const vtkIdType ids[3] = { t[0] + offset, t[1] + offset, t[2] + offset };
        polys->InsertNextCell(3, ids);
      }
    }
    vtkNew<vtkPolyData> twoSpheres;
    twoSpheres->SetPoints(pts);
    twoSpheres->SetPolys(polys);
    vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = filter.make();
    algorithm->SetInputData(twoSpheres);
    ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(algorithm).empty());
  }

  // The xatlas edge cases: each file either gives a clear error or a valid result.
  struct FileCase
  {
    const char* file;
    const char* expected; // "" when the filter must succeed
  };
  const FileCase xatlas[] = {
    { "xatlas/cube.obj", "" },   // split at texture seams, welded back to a closed cube
    { "xatlas/gazebo.obj", "" }, // 56 parts
    { "xatlas/degenerate_edge.obj", "same point twice" }, { "xatlas/zero_length_edge.obj", "same point twice" },
    { "xatlas/double_sided.obj", "duplicate" }, { "xatlas/duplicate_edge.obj", "" },
    { "xatlas/zero_area_face.obj", "" }, // zero-area triangles contribute nothing
  };
  if (kerf::test::SharedDataPath("xatlas").empty())
  {
    std::cout << "../shared/data/xatlas is absent: the xatlas cases are skipped" << std::endl;
  }
  else
  {
    for (const FileCase& c : xatlas)
    {
      vtkNew<vtkKerfMeshFileReader> reader;
      reader->SetFileName(kerf::test::SharedDataPath(c.file).c_str());
      ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(reader).empty());
      for (const Filter& filter : filters())
      {
        if (!filter.alone && c.expected[0] == '\0')
        {
          continue;
        }
        vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = filter.make();
        algorithm->SetInputConnection(reader->GetOutputPort());
        int succeeded = 0;
        const std::string error = kerf::test::UpdateAndCaptureError(algorithm, &succeeded);
        std::cout << filter.name << " on " << c.file << ": " << (error.empty() ? "ok" : error) << std::endl;
        if (c.expected[0] == '\0')
        {
          ok &= KERF_CHECK(succeeded == 1 && error.empty());
        }
        else
        {
          ok &= KERF_CHECK(succeeded == 0 && error.find(c.expected) != std::string::npos);
        }
      }
    }
  }

  // Readers: missing, truncated, garbage and unsupported files.
  const std::string input = kerf::test::SourcePath(argc, argv, "Testing/Data/Input/");
  const std::pair<std::string, std::string> badFiles[] = {
    { input + "does-not-exist.off", "does not exist" },
    { input + "truncated.off", "ends after" },
    { input + "garbage.off", "expected the OFF header" },
    { input + "bad-index.off", "out of range" },
    { input + "binary-garbage.ply", "no vertex element with x, y and z" },
    { input + "truncated-ascii.ply", "vertex row 1 is incomplete" },
    { input + "truncated-binary.ply", "the file ends inside the vertex element" },
    { input + "no-faces.ply", "no face element" },
    { input + "empty.stl", "the file is empty" },
    { input + "not-a-mesh.txt", "Unsupported mesh file extension" },
  };
  for (const auto& bad : badFiles)
  {
    vtkNew<vtkKerfMeshFileReader> reader;
    reader->SetFileName(bad.first.c_str());
    int succeeded = 1;
    const std::string error = kerf::test::UpdateAndCaptureError(reader, &succeeded);
    std::cout << "vtkKerfMeshFileReader on " << bad.first << ": " << error << std::endl;
    ok &= KERF_CHECK(succeeded == 0 && !error.empty());
    ok &= KERF_CHECK(error.find(bad.second) != std::string::npos);
  }

  // A face with an index past the last vertex is refused, naming the line.
  {
    vtkNew<vtkKerfMeshFileReader> reader;
    reader->SetFileName((input + "bad-index.obj").c_str());
    int succeeded = 1;
    const std::string error = kerf::test::UpdateAndCaptureError(reader, &succeeded);
    std::cout << "vtkKerfMeshFileReader on bad-index.obj: " << error << std::endl;
    ok &= KERF_CHECK(succeeded == 0 &&
      error.find("OBJ line 3: vertex index 9 is out of range: the file has 2 vertices") != std::string::npos);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
