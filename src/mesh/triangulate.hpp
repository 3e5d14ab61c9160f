#pragma once
// Splitting one planar-ish polygon into triangles. Internal to src/mesh.
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/soup.hpp"

namespace convray::mesh {

// Appends to `out` the triangles of the polygon whose corners are `corners` (indices into
// `positions`, already checked to be in range). Convex polygons come out as a fan from the
// first corner, the way exporters expect; concave ones are ear-clipped in the polygon's
// plane. Self-intersecting or degenerate polygons, and polygons with more corners than ear
// clipping is allowed to spend quadratic time on, fall back to the fan.
void triangulate_polygon(std::span<const uint32_t> corners, const std::vector<Vec3>& positions,
                         std::vector<Triangle>& out);

}  // namespace convray::mesh
