// Conversion between kerf::TriangleMesh and OpenMesh, for algorithms that edit topology.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace kerf
{

/// OpenMesh's triangle mesh with double-precision points.
struct OpenMeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using EditableMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

/// Copies a mesh into OpenMesh's half-edge structure, keeping vertex and face numbering.
/// Throws kerf::Error if OpenMesh refuses a triangle (it accepts only manifold, consistently
/// oriented input; validate first).
EditableMesh toEditableMesh(const TriangleMesh& mesh);

/// Copies an OpenMesh mesh back, skipping deleted elements (call garbage_collection() first to
/// keep the numbering dense).
TriangleMesh fromEditableMesh(const EditableMesh& mesh);

} // namespace kerf
