#pragma once
// Our own scan of an OBJ file, done before tinyobjloader reads it, because tinyobjloader
// forgives too much: a missing or unparsable coordinate becomes 0, a face with fewer than
// three corners vanishes, "3x" reads as 3, and its number parser is not correctly rounded.
// The scan reads only what convray uses (`v` and `f` lines) and is strict about it.
// Internal to src/mesh.
#include <string>
#include <string_view>

#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

// The exact vertex positions and every face's corners as 0-based indices, with relative
// (negative) indices resolved. Throws InputError, with the line, for the first problem.
PolygonMesh scan_obj(std::string_view text, const std::string& file);

}  // namespace convray::mesh
