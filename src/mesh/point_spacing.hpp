#pragma once
// How far apart a point cloud's points are: the mean distance from each point to its nearest
// neighbour, the natural unit of a point skeleton's kernel radius (`convray info`).
#include <vector>

#include "util/math.hpp"

namespace convray::mesh {

// The mean, over the points, of the distance from each to the nearest point at another
// position (a repeated position is not its own neighbour). 0 when all points share one
// position. A k-d tree searched on all cores: O(n log n) whatever the cloud's shape.
double mean_point_spacing(const std::vector<Vec3>& points);

}  // namespace convray::mesh
