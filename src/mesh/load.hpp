#pragma once
// Reading skeletons from OBJ, PLY (ascii, binary little and big endian), STL (ascii, binary)
// and OFF (text and binary) files, each optionally gzip-compressed (`bunny.ply.gz`). A file
// gives triangles (its polygons, triangulated), segments (OBJ `l` polylines, PLY `edge`
// elements) and points (OBJ `p`; or every vertex of a file with no faces and no lines, a
// point cloud), all over one array of vertices. docs/mesh-input.md is the user's view.
//
// The readers are our own (src/mesh/*_reader.cpp), written from the formats' specifications
// and streaming: one pass over the bytes, nothing allocated that the bytes do not pay for.
// Every file is read strictly, and the result is checked again (finite coordinates, indices
// in range) before anyone sees it.
//
// Errors. Every problem with the input is a convray::InputError whose text reads
//
//     FILE[:LINE]: WHAT IS WRONG[ (ELEMENT N)]
//
//   FILE     the path (or, for load_mesh_from_memory, the name) exactly as given;
//   LINE     for text formats, the 1-based line the problem is on, where there is one;
//   ELEMENT  `vertex N`, `face N`, `line N` (a polyline, or a PLY edge) or another PLY
//            element: the element the problem is in, counted from 0 in the order the file
//            lists them (as PLY and OFF number them; in OBJ too, although OBJ's own indices
//            start at 1). An index a face refers to is quoted as the file writes it. Example:
//                bunny.ply:15: face refers to vertex 90, but the file has 80 vertices (face 12)
//
// Faces. Polygons with more than three corners are triangulated (ear clipping in the
// polygon's plane). Triangles whose three positions span no area (cross product exactly zero)
// and triangles that name one vertex twice are dropped and counted, not errors; so are
// segments whose two ends coincide. A file that ends up with nothing to render (no triangle,
// segment or point) is an error.
//
// Precision. Coordinates keep the precision the file gives them: text is read exactly
// (correctly rounded doubles), except PLY values declared `float`, which are rounded to
// float32 as their binary form would be; binary float32 and float64 values are exact.
//
// Safety. No byte sequence makes these functions crash, hang or allocate without bound: gzip
// output is capped (see kMaxInflatedBytes) and counts in headers are checked against the
// bytes that are really there before anything is allocated. Fuzzed by fuzz/mesh_fuzz.cpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/soup.hpp"

namespace convray::mesh {

using Segment = std::array<uint32_t, 2>;  // two vertex indices

// What reading did to the faces and lines of the file.
struct LoadReport {
  size_t faces_read = 0;               // faces (polygons) in the file
  size_t triangles_kept = 0;           // triangles in the soup
  size_t polygons_triangulated = 0;    // faces with more than three corners
  // Faces dropped whole, no triangle of theirs spanning an area: those that name one vertex
  // index twice, and the others (corners collinear or coincident).
  size_t dropped_zero_area = 0;
  size_t dropped_repeated_vertex = 0;
  size_t lines_read = 0;               // polylines (OBJ `l`) and edges (PLY `edge`)
  size_t segments_kept = 0;            // segments of those lines
  size_t dropped_zero_length = 0;      // segments whose two ends coincide
  bool point_cloud = false;            // no faces and no lines: every vertex is a point
};

struct LoadedMesh {
  TriangleSoup soup;              // the vertices, and the triangles
  std::vector<Segment> segments;  // indices into soup.vertices
  std::vector<uint32_t> points;   // indices into soup.vertices
  LoadReport report;
  std::string format;  // human-readable, e.g. "PLY binary little-endian, gzip-compressed"

  // Box around everything that gets rendered: triangles' corners, segments' ends, points.
  Box3 bounds() const;
};

// Reads the mesh at `path`; the extension (case-insensitive) selects the format.
LoadedMesh load_mesh(const std::string& path);

// Whether load_mesh reads a file of this name (.obj .ply .stl .off, optionally .gz, in any
// case): its extension only, the file is not opened.
bool is_mesh_file_name(const std::string& name);

// Reads a mesh from bytes already in memory. `name` selects the format by its extension,
// exactly as a path would, and is the FILE of error messages.
LoadedMesh load_mesh_from_memory(std::string_view bytes, const std::string& name);

// Scales and centres everything (triangles, segments, points) as fit_into_box does a soup.
void fit_into_box(LoadedMesh& mesh, double size);

// For commands that need a surface of triangles: throws InputError `FILE: WHAT needs
// triangles, but the file has none (N segments, M points)` when the mesh has no triangle.
void require_triangles(const LoadedMesh& mesh, const std::string& file, const std::string& what);

}  // namespace convray::mesh
