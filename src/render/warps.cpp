#include "render/warps.hpp"

#include <cmath>

#include "render/noise.hpp"

namespace convray::render {

namespace {

// The repeat warp's copy k of the slab [0, width) along its axis, brought back to copy 0.
Vec3 repeat(const scene::Warp& warp, Vec3 p) {
  const double k = std::floor(p[warp.axis] / warp.width);
  p[warp.axis] -= k * warp.width;
  if (std::fmod(std::abs(k), 2.0) == 1.0) {
    for (int axis = 0; axis < 3; ++axis) {
      if (warp.flip[axis] == 0.0) continue;
      p[axis] = axis == warp.axis ? warp.width - p[axis] : -p[axis];
    }
  }
  return p + k * warp.offset;
}

}  // namespace

Vec3 apply_warp(const scene::Warp& warp, const Vec3& p) {
  if (warp.kind == scene::Warp::Kind::repeat) return repeat(warp, p);
  const scene::Turbulence& t = warp.turbulence;
  return p + t.amount * turbulence_vector(p, t.octaves, t.omega, t.lambda);
}

Vec3 pattern_point(const scene::PatternSpace& space, const Vec3& world_point) {
  Vec3 q = space.transform.inverse_point(world_point);
  for (auto warp = space.warps.rbegin(); warp != space.warps.rend(); ++warp) {
    q = warp->inner.inverse_point(apply_warp(*warp, q));
  }
  return q;
}

scene::Transform placement_without_warps(const scene::PatternSpace& space) {
  scene::Transform placement;
  for (const scene::Warp& warp : space.warps) placement = placement.then(warp.inner);
  return placement.then(space.transform);
}

}  // namespace convray::render
