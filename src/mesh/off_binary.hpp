#pragma once
// Binary OFF, and what the OFF keyword says about each vertex. Internal to src/mesh.
#include <cstdint>
#include <string>
#include <string_view>

#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

// What the keyword's prefixes ([ST][C][N][4][n]OFF) and a BINARY after it say.
struct OffLayout {
  bool texture = false;      // ST: two texture coordinates
  bool colour = false;       // C: a colour
  bool normal = false;       // N: three normal components
  bool homogeneous = false;  // 4: a fourth coordinate w
  bool dimension = false;    // n: the dimension comes before the counts
  bool binary = false;

  int coordinates() const { return homogeneous ? 4 : 3; }
  // Binary only: the float32s per vertex (colours are RGBA there).
  uint64_t floats_per_vertex() const { return coordinates() + (normal ? 3 : 0) + (colour ? 4 : 0) + (texture ? 2 : 0); }
};

// The data after the `OFF BINARY` line, from `start`. Geomview defines it: big-endian int32
// counts (vertices, faces, edges), per vertex its float32s, per face an int32 corner count,
// the int32 indices, an int32 colour count and that many float32s. pmp-library (and the
// programs of its lineage) write it little-endian and without the colour counts. Each of the
// four readings is tried, Geomview's first, and the one that reads the file to its end
// (trailing whitespace aside) is taken; if none does, Geomview's reading's error is reported.
PolygonMesh read_binary_off(std::string_view bytes, size_t start, const OffLayout& layout, const std::string& file);

}  // namespace convray::mesh
