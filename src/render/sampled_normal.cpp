#include "render/sampled_normal.hpp"

#include <array>
#include <cmath>

#include "render/patterns.hpp"
#include "render/warps.hpp"

namespace convray::render {

namespace {

// The tetrahedron's unit corner directions, as the povray binary places them.
const std::array<Vec3, 4>& tetrahedron_corners() {
  static const std::array<Vec3, 4> corners = [] {
    const double third = 1.0 / 3.0;
    const double root2 = std::sqrt(2.0);
    const double side = std::sqrt(2.0 / 3.0);
    return std::array<Vec3, 4>{Vec3(0.0, 1.0, 0.0), Vec3(2.0 * root2 * third, -third, 0.0),
                               Vec3(-root2 * third, -third, side),
                               Vec3(-root2 * third, -third, -side)};
  }();
  return corners;
}

// POV-Ray's vector per unit of value: a linear ramp of slope 1 along u gives
// -(1 / (10 a)) a (4/3) u = -(2/15) u, the tilt measured on `normal { gradient x }`.
constexpr double kTiltPerSample = 0.1;

// v = -(0.1 / accuracy) Σ value(q + accuracy u_k) u_k at the pattern-space point q. The plain
// turbulence moves the tetrahedron as a whole, as in POV-Ray (on a linear ramp it changes no
// tilt); marble's and wood's own turbulence is sampled at each corner.
Vec3 sampled_tilt(const scene::PatternSpace& space, const Vec3& q, double accuracy) {
  const Vec3 centre = turbulent_point(space, q);
  Vec3 sum(0.0);
  for (const Vec3& u : tetrahedron_corners()) {
    sum += pattern_value_after_turbulence(space, centre + accuracy * u) * u;
  }
  return -(kTiltPerSample / accuracy) * sum;
}

}  // namespace

Vec3 sampled_pattern_normal(const scene::Normal& perturbation, const Vec3& world_point,
                            const Vec3& normal) {
  const scene::PatternSpace& space = perturbation.space;
  const double accuracy = perturbation.accuracy;
  if (!(accuracy > 0.0)) return normal;
  // The normal is bent in pattern space: a pattern squashed along the normal tilts more.
  const scene::Transform placement = placement_without_warps(space);
  const Vec3 in_space = glm::transpose(glm::dmat3(placement.forward())) * normal;
  const double length = glm::length(in_space);
  if (!(length > 0.0)) return normal;
  const Vec3 tilt = sampled_tilt(space, pattern_point(space, world_point), accuracy);
  const Vec3 bent = in_space / length + perturbation.amount * tilt;
  const Vec3 world = placement.normal(bent);
  const double world_length = glm::length(world);
  return world_length > 0.0 && std::isfinite(world_length) ? world / world_length : normal;
}

}  // namespace convray::render
