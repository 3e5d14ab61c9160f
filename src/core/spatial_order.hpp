#pragma once
// An order of points along a space-filling curve (Morton's Z-order over their bounding box,
// 21 bits an axis): points near each other in space come mostly near each other in the
// order. Whoever keeps many primitives that a ray or a point query meets together (a mesh's
// triangles in a convolution surface) stores them in this order, so that a query's
// primitives lie near each other in memory. Deterministic: ties keep their given order.
#include <cstdint>
#include <span>
#include <vector>

#include "util/math.hpp"

namespace convray {

// The indices of `points` sorted by their Morton code. Non-finite points go last.
std::vector<uint32_t> spatial_order(std::span<const Vec3> points);

}  // namespace convray
