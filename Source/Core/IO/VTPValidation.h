// A check of VTK XML PolyData (.vtp) files against what VTK's XML reader would allocate and read.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace kerf
{

/// Decompresses one block written by the VTK compressor `compressorName` (vtkZLibDataCompressor,
/// vtkLZ4DataCompressor or vtkLZMADataCompressor) into exactly `uncompressedSize` bytes; returns
/// false if the block does not decompress to that size. Supplied by the caller, so that the Core
/// stays free of compression libraries.
using XMLBlockDecompressor = std::function<bool(const std::string& compressorName, std::string_view compressed,
  std::size_t uncompressedSize, std::string& uncompressed)>;

/// Checks a .vtp file the way VTK 9.2's vtkXMLPolyDataReader will read it, and throws
/// kerf::Error (naming the byte offset and the element) at the first thing that reader could not
/// survive: a declared count (NumberOfPoints, NumberOfPolys, ..., NumberOfTuples,
/// NumberOfComponents) beyond 2^31 - 1 or beyond the values the data actually holds (ASCII
/// words, the byte count in a binary header, the block table of compressed data), a compressed
/// block table that is inconsistent (no blocks, blocks larger than 2^30 bytes or than their
/// compressed size allows), an appended-data offset outside the appended data, a last cell offset
/// past the connectivity (VTK sizes the connectivity by it), unknown array types, compressors,
/// byte orders or header types, field-data arrays VTK cannot create, array information keys,
/// and malformed or too deeply nested XML. `decompress` reads the cell offsets of compressed files.
void checkVTP(std::string_view bytes, const XMLBlockDecompressor& decompress);

} // namespace kerf
