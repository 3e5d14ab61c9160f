#include "mesh/soup.hpp"

namespace convray::mesh {

Box3 TriangleSoup::bounds() const {
  Box3 box;
  for (const Triangle& tri : triangles) {
    for (uint32_t index : tri) box.extend(vertices[index]);
  }
  return box;
}

}  // namespace convray::mesh
