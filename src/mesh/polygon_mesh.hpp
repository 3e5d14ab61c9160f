#pragma once
// What every format reader produces: positions and faces exactly as the file lists them,
// before triangulation and before our validation. Internal to src/mesh.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/load.hpp"
#include "util/math.hpp"

namespace convray::mesh {

struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<int64_t> corners;   // vertex indices of every face, one face after the other
  std::vector<size_t> face_ends;  // face f owns corners [face_ends[f-1], face_ends[f])
  std::string format;             // e.g. "PLY binary little-endian"
  bool vertex_per_corner = false; // STL: vertex 3f+k is corner k of face f; errors name the face

  size_t face_count() const { return face_ends.size(); }
  std::span<const int64_t> face(size_t f) const {
    size_t begin = f == 0 ? 0 : face_ends[f - 1];
    return {corners.data() + begin, face_ends[f] - begin};
  }
  void add_face(std::span<const int64_t> face_corners) {
    corners.insert(corners.end(), face_corners.begin(), face_corners.end());
    face_ends.push_back(corners.size());
  }
};

// Checks what no reader is trusted with (finite coordinates, faces of at least three
// corners, indices in range), triangulates polygons and drops degenerate triangles.
// Throws InputError, named after `file`, for the first problem found.
LoadedMesh build_soup(PolygonMesh polygons, const std::string& file);

}  // namespace convray::mesh
