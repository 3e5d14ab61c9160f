#pragma once
// What every format reader produces: positions, faces, polylines and points exactly as the
// file lists them, before triangulation and before our validation. Internal to src/mesh.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/load.hpp"
#include "util/math.hpp"

namespace convray::mesh {

// Index lists one after the other: list i owns items [ends[i-1], ends[i]).
struct IndexLists {
  std::vector<int64_t> items;
  std::vector<size_t> ends;

  size_t size() const { return ends.size(); }
  std::span<const int64_t> operator[](size_t i) const {
    size_t begin = i == 0 ? 0 : ends[i - 1];
    return {items.data() + begin, ends[i] - begin};
  }
  void add(std::span<const int64_t> list) {
    items.insert(items.end(), list.begin(), list.end());
    ends.push_back(items.size());
  }
};

struct PolygonMesh {
  std::vector<Vec3> vertices;
  IndexLists faces;               // polygons: vertex indices, counted from 0
  IndexLists lines;               // polylines (OBJ `l`, PLY `edge`): consecutive corners joined
  std::vector<int64_t> points;    // vertices the file names as points (OBJ `p`)
  std::string format;             // e.g. "PLY binary little-endian"
  bool vertex_per_corner = false; // STL: vertex 3f+k is corner k of face f; errors name the face

  size_t face_count() const { return faces.size(); }
  std::span<const int64_t> face(size_t f) const { return faces[f]; }
  void add_face(std::span<const int64_t> face_corners) { faces.add(face_corners); }
};

// Checks what no reader is trusted with (finite coordinates, faces of at least three
// corners, lines of at least two, indices in range), triangulates polygons, splits polylines
// into segments and drops degenerate triangles and segments. A file with no face, line or
// point at all is a point cloud: every vertex is a point. Throws InputError, named after
// `file`, for the first problem found.
LoadedMesh build_soup(PolygonMesh polygons, const std::string& file);

}  // namespace convray::mesh
