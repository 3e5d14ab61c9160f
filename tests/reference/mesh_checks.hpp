#pragma once
// Independent checks of triangle meshes for the polygonizer's tests: brute force, written
// without any of the code under test.
#include <array>
#include <cstddef>
#include <vector>

#include "util/math.hpp"

namespace convray::reference {

struct IndexedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Pairs of triangles that cross each other: for pairs sharing no vertex, any edge of one
// piercing the other; for pairs sharing one vertex, an edge opposite the shared vertex
// piercing the other. (Pairs sharing an edge meet along it by construction.) Brute force over
// the pairs whose boxes overlap, found through a uniform grid.
size_t count_self_intersections(const IndexedMesh& mesh);

// Whether segment [p, q] meets triangle (a, b, c) at a point strictly inside both, up to a
// relative tolerance that ignores touching at the shared boundary.
bool segment_pierces_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c);

// The signed volume enclosed by an oriented closed mesh (divergence theorem).
double enclosed_volume(const IndexedMesh& mesh);

}  // namespace convray::reference
