// Kerf's own Wavefront OBJ parser for polygonal geometry, safe for any byte sequence.
#pragma once

#include "IO/MeshFileData.h"

#include <string_view>

namespace kerf
{

/// Parses an OBJ file held in memory: v (x y z; further numbers are ignored), vt, vn, f (corners
/// v, v/vt, v/vt/vn or v//vn, at least 3), l (at least 2 corners) and p; other statements (g, o,
/// s, usemtl, mtllib, ...) are ignored. Indices start at 1; negative ones count back from the
/// last element defined so far; every index, texture and normal ones included, must name an
/// element the file defines. Coordinates are read as written, "nan" and "inf" included (Kerf's
/// filters refuse such surfaces with their own message). Texture coordinates (TCoords) and
/// normals (Normals) become point arrays when every face corner gives one and each point always
/// gets the same one. Line continuations ('\') are refused.
/// Throws kerf::Error naming the line of the first problem.
MeshFileData parseOBJ(std::string_view bytes);

} // namespace kerf
