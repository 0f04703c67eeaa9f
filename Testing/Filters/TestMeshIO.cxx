// OFF and .seg readers and writers through VTK, and vtkKerfMeshFileReader on every supported format.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkKerfMeshFileWriter.h"
#include "vtkKerfOFFReader.h"
#include "vtkKerfOFFWriter.h"
#include "vtkKerfSegmentationReader.h"
#include "vtkKerfSegmentationWriter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkTestUtilities.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <vector>

namespace
{
template <typename Reader>
vtkSmartPointer<vtkPolyData> readWithVTK(const std::string& file)
{
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}
} // namespace

int TestMeshIO(int argc, char* argv[])
{
  bool ok = true;
  char* tempDirectory = vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "/tmp");
  const std::string temp(tempDirectory);
  delete[] tempDirectory;
  vtkSmartPointer<vtkPolyData> torus = kerf::test::ToPolyData(kerf::makeTorus(2.0, 0.5, 24, 12));

  // OFF round trip is lossless, and face order is cell order.
  const std::string offFile = temp + "/kerf-io-torus.off";
  vtkNew<vtkKerfOFFWriter> offWriter;
  offWriter->SetInputData(torus);
  offWriter->SetFileName(offFile.c_str());
  ok &= KERF_CHECK(offWriter->Write() == 1);
  vtkNew<vtkKerfOFFReader> offReader;
  offReader->SetFileName(offFile.c_str());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(offReader).empty());
  vtkPolyData* back = offReader->GetOutput();
  ok &= KERF_CHECK(back->GetNumberOfPoints() == torus->GetNumberOfPoints());
  ok &= KERF_CHECK(back->GetNumberOfPolys() == torus->GetNumberOfPolys());
  for (vtkIdType i = 0; i < torus->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    torus->GetPoint(i, a);
    back->GetPoint(i, b);
    if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
    {
      ok &= KERF_CHECK(false && "OFF coordinates changed");
      break;
    }
  }
  ok &= KERF_CHECK(vtkKerfOFFReader::CanReadFile(offFile.c_str()) == 1);

  // A segmentation written from a cell array reads back onto the mesh.
  vtkNew<vtkIntArray> labels;
  labels->SetName("Segment");
  for (vtkIdType c = 0; c < back->GetNumberOfCells(); ++c)
  {
    labels->InsertNextValue(static_cast<int>((c * 7) % 5));
  }
  vtkNew<vtkPolyData> labelled;
  labelled->ShallowCopy(back);
  labelled->GetCellData()->AddArray(labels);
  const std::string segFile = temp + "/kerf-io-torus.seg";
  vtkNew<vtkKerfSegmentationWriter> segWriter;
  segWriter->SetInputData(labelled);
  segWriter->SetFileName(segFile.c_str());
  ok &= KERF_CHECK(segWriter->Write() == 1);
  vtkNew<vtkKerfSegmentationReader> segReader;
  segReader->SetInputConnection(offReader->GetOutputPort());
  segReader->SetFileName(segFile.c_str());
  segReader->SetArrayName("Human");
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(segReader).empty());
  vtkDataArray* read = segReader->GetOutput()->GetCellData()->GetArray("Human");
  ok &= KERF_CHECK(read && read->GetNumberOfTuples() == labels->GetNumberOfTuples());
  for (vtkIdType c = 0; read && c < read->GetNumberOfTuples(); ++c)
  {
    if (read->GetComponent(c, 0) != labels->GetValue(c))
    {
      ok &= KERF_CHECK(false && "labels changed");
      break;
    }
  }
  ok &= KERF_CHECK(offReader->GetOutput()->GetCellData()->GetArray("Human") == nullptr);

  // A .seg with the wrong number of labels, a missing array, a bad path: clear errors.
  const std::string shortSeg = temp + "/kerf-io-short.seg";
  std::ofstream(shortSeg) << "0\n1\n";
  vtkNew<vtkKerfSegmentationReader> wrongCount;
  wrongCount->SetInputConnection(offReader->GetOutputPort());
  wrongCount->SetFileName(shortSeg.c_str());
  int succeeded = 1;
  std::string error = kerf::test::UpdateAndCaptureError(wrongCount, &succeeded);
  ok &= KERF_CHECK(succeeded == 0 && error.find("has 2 labels but the mesh has 576 cells") != std::string::npos);
  const std::string garbageSeg = temp + "/kerf-io-garbage.seg";
  std::ofstream(garbageSeg) << "0\nseven\n";
  wrongCount->SetFileName(garbageSeg.c_str());
  error = kerf::test::UpdateAndCaptureError(wrongCount, &succeeded);
  ok &= KERF_CHECK(succeeded == 0 && error.find("line 2") != std::string::npos);

  vtkNew<vtkKerfSegmentationWriter> noArray;
  noArray->SetInputData(torus);
  noArray->SetFileName((temp + "/kerf-io-none.seg").c_str());
  noArray->SetArrayName("Missing");
  error = kerf::test::UpdateAndCaptureError(noArray, &succeeded);
  ok &= KERF_CHECK(error.find("no cell array named 'Missing'") != std::string::npos);
  ok &= KERF_CHECK(noArray->GetErrorCode() != 0);

  vtkNew<vtkKerfOFFWriter> badPath;
  badPath->SetInputData(torus);
  badPath->SetFileName("/nonexistent/kerf/out.off");
  error = kerf::test::UpdateAndCaptureError(badPath, &succeeded);
  ok &= KERF_CHECK(error.find("cannot write") != std::string::npos);

  // Every supported format reads back with the torus's surface.
  auto write = [&torus](auto* writer, const std::string& file) {
    writer->SetInputData(torus);
    writer->SetFileName(file.c_str());
    return writer->Write();
  };
  const std::string any = temp + "/kerf-io-any";
  vtkNew<vtkPLYWriter> ply;
  vtkNew<vtkOBJWriter> obj;
  vtkNew<vtkSTLWriter> stl;
  vtkNew<vtkXMLPolyDataWriter> vtp;
  // Inline binary: appended data does not read back with Debian 12's expat (see vtkKerfMeshFileReader).
  vtp->SetDataModeToBinary();
  vtkNew<vtkPolyDataWriter> legacy;
  vtkNew<vtkKerfOFFWriter> off;
  ok &= KERF_CHECK(write(ply.Get(), any + ".ply") == 1);
  ok &= KERF_CHECK(write(obj.Get(), any + ".obj") == 1);
  ok &= KERF_CHECK(write(stl.Get(), any + ".stl") == 1);
  ok &= KERF_CHECK(write(vtp.Get(), any + ".vtp") == 1);
  ok &= KERF_CHECK(write(legacy.Get(), any + ".vtk") == 1);
  ok &= KERF_CHECK(write(off.Get(), any + ".OFF") == 1);
  for (const char* extension : { ".ply", ".obj", ".stl", ".vtp", ".vtk", ".OFF" })
  {
    const std::string file = any + extension;
    vtkNew<vtkKerfMeshFileReader> reader;
    reader->SetFileName(file.c_str());
    ok &= KERF_CHECK(vtkKerfMeshFileReader::IsSupportedExtension(file.c_str()) == 1);
    error = kerf::test::UpdateAndCaptureError(reader);
    std::cout << "read " << file << ": " << (error.empty() ? "ok" : error) << std::endl;
    ok &= KERF_CHECK(error.empty());
    ok &= KERF_CHECK(reader->GetOutput()->GetNumberOfPolys() == torus->GetNumberOfPolys());
    // STL stores each facet separately; its reader merges points back.
    ok &= KERF_CHECK(reader->GetOutput()->GetNumberOfPoints() == torus->GetNumberOfPoints());
  }

  // Texture coordinates in double precision (Chart Parameterization's UV) travel through every
  // format that holds them and read back within float precision; input untouched.
  {
    auto textured = vtkSmartPointer<vtkPolyData>::New();
    textured->ShallowCopy(torus);
    vtkNew<vtkDoubleArray> uv;
    uv->SetName("UV");
    uv->SetNumberOfComponents(2);
    for (vtkIdType v = 0; v < textured->GetNumberOfPoints(); ++v)
    {
      uv->InsertNextTuple2(0.001 * static_cast<double>(v % 997), 0.5 + 0.0003 * static_cast<double>(v % 1201));
    }
    textured->GetPointData()->SetTCoords(uv);
    for (const char* extension : { ".ply", ".obj", ".vtp", ".vtk" })
    {
      const std::string file = temp + "/kerf-io-uv" + extension;
      vtkNew<vtkKerfMeshFileWriter> writer;
      writer->SetInputData(textured);
      writer->SetFileName(file.c_str());
      ok &= KERF_CHECK(writer->Write() == 1);
      ok &= KERF_CHECK(textured->GetPointData()->GetTCoords() == uv.Get());
      vtkNew<vtkKerfMeshFileReader> reader;
      reader->SetFileName(file.c_str());
      error = kerf::test::UpdateAndCaptureError(reader);
      ok &= KERF_CHECK(error.empty());
      vtkDataArray* back = reader->GetOutput()->GetPointData()->GetTCoords();
      ok &=
        KERF_CHECK(back && back->GetNumberOfTuples() == uv->GetNumberOfTuples() && back->GetNumberOfComponents() == 2);
      double worst = back ? 0.0 : 1.0;
      for (vtkIdType v = 0; back && v < back->GetNumberOfTuples(); ++v)
      {
        for (int k = 0; k < 2; ++k)
        {
          worst = std::max(worst, std::abs(back->GetComponent(v, k) - uv->GetComponent(v, k)));
        }
      }
      std::cout << "texture coordinates through " << extension << ": largest difference " << worst << std::endl;
      ok &= KERF_CHECK(worst < 1e-6);
    }
  }

  // Kerf's PLY, STL and OBJ parsers and its checks before VTK's legacy and XML readers give what
  // VTK's own readers give on every flavour VTK writes: the same points in the same order and the
  // same cells.
  struct Flavour
  {
    std::string file;
    vtkSmartPointer<vtkPolyData> (*readWithVTK)(const std::string&);
  };
  std::vector<Flavour> flavours;
  auto add = [&](auto writer, const std::string& name, vtkSmartPointer<vtkPolyData> (*reader)(const std::string&)) {
    const std::string file = temp + "/kerf-io-flavour-" + name;
    writer->SetInputData(torus);
    writer->SetFileName(file.c_str());
    ok &= KERF_CHECK(writer->Write() == 1);
    flavours.push_back({ file, reader });
  };
  for (int order : { 0, 1, 2 })
  {
    auto plyWriter = vtkSmartPointer<vtkPLYWriter>::New();
    if (order == 0)
    {
      plyWriter->SetFileTypeToASCII();
    }
    else
    {
      plyWriter->SetFileTypeToBinary();
      plyWriter->SetDataByteOrder(order == 1 ? VTK_LITTLE_ENDIAN : VTK_BIG_ENDIAN);
    }
    add(plyWriter, "order" + std::to_string(order) + ".ply", readWithVTK<vtkPLYReader>);
  }
  for (bool binary : { false, true })
  {
    auto stlWriter = vtkSmartPointer<vtkSTLWriter>::New();
    binary ? stlWriter->SetFileTypeToBinary() : stlWriter->SetFileTypeToASCII();
    add(stlWriter, std::string(binary ? "binary" : "ascii") + ".stl", readWithVTK<vtkSTLReader>);
    auto legacyWriter = vtkSmartPointer<vtkPolyDataWriter>::New();
    binary ? legacyWriter->SetFileTypeToBinary() : legacyWriter->SetFileTypeToASCII();
    add(legacyWriter, std::string(binary ? "binary" : "ascii") + ".vtk", readWithVTK<vtkPolyDataReader>);
  }
  add(vtkSmartPointer<vtkOBJWriter>::New(), "text.obj", readWithVTK<vtkOBJReader>);
  for (int mode : { 0, 1, 2, 3, 4 })
  {
    auto vtpWriter = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    mode == 0 ? vtpWriter->SetDataModeToAscii() : vtpWriter->SetDataModeToBinary();
    vtpWriter->SetHeaderTypeToUInt32();
    if (mode == 1)
    {
      vtpWriter->SetCompressorTypeToNone();
      vtpWriter->SetHeaderTypeToUInt64();
    }
    if (mode == 2)
    {
      vtpWriter->SetCompressorTypeToZLib();
    }
    if (mode == 3)
    {
      vtpWriter->SetCompressorTypeToLZ4();
    }
    if (mode == 4)
    {
      vtpWriter->SetCompressorTypeToLZMA();
      vtpWriter->SetBlockSize(256); // several blocks per array
    }
    add(vtpWriter, "mode" + std::to_string(mode) + ".vtp", readWithVTK<vtkXMLPolyDataReader>);
  }
  for (const Flavour& flavour : flavours)
  {
    vtkNew<vtkKerfMeshFileReader> kerfReader;
    kerfReader->SetFileName(flavour.file.c_str());
    error = kerf::test::UpdateAndCaptureError(kerfReader);
    std::cout << "read " << flavour.file << ": " << (error.empty() ? "ok" : error) << std::endl;
    ok &= KERF_CHECK(error.empty());
    vtkPolyData* kerfMesh = kerfReader->GetOutput();
    vtkSmartPointer<vtkPolyData> vtkMesh = flavour.readWithVTK(flavour.file);
    ok &= KERF_CHECK(vtkMesh && vtkMesh->GetNumberOfPoints() == kerfMesh->GetNumberOfPoints());
    ok &= KERF_CHECK(vtkMesh && vtkMesh->GetNumberOfPolys() == kerfMesh->GetNumberOfPolys());
    if (!vtkMesh || vtkMesh->GetNumberOfPoints() != kerfMesh->GetNumberOfPoints() ||
      vtkMesh->GetNumberOfPolys() != kerfMesh->GetNumberOfPolys())
    {
      continue;
    }
    for (vtkIdType i = 0; i < kerfMesh->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      kerfMesh->GetPoint(i, a);
      vtkMesh->GetPoint(i, b);
      if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
      {
        ok &= KERF_CHECK(false && "a point differs from VTK's reader");
        break;
      }
    }
    vtkNew<vtkIdList> kerfCell;
    vtkNew<vtkIdList> vtkCell;
    for (vtkIdType c = 0; c < kerfMesh->GetNumberOfPolys(); ++c)
    {
      kerfMesh->GetPolys()->GetCellAtId(c, kerfCell);
      vtkMesh->GetPolys()->GetCellAtId(c, vtkCell);
      bool same = kerfCell->GetNumberOfIds() == vtkCell->GetNumberOfIds();
      for (vtkIdType k = 0; same && k < kerfCell->GetNumberOfIds(); ++k)
      {
        same = kerfCell->GetId(k) == vtkCell->GetId(k);
      }
      if (!same)
      {
        ok &= KERF_CHECK(false && "a cell differs from VTK's reader");
        break;
      }
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
