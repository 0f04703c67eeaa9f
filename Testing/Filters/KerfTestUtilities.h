// Helpers shared by Kerf's VTK filter tests: Core meshes as vtkPolyData, data paths, error capture.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkKerfMeshFileReader;
class vtkPolyDataAlgorithm;
class vtkPolyData;

namespace kerf
{
namespace test
{

/// A vtkPolyData with the mesh's points (double) and triangles.
vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& mesh);

/// ToPolyData with the per-point seam-carving regions as the point array "Region".
vtkSmartPointer<vtkPolyData> WithRegions(const TriangleMesh& mesh, const std::vector<double>& regions);

/// A circle of radius r at height z around the z axis, as one closed polyline of `points`
/// points (the last repeats the first).
vtkSmartPointer<vtkPolyData> CirclePolyline(double r, double z, int points);

/// The path of a file in the source tree, given the -D argument of the test driver.
std::string SourcePath(int argc, char* argv[], const std::string& relative);

/// Readers of the bundled camel (Data/camel.off) and its neck stroke (Data/camel-neck-stroke.vtk).
struct CamelWithNeckStroke
{
  vtkSmartPointer<vtkKerfMeshFileReader> camel;
  vtkSmartPointer<vtkKerfMeshFileReader> stroke;
};
CamelWithNeckStroke ReadCamelWithNeckStroke(int argc, char* argv[]);

/// The regression image of an automatic segmentation of the bundled camel: `segmentation` (a
/// configured filter writing the cell array "Segment") gets Data/camel.off and its output is drawn
/// from one camera with categorical colours; returns the test's exit code.
int CamelSegmentationImageTest(int argc, char* argv[], vtkPolyDataAlgorithm* segmentation);

/// Per input point, the output point whose OriginalPointId names it (-1 if none: collapsed away),
/// for the outputs of Geometry Seam Carving.
std::vector<vtkIdType> OutputPointOfInput(vtkPolyData* output, int inputPoints);

/// The regression image of two Geometry Seam Carving results side by side, coloured by ring seam
/// from one camera looking at the tube's side; returns the test's exit code.
int SeamCarvingPairImageTest(
  int argc, char* argv[], vtkPolyData* left, const char* leftCaption, vtkPolyData* right, const char* rightCaption);

/// The shared research data folder (../shared/data), or "" if absent.
std::string SharedDataPath(const std::string& relative);

/// Runs the algorithm and returns the error message it reported, or "" if it succeeded.
/// Errors are captured, so they do not print "ERROR:" and fail the test.
/// `succeeded` receives the executive's return value (1 on success, 0 on failure).
std::string UpdateAndCaptureError(vtkAlgorithm* algorithm, int* succeeded = nullptr);

/// Reports a failed check with its location; returns the condition.
bool Check(bool condition, const char* what, const char* file, int line);

} // namespace test
} // namespace kerf

#define KERF_CHECK(condition) kerf::test::Check((condition), #condition, __FILE__, __LINE__)
