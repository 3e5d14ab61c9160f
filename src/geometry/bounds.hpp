#pragma once
// Boxes that may be empty or reach to infinity (planes, inverted solids), and the slab test
// that narrows a ray's interval to a box.
#include <limits>

#include "implicit/ray.hpp"
#include "implicit/ray_box.hpp"
#include "scene/transform.hpp"
#include "util/math.hpp"

namespace convray::geometry {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

inline Box3 infinite_box() { return Box3{Vec3(-kInfinity), Vec3(kInfinity)}; }

inline bool is_empty(const Box3& box) { return box.empty(); }

// Non-empty and bounded on every side.
inline bool is_finite(const Box3& box) {
  if (is_empty(box)) return false;
  for (int axis = 0; axis < 3; ++axis) {
    if (box.lo[axis] == -kInfinity || box.hi[axis] == kInfinity) return false;
  }
  return true;
}

inline Box3 hull(const Box3& a, const Box3& b) {
  if (is_empty(a)) return b;
  if (is_empty(b)) return a;
  return Box3{glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

inline Box3 overlap(const Box3& a, const Box3& b) {
  return Box3{glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

inline bool contains(const Box3& box, const Vec3& p) {
  return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y &&
         p.z >= box.lo.z && p.z <= box.hi.z;
}

// The box around the image of `box` under `transform` (object -> placed space). Infinite
// sides stay infinite along every axis they reach; zero matrix entries never make 0 * inf.
Box3 transform_box(const scene::Transform& transform, const Box3& box);

// `box` grown by a tiny fraction of its size (and a little absolutely), so that rounding in
// the boxes put into a hierarchy never culls a grazing hit or a point on a boundary.
inline Box3 padded(const Box3& box) {
  constexpr double kPadding = 1e-9;
  const Vec3 margin = kPadding * (box.hi - box.lo + glm::abs(box.lo) + glm::abs(box.hi)) + 1e-300;
  return Box3{box.lo - margin, box.hi + margin};
}

// Narrows [tmin, tmax] to where ray.at(t) lies in `box`; false when nothing is left. Works
// for any direction length and for infinite boxes.
using implicit::clip_to_box;

}  // namespace convray::geometry
