#pragma once
// The format readers behind load_mesh, our own, each written from its format's
// specification. Each returns the file's vertices, faces, lines and points as it lists them
// (indices counted from 0), or throws InputError; build_soup() then validates, triangulates
// and splits lines into segments. Internal to src/mesh.
#include <string>
#include <string_view>

#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

// OBJ (src/mesh/obj_reader.cpp): `v`, `f`, `l` and `p` lines; text as UTF-8, or UTF-16
// with a byte-order mark.
PolygonMesh read_obj(std::string_view text, const std::string& file);

// PLY (src/mesh/ply_reader.cpp): text, binary little- and big-endian.
PolygonMesh read_ply(std::string_view bytes, const std::string& file);

// STL (src/mesh/stl_reader.cpp): text and binary.
PolygonMesh read_stl(std::string_view bytes, const std::string& file);

// OFF (src/mesh/off_reader.cpp): text and binary, with the optional prefixes.
PolygonMesh read_off(std::string_view bytes, const std::string& file);

}  // namespace convray::mesh
