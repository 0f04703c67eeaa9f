// Parsers and writers for the OFF mesh format and the Princeton benchmark .seg format.
#pragma once

#include "Mesh/PolygonMesh.h"

#include <string>
#include <vector>

namespace kerf
{

/// Parses ASCII OFF (with the optional C/N/ST/4 prefixes of the header ignored beyond their
/// extra columns; per-vertex and per-face colours are skipped). Comments start with '#'.
/// Throws kerf::Error naming the line for truncated or malformed files and for indices out of
/// range. Binary OFF is refused.
PolygonMesh parseOFF(const std::string& text);
PolygonMesh readOFF(const std::string& fileName);

/// Writes ASCII OFF with 17 significant digits (lossless for doubles).
void writeOFF(const std::string& fileName, const PolygonMesh& mesh);

/// Parses a .seg file: one integer per line, line i being the segment id of face i.
/// Blank lines are ignored; anything else that is not an integer is an error naming the line.
std::vector<int> parseSegmentation(const std::string& text);
std::vector<int> readSegmentation(const std::string& fileName);
void writeSegmentation(const std::string& fileName, const std::vector<int>& labels);

/// Reads a whole file into a string; throws kerf::Error if it cannot be opened.
std::string readTextFile(const std::string& fileName);

} // namespace kerf
