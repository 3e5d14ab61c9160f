#pragma once
// Reading polygon soups from OBJ, PLY (ascii, binary little and big endian), STL (ascii,
// binary) and OFF files, each optionally gzip-compressed (`bunny.ply.gz`).
//
// The libraries do the parsing (tinyobjloader for OBJ, assimp 5.2 for PLY/STL/OFF), but they
// are lenient where we must not be: assimp reads past the end of a truncated binary PLY,
// clamps out-of-range OFF indices, and both silently turn missing numbers into zeros. So every
// file is first checked by our own scanner (src/mesh/*_check.cpp), and the result is checked
// again (finite coordinates, indices in range) before anyone sees it.
//
// Errors. Every problem with the input is a convray::InputError whose text reads
//
//     FILE[:LINE]: WHAT IS WRONG[ (ELEMENT N)]
//
//   FILE     the path (or, for load_mesh_from_memory, the name) exactly as given;
//   LINE     for text formats, the 1-based line the problem is on, where there is one;
//   ELEMENT  `vertex N` or `face N`: the element the problem is in, counted from 0 in the
//            order the file lists them (as PLY and OFF number them; in OBJ too, although
//            OBJ's own indices start at 1). An index a face refers to is quoted as the file
//            writes it. Example:
//                bunny.ply: face refers to vertex 90, but the file has 80 vertices (face 12)
//   Problems the library itself reports are wrapped as `FILE: PLY reader: <its message>`.
//
// Faces. Polygons with more than three corners are triangulated (ear clipping in the
// polygon's plane). Triangles whose three positions span no area (cross product exactly zero)
// and triangles that name one vertex twice are dropped and counted, not errors. A file that
// ends up with no triangle at all is an error.
//
// Precision. OBJ coordinates are read exactly (correctly rounded doubles). assimp stores
// positions as float32, so PLY, STL and OFF coordinates are rounded to float.
//
// Safety. No byte sequence makes these functions crash, hang or allocate without bound: gzip
// output is capped (see kMaxInflatedBytes) and counts in headers are checked against the
// bytes that are really there before anything is allocated. Fuzzed by fuzz/mesh_fuzz.cpp.
#include <cstddef>
#include <string>
#include <string_view>

#include "mesh/soup.hpp"

namespace convray::mesh {

// What reading did to the faces of the file.
struct LoadReport {
  size_t faces_read = 0;               // faces (polygons) in the file
  size_t triangles_kept = 0;           // triangles in the soup
  size_t polygons_triangulated = 0;    // faces with more than three corners
  size_t dropped_zero_area = 0;        // triangles whose corners are collinear or coincide
  size_t dropped_repeated_vertex = 0;  // triangles that name one vertex index twice
};

struct LoadedMesh {
  TriangleSoup soup;
  LoadReport report;
  std::string format;  // human-readable, e.g. "PLY binary little-endian, gzip-compressed"
};

// Reads the mesh at `path`; the extension (case-insensitive) selects the format.
LoadedMesh load_mesh(const std::string& path);

// Reads a mesh from bytes already in memory. `name` selects the format by its extension,
// exactly as a path would, and is the FILE of error messages.
LoadedMesh load_mesh_from_memory(std::string_view bytes, const std::string& name);

}  // namespace convray::mesh
