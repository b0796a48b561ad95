// The pre-scan of a particles.vtp before VTK reads it (docs/reliability.md,
// "Restart files are validated before they are read"). VTK's XML reader trusts
// the header: a negative NumberOfPoints, a block shorter than its array, or
// offsets pointing outside the connectivity crash it. This small scanner
// accepts only the form VtpFile writes (docs/design.md 1.3):
//
//   - an XML header of the elements VTKFile (type PolyData, LittleEndian,
//     header_type UInt64, no compressor), PolyData, FieldData, one Piece,
//     PointData, CellData, Points, Verts, Lines, Strips, Polys, DataArray;
//     no DOCTYPE, entity, processing instruction (but <?xml?>) or text;
//   - Piece counts: NumberOfPoints = NumberOfVerts >= 0, no lines, strips
//     or polygons;
//   - every DataArray: a numeric type, format appended, an offset, 1 to 9
//     components, and the number of values its place implies (NumberOfPoints
//     for point data and points, NumberOfTuples for field data, the vertex
//     count for Verts); Points holds one 3-component array;
//   - raw appended data: each block's UInt64 byte count equals values x
//     components x size of the type and the block lies inside the file, which
//     ends with </AppendedData> </VTKFile> after the last block;
//   - the vertex cells are point 0..n-1 one each (offsets 1..n, connectivity
//     in range).
// Dictionary keys read: none.
#pragma once
#include <cstdint>
#include <string>

namespace shizuku {

struct VtpLayout {
  std::int64_t points = 0;  // NumberOfPoints, agreed by every point array's block size
};

// Throws InputError "corrupt particle file '<path>': <why>".
[[noreturn]] void corruptVtp(const std::string& path, const std::string& why);

// Throws InputError "corrupt particle file '<path>': <what is wrong>" (naming
// the element, attribute or array) on anything else.
VtpLayout scanVtpLayout(const std::string& path);

}  // namespace shizuku
