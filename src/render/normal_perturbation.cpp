#include "render/normal_perturbation.hpp"

#include <cmath>

#include "render/noise.hpp"
#include "render/patterns.hpp"
#include "render/sampled_normal.hpp"
#include "render/warps.hpp"

namespace convray::render {

namespace {

// Pattern cells are about a unit wide; this step resolves them with a central difference
// error far below what shading can show, and stays far above rounding.
constexpr double kGradientStep = 1e-4;

// POV-Ray's ripples and waves normals have functions of their own, not measured yet; this
// factor on their slope makes them about as steep as POV-Ray's.
constexpr double kWaveSlopeFactor = 0.5;

// A difference of two wrapped values taken the short way round: a ramp crossing its wrap
// (0.99 -> 0.01) changes by 0.02, not by -0.98.
double unwrapped_difference(double a, double b) {
  double d = a - b;
  if (d > 0.5) d -= 1.0;
  if (d < -0.5) d += 1.0;
  return d;
}

// POV-Ray's bumps, dents and wrinkles normals add amount times a vector made of its vector
// noise V (render/noise.hpp) to the normal. Measured on a plane lit from four sides and from
// the front (16-bit renders, the normal recovered per pixel), each to 1e-5:
//   bumps     V(p)
//   dents     V(p) noise(p)^3
//   wrinkles  sum over k = 0..9 of |V(2^k p)| / 2^k, the absolute value per component
// at the pattern-space point; the vector keeps its length when carried to world space
// (scale 0.25 tilts as much as scale 1).
// POV-Ray's quilted normal, measured the same way (to 1e-5, for several controls, amounts
// and scales): with v the offset from the unit cell's centre and B quilted's cubic
// (render/patterns.hpp), the vector B(|v|) v * 2 / sqrt(3), pointing away from the centre.
Vec3 quilted_normal_vector(const scene::PatternSpace& space, const Vec3& q) {
  const Vec3 v = q - glm::floor(q) - Vec3(0.5);
  return quilted_cubic(glm::length(v), space.control0, space.control1) * (2.0 / std::sqrt(3.0)) *
         v;
}

Vec3 noise_normal_vector(const scene::PatternSpace& space, const Vec3& q) {
  const scene::Pattern pattern = space.pattern;
  if (pattern == scene::Pattern::quilted) return quilted_normal_vector(space, q);
  if (pattern == scene::Pattern::dents) return vector_noise(q) * std::pow(noise(q), 3.0);
  if (pattern == scene::Pattern::wrinkles) {
    Vec3 sum(0.0);
    double frequency = 1.0;
    for (int octave = 0; octave < 10; ++octave) {
      sum += glm::abs(vector_noise(frequency * q)) / frequency;
      frequency *= 2.0;
    }
    return sum;
  }
  return vector_noise(q);
}

bool has_noise_normal(scene::Pattern pattern) {
  return pattern == scene::Pattern::bumps || pattern == scene::Pattern::dents ||
         pattern == scene::Pattern::wrinkles || pattern == scene::Pattern::quilted;
}

Vec3 noise_normal(const scene::Normal& perturbation, const Vec3& world_point,
                  const Vec3& normal) {
  const scene::PatternSpace& space = perturbation.space;
  Vec3 q = pattern_point(space, world_point);
  const scene::Turbulence& turbulence = space.turbulence;
  if (turbulence.active()) {
    q += turbulence.amount *
         turbulence_vector(q, turbulence.octaves, turbulence.omega, turbulence.lambda);
  }
  const Vec3 v_pattern = noise_normal_vector(space, q);
  Vec3 v = placement_without_warps(space).normal(v_pattern);
  const double length = glm::length(v);
  if (length > 0.0) v *= glm::length(v_pattern) / length;
  const Vec3 tilted = normal + perturbation.amount * v;
  const double tilted_length = glm::length(tilted);
  return tilted_length > 0.0 && std::isfinite(tilted_length) ? tilted / tilted_length : normal;
}

// With warps the pattern-space point does not move linearly with the world point: the
// difference is taken in world space, along the pattern-space axes carried there by the
// transforms, so that the warps' own turns (a repeat's flips) tilt the normal too.
Vec3 warped_pattern_gradient(const scene::PatternSpace& space, const Vec3& world_point) {
  const scene::Transform placement = placement_without_warps(space);
  Vec3 g(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step(0.0);
    step[axis] = kGradientStep;
    const Vec3 world_step = placement.vector(step);
    const double ahead = pattern_value(space, world_point + world_step);
    const double behind = pattern_value(space, world_point - world_step);
    g[axis] = unwrapped_difference(ahead, behind) / (2.0 * kGradientStep);
  }
  return g;
}

}  // namespace

Vec3 pattern_space_gradient(const scene::PatternSpace& space, const Vec3& world_point) {
  if (!space.warps.empty()) return warped_pattern_gradient(space, world_point);
  const Vec3 q = pattern_point(space, world_point);
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

Vec3 perturb_normal(const scene::Normal& perturbation, const Vec3& world_point,
                    const Vec3& normal) {
  const scene::Pattern pattern = perturbation.space.pattern;
  if (pattern == scene::Pattern::solid || perturbation.amount == 0.0) return normal;
  if (has_noise_normal(pattern)) return noise_normal(perturbation, world_point, normal);
  if (pattern != scene::Pattern::ripples && pattern != scene::Pattern::waves) {
    return sampled_pattern_normal(perturbation, world_point, normal);
  }
  // The world gradient's direction with the pattern-space gradient's length: bumps as steep
  // at `scale 0.025` as at scale 1 (POV-Ray's amount does not depend on the pattern's scale).
  const Vec3 g_pattern = pattern_space_gradient(perturbation.space, world_point);
  Vec3 g = placement_without_warps(perturbation.space).normal(g_pattern);
  const double length = glm::length(g);
  if (length > 0.0) g *= glm::length(g_pattern) / length;
  const Vec3 tangential = g - glm::dot(g, normal) * normal;
  const Vec3 tilted = normal - perturbation.amount * kWaveSlopeFactor * tangential;
  const double tilted_length = glm::length(tilted);
  return tilted_length > 0.0 && std::isfinite(tilted_length) ? tilted / tilted_length : normal;
}

}  // namespace convray::render
