#pragma once
// Operations on boxes (util/math.hpp's Box3) that may be empty or reach to infinity (planes,
// inverted solids), and clipping a ray's parameter interval to a box (the slab test), shared
// by the surface finders, the shapes, the polygonizer and the renderer: each hands on only
// the part of a ray that can meet what is in the box, and never an infinite interval where
// the box is finite.
#include <algorithm>

#include "core/ray.hpp"
#include "util/math.hpp"

namespace convray {

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

// `box` grown by a tiny fraction of its size (and a little absolutely), so that rounding in
// the boxes put into a hierarchy never culls a grazing hit or a point on a boundary.
inline Box3 padded(const Box3& box) {
  constexpr double kPadding = 1e-9;
  const Vec3 margin = kPadding * (box.hi - box.lo + glm::abs(box.lo) + glm::abs(box.hi)) + 1e-300;
  return Box3{box.lo - margin, box.hi + margin};
}

// The box around the image of `box` under the affine map `m` (object -> placed space).
// Infinite sides stay infinite along every axis they reach; zero matrix entries never make
// 0 * inf.
Box3 transform_box(const Mat4& m, const Box3& box);

// Narrows [tmin, tmax] to where ray.at(t) lies in `box` (which may reach to infinity); false
// when nothing is left or the box is empty on any axis.
inline bool clip_to_box(const Ray& ray, const Box3& box, double& tmin, double& tmax) {
  for (int axis = 0; axis < 3; ++axis) {
    if (box.lo[axis] > box.hi[axis]) return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0) {
      // Parallel to this slab: inside it everywhere or nowhere (avoids 0 * inf).
      if (o < box.lo[axis] || o > box.hi[axis]) return false;
      continue;
    }
    double t0 = (box.lo[axis] - o) / d, t1 = (box.hi[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    tmin = std::max(tmin, t0);
    tmax = std::min(tmax, t1);
    if (tmin > tmax) return false;
  }
  return true;
}

}  // namespace convray
