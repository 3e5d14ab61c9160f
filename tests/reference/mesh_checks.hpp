#pragma once
// Independent checks of triangle meshes for the polygonizer's tests, written without any of
// the code under test.
#include <array>
#include <cstddef>
#include <vector>

#include "util/math.hpp"

namespace convray::reference {

struct IndexedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// The signed volume enclosed by an oriented closed mesh (divergence theorem).
double enclosed_volume(const IndexedMesh& mesh);

}  // namespace convray::reference
