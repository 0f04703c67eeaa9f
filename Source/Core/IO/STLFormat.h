// Kerf's own STL parser (ASCII and binary), safe for any byte sequence.
#pragma once

#include "IO/MeshFileData.h"

#include <string_view>

namespace kerf
{

/// Parses an STL file held in memory into single-precision points and triangles.
///
/// Binary when the size is 84 + 50 * (the header's triangle count), or when the file does not
/// start with "solid" followed by text; ASCII otherwise. A binary header count larger than the
/// file is an error; a count of 0, or one whose facets do not fill the file, is replaced by the
/// number of whole facets the file holds when those fill it exactly (exporters often write 0);
/// otherwise trailing bytes after the counted facets are ignored. ASCII: solid, facet normal,
/// outer loop, three vertex lines, endloop, endfacet, endsolid (keywords in any case, several
/// solids, an optional color line); a missing final endsolid is tolerated.
/// Corners with identical coordinates are merged into one point (as VTK's STL reader does), and
/// facets whose corners merge are dropped.
/// Throws kerf::Error naming the line or byte offset of the first problem.
MeshFileData parseSTL(std::string_view bytes);

} // namespace kerf
