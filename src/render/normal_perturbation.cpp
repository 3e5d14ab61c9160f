#include "render/normal_perturbation.hpp"

#include <cmath>

#include "render/patterns.hpp"

namespace convray::render {

namespace {

// Pattern cells are about a unit wide; this step resolves them with a central difference
// error far below what shading can show, and stays far above rounding.
constexpr double kGradientStep = 1e-4;

// POV-Ray 3.7 tilts the normal by amount * slope * 2/15 for a pattern used as a normal
// (measured: `normal { gradient x A }` tilts by 0.13334 A, at any scale and accuracy, and
// twice that for marble, whose triangle wave has slope 2).
constexpr double kPatternSlopeFactor = 2.0 / 15.0;

// POV-Ray's own normal patterns (bumps, dents, wrinkles, ripples, waves) have functions of
// their own; with ours, this factor makes bumps about as steep as POV-Ray's (tilt along one
// axis for `bumps 1`: RMS about 0.19 in POV-Ray's picture, 0.18 here).
constexpr double kNoiseSlopeFactor = 0.5;

double slope_factor(scene::Pattern pattern) {
  switch (pattern) {
    case scene::Pattern::bumps:
    case scene::Pattern::dents:
    case scene::Pattern::wrinkles:
    case scene::Pattern::ripples:
    case scene::Pattern::waves:
      return kNoiseSlopeFactor;
    default:
      return kPatternSlopeFactor;
  }
}

// A difference of two wrapped values taken the short way round: a ramp crossing its wrap
// (0.99 -> 0.01) changes by 0.02, not by -0.98.
double unwrapped_difference(double a, double b) {
  double d = a - b;
  if (d > 0.5) d -= 1.0;
  if (d < -0.5) d += 1.0;
  return d;
}

}  // namespace

Vec3 pattern_space_gradient(const scene::PatternSpace& space, const Vec3& world_point) {
  const Vec3 q = space.transform.inverse_point(world_point);
  Vec3 g(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step(0.0);
    step[axis] = kGradientStep;
    const double ahead = pattern_value_in_space(space, q + step);
    const double behind = pattern_value_in_space(space, q - step);
    g[axis] = unwrapped_difference(ahead, behind) / (2.0 * kGradientStep);
  }
  return g;
}

Vec3 pattern_gradient(const scene::PatternSpace& space, const Vec3& world_point) {
  // A gradient is a covector: pattern -> world by the inverse transpose of the placement.
  return space.transform.normal(pattern_space_gradient(space, world_point));
}

Vec3 perturb_normal(const scene::Normal& perturbation, const Vec3& world_point,
                    const Vec3& normal) {
  // Block patterns (checker, brick, hexagon) as normals: left out, with the parser's warning.
  if (perturbation.space.pattern == scene::Pattern::solid || perturbation.amount == 0.0 ||
      scene::is_block_pattern(perturbation.space.pattern)) {
    return normal;
  }
  // The world gradient's direction with the pattern-space gradient's length: bumps as steep
  // at `scale 0.025` as at scale 1 (POV-Ray's amount does not depend on the pattern's scale).
  const Vec3 g_pattern = pattern_space_gradient(perturbation.space, world_point);
  Vec3 g = perturbation.space.transform.normal(g_pattern);
  const double length = glm::length(g);
  if (length > 0.0) g *= glm::length(g_pattern) / length;
  const Vec3 tangential = g - glm::dot(g, normal) * normal;
  const double strength = perturbation.amount * slope_factor(perturbation.space.pattern);
  const Vec3 tilted = normal - strength * tangential;
  const double tilted_length = glm::length(tilted);
  return tilted_length > 0.0 && std::isfinite(tilted_length) ? tilted / tilted_length : normal;
}

}  // namespace convray::render
