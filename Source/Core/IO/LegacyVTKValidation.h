// A check of legacy VTK polydata files against what VTK's legacy reader would allocate and read.
#pragma once

#include <string_view>

namespace kerf
{

/// Walks a legacy VTK file (ASCII or binary, cells in the 4.x "n id id id" layout or the 5.x
/// OFFSETS/CONNECTIVITY layout) token by token the way VTK 9.2's vtkPolyDataReader reads it, and
/// throws kerf::Error, naming the line and byte offset, at the first thing that reader could not
/// survive or would read wrongly: a count (points, cells, tuples, components, lookup-table
/// entries, field arrays, string lengths) that is negative or larger than the bytes left,
/// binary data running past the end, ASCII values that are not numbers of the declared type
/// (VTK's stream reader stops at "nan" and leaves the rest uninitialised), a 4.x cell claiming
/// more indices than its section holds, 5.x offsets that do not start at 0, decrease or end
/// elsewhere than the connectivity size, attribute counts that differ from the points or cells,
/// malformed %XX escapes in names, "INFORMATION" metadata with keys, and anything the walk does
/// not know. Only DATASET POLYDATA is accepted. Returns when VTK's reader may read the file.
void checkLegacyVTK(std::string_view bytes);

} // namespace kerf
