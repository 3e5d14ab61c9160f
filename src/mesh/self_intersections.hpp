#pragma once
// Which faces of a triangle mesh intersect each other where a mesh may not (beyond the corners
// they share; see faces_intersect in mesh/triangle_contact.hpp), decided exactly. Candidate
// pairs come from a uniform grid over the faces' boxes, searched on TBB threads; every pair
// whose boxes overlap is tested, so nothing is missed. `convray info --self-intersections`
// reports it; the polygonizer's tests and the library evaluation count with it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/soup.hpp"

namespace convray::mesh {

struct SelfIntersections {
  size_t pairs = 0;       // pairs of faces that intersect
  size_t flat_faces = 0;  // faces with collinear corners: they have no plane and are not tested
  // The first intersecting pairs in (lower face, higher face) order, at most the number asked.
  std::vector<std::array<uint32_t, 2>> examples;
};

SelfIntersections find_self_intersections(const TriangleSoup& soup, size_t max_examples = 8);

// The same answer by testing every pair of faces: the slow exact twin for the tests.
SelfIntersections find_self_intersections_brute_force(const TriangleSoup& soup,
                                                      size_t max_examples = 8);

}  // namespace convray::mesh
