#pragma once
// Our own walk over an OFF file before assimp reads it. assimp's OFF reader clamps
// out-of-range indices to the last vertex, reads missing indices as 0, drops faces of more
// than nine corners, allocates whatever the header's counts say before reading anything,
// and copies each line into a 4096-byte stack buffer. The walk reads the file the way
// assimp will (line by line after the header), but strictly. Internal to src/mesh.
#include <cstdint>
#include <string>
#include <string_view>

#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

struct OffContents {
  uint64_t vertex_count = 0;
  PolygonMesh faces;  // every face's corners, checked to be in range; no vertices
};

// Lines longer than this are refused: assimp's line buffer holds 4096 bytes, terminator
// included, and writes one past it for longer lines.
inline constexpr size_t kMaxOffLineLength = 4000;

// Throws InputError (with the line) for a malformed or truncated file.
OffContents check_off(std::string_view bytes, const std::string& file);

}  // namespace convray::mesh
