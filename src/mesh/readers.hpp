#pragma once
// The format readers behind load_mesh. Each returns the file's faces as it lists them, or
// throws InputError; build_soup() then validates and triangulates. Internal to src/mesh.
#include <string>
#include <string_view>

#include "mesh/format.hpp"
#include "mesh/polygon_mesh.hpp"

namespace convray::mesh {

// OBJ through tinyobjloader, checked by scan_obj() (src/mesh/obj_check.hpp).
PolygonMesh read_obj(std::string_view text, const std::string& file);

// PLY, STL or OFF through assimp, after the checks of src/mesh/{ply,stl,off}_check.hpp.
PolygonMesh read_with_assimp(std::string_view bytes, MeshFormat format, const std::string& file);

}  // namespace convray::mesh
