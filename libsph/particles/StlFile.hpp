// Reading an STL file (ASCII or binary, told apart by VTK's vtkSTLReader) into points and
// triangles, coincident points merged (the reader's default), degenerate triangles
// dropped, and the count of its open edges: vtkFeatureEdges' boundary edges (used by one
// triangle) plus non-manifold ones (used by more than two); a closed surface has none.
// The coordinates are the file's, in its units; the caller scales, rotates and
// translates them (ShapeRegion.cpp). Reads no keys.
#pragma once
#include "core/types.hpp"
#include <array>
#include <string>
#include <vector>

namespace shizuku {

struct StlMesh {
  std::vector<Vec<3>> points;
  std::vector<std::array<int, 3>> triangles;
  long openEdges = 0;
};

// "" on success, else what went wrong: the file is missing, unreadable or empty, VTK's
// message, or it holds no triangle. The caller names the file and the keyword.
std::string readStl(const std::string& path, StlMesh& mesh);

}  // namespace shizuku
