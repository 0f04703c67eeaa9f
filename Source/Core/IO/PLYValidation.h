// Checks a PLY file's structure before VTK's PLY reader, which crashes on truncated files.
#pragma once

#include <string>

namespace kerf
{

/// Walks a PLY file (ASCII or binary, either byte order) without storing it and returns a
/// sentence naming the first structural problem, or "" when every element the header declares is
/// present and complete: a "vertex" element with x, y and z and a "face" element with a
/// vertex_indices (or vertex_index) list. Index values are not checked here.
std::string checkPLYStructure(const std::string& fileName);

} // namespace kerf
