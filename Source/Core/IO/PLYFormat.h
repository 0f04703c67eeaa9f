// Kerf's own PLY parser (ASCII and binary of either byte order), safe for any byte sequence.
#pragma once

#include "IO/MeshFileData.h"

#include <string_view>

namespace kerf
{

/// Parses a PLY file held in memory. The header must declare a "vertex" element with scalar x, y
/// and z and a "face" element with a vertex_indices (or vertex_index) list of an integer type;
/// other elements and properties are read past, elements may come in any order. Every count is
/// checked against the bytes that remain before anything is allocated, every face index against
/// the vertex count, and a face needs at least 3 corners. ASCII rows are one per line.
/// Point arrays: Normals (nx, ny, nz), RGB or RGBA (red, green, blue[, alpha], or diffuse_*),
/// TCoords (u, v or texture_u, texture_v); face arrays: RGB/RGBA and intensity.
/// Throws kerf::Error naming the header line, data line or byte offset of the first problem.
MeshFileData parsePLY(std::string_view bytes);

} // namespace kerf
