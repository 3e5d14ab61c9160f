#include "reference/mesh_checks.hpp"

namespace convray::reference {

double enclosed_volume(const IndexedMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    volume += glm::dot(mesh.vertices[t[0]], glm::cross(mesh.vertices[t[1]], mesh.vertices[t[2]]));
  }
  return volume / 6.0;
}

}  // namespace convray::reference
