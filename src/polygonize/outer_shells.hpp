#pragma once
// The shells of a polygonized surface that can be reached from infinity. A closed soup gives a
// thickened sheet: an outer shell and an inner one facing the hollow inside; a repair
// usually wants only the outer one.
#include <cstddef>
#include <vector>

#include "mesh/soup.hpp"
#include "polygonize/polygonize.hpp"

namespace convray::polygonize {

// The connected components of a mesh (triangles sharing a vertex index), as a component index
// per triangle; returns the number of components.
size_t triangle_components(const mesh::TriangleSoup& soup, std::vector<uint32_t>& component);

// Winding number of the closed, outward-oriented triangle mesh `shell` around p: 1 inside, 0
// outside, -1 inside an inward-facing shell (a hollow's wall). The sum of signed solid angles
// over 4 pi (Van Oosterom and Strackee), exact up to rounding for closed meshes.
double winding_number(const mesh::TriangleSoup& soup, const std::vector<uint32_t>& triangles,
                      const Vec3& p);

// Keeps the shells that border the unbounded outside region. A shell does when the points just
// outside it lie outside every shell, itself included: an outward-facing shell (positive
// volume) that no other shell encloses. Inner walls of hollows (negative volume) and anything
// inside a hollow go. Unused vertices are dropped. Returns the number of shells kept.
size_t keep_outer_shells(SurfaceMesh& mesh);

}  // namespace convray::polygonize
