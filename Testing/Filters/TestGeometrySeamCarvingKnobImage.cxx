// Regression image: the tube with one knob (Geometry Seams with its defaults) stretched by a quarter of its modeling
// region, elastic editing (Plastic off, left) beside geometry seam carving (right), coloured by ring seam; the
// knob's edges change far less with seam carving (asserted).
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkGeometrySeamCarving.h"
#include "vtkGeometrySeams.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace
{
// The largest |l' / l - 1| over the input edges between two knob points.
double largestKnobChange(const kerf::TriangleMesh& mesh, const std::vector<int>& knob, vtkPolyData* output)
{
  const std::vector<vtkIdType> outputOf = kerf::test::OutputPointOfInput(output, mesh.vertexCount());
  std::vector<char> onKnob(static_cast<std::size_t>(mesh.vertexCount()), 0);
  for (int v : knob)
  {
    onKnob[static_cast<std::size_t>(v)] = 1;
  }
  double largest = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::size_t a = static_cast<std::size_t>(mesh.edgeVertices(e)[0]);
    const std::size_t b = static_cast<std::size_t>(mesh.edgeVertices(e)[1]);
    if (onKnob[a] && onKnob[b])
    {
      if (outputOf[a] < 0 || outputOf[b] < 0)
      {
        return 1e300; // a knob point was collapsed away
      }
      double p[3], q[3];
      output->GetPoint(outputOf[a], p);
      output->GetPoint(outputOf[b], q);
      const double now =
        std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
      largest = std::max(
        largest, std::abs(now / (mesh.point(static_cast<int>(a)) - mesh.point(static_cast<int>(b))).norm() - 1.0));
    }
  }
  return largest;
}
} // namespace

int TestGeometrySeamCarvingKnobImage(int argc, char* argv[])
{
  const kerf::TriangleMesh mesh = kerf::makeFeatureTube(kerf::TubeFeature::Knob, 64, 81);
  vtkNew<vtkGeometrySeams> seams;
  seams->SetInputData(kerf::test::WithRegions(mesh, kerf::heightBandRegions(mesh, 0.8, 4.2)));
  vtkNew<vtkTransform> handle;
  vtkSmartPointer<vtkPolyData> results[2];
  double change[2];
  for (int plastic = 0; plastic < 2; ++plastic)
  {
    vtkNew<vtkGeometrySeamCarving> carving;
    carving->SetInputConnection(seams->GetOutputPort());
    carving->SetHandleTransform(handle);
    carving->SetPlastic(plastic == 1);
    for (int step = 1; step <= 4; ++step)
    {
      handle->Identity();
      handle->Translate(0.0, 0.0, -0.85 * step / 4.0);
      if (!kerf::test::UpdateAndCaptureError(carving).empty())
      {
        return EXIT_FAILURE;
      }
    }
    results[plastic] = carving->GetOutput();
    change[plastic] = largestKnobChange(mesh, kerf::featureTubePoints(mesh), results[plastic]);
  }
  std::cout << "largest change of a knob edge: elastic " << change[0] << ", seam carving " << change[1] << std::endl;
  if (!(change[1] < 0.5 * change[0]))
  {
    std::cerr << "seam carving changes the knob more than half as much as elastic editing" << std::endl;
    return EXIT_FAILURE;
  }

  return kerf::test::SeamCarvingPairImageTest(
    argc, argv, results[0], "Elastic (Plastic off)", results[1], "Seam carving");
}
