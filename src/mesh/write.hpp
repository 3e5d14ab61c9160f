#pragma once
// Writing triangle soups as OBJ, PLY, STL or OFF, chosen by the extension of the path.
// Our own small writers (no assimp export), at full precision: text formats print the
// shortest decimal that reads back as the same double; binary PLY stores doubles; binary
// STL can only store float32, so coordinates are rounded to float there.
//
// The file appears complete or not at all: everything is written to a temporary file next
// to it, which is then renamed over the path.
#include <string>
#include <vector>

#include "mesh/soup.hpp"

namespace convray::mesh {

enum class MeshEncoding {
  Default,  // OBJ and OFF: text; PLY: binary little-endian; STL: binary
  Ascii,
  Binary,   // PLY: binary little-endian; STL: binary. OBJ and OFF have none (an error).
};

// With `vertex_normals` (one per vertex), OBJ gets `vn` lines and faces `f a//a b//b c//c`,
// PLY gets nx, ny, nz properties; STL keeps its facet normals and OFF has none.
// Throws InputError for an unknown extension (or `.gz`, which is not written), an encoding
// the format does not have, or a file that cannot be written.
void save_mesh(const TriangleSoup& soup, const std::string& path,
               MeshEncoding encoding = MeshEncoding::Default,
               const std::vector<Vec3>* vertex_normals = nullptr);

}  // namespace convray::mesh
