#pragma once
// Our own walk over a PLY file before assimp reads it. assimp reads past the end of a
// truncated binary PLY, takes a face's missing indices from whatever follows, and passes
// out-of-range indices through; so we check the header against the bytes that are really
// there, element by element, and read the faces ourselves to compare with assimp's.
// Internal to src/mesh.
#include <cstdint>
#include <string>
#include <string_view>

#include "mesh/ply_header.hpp"
#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

struct PlyContents {
  PlyEncoding encoding = PlyEncoding::Ascii;
  uint64_t vertex_count = 0;
  PolygonMesh faces;  // every face's corners, checked to be in range; no vertices
};

// Throws InputError for a malformed header, a body that does not match it (too short,
// values of the wrong kind, lines with too few or too many values), a face with fewer than
// three corners or an index out of range.
PlyContents check_ply(std::string_view bytes, const std::string& file);

}  // namespace convray::mesh
