// Builds a vtkPolyData from what Kerf's own mesh-file parsers return.
#pragma once

#include "IO/MeshFileData.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace kerf
{

/// Points (float when the file stores floats), vertices, lines, polygons and the arrays: normals
/// and texture coordinates set as such, colours as unsigned char (values clamped to 0..255) and
/// set as the active scalars.
vtkSmartPointer<vtkPolyData> MeshFileDataToPolyData(const MeshFileData& data);

} // namespace kerf
