// Converts a Core triangle mesh to the vtkPolyData the benchmarked filters read.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace kerf
{
namespace benchmarks
{

/// A vtkPolyData with the mesh's points (double) and its triangles as polygons, in the same order.
vtkSmartPointer<vtkPolyData> MakePolyData(const TriangleMesh& mesh);

} // namespace benchmarks
} // namespace kerf
