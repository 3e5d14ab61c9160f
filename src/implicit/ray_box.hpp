#pragma once
// Clipping a ray's parameter interval to a box (the slab test), shared by the surface finders,
// the shapes and the renderer: each hands on only the part of a ray that can meet what is in
// the box, and never an infinite interval where the box is finite.
#include <algorithm>

#include "implicit/ray.hpp"
#include "util/math.hpp"

namespace convray::implicit {

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

}  // namespace convray::implicit
