#include "render/normal_perturbation.hpp"

#include <cmath>

#include "render/noise.hpp"
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

// POV-Ray's ripples and waves normals have functions of their own, not measured yet; this
// factor makes them about as steep as POV-Ray's.
constexpr double kNoiseSlopeFactor = 0.5;

double slope_factor(scene::Pattern pattern) {
  switch (pattern) {
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

// POV-Ray's bumps, dents and wrinkles normals add amount times a vector made of its vector
// noise V (render/noise.hpp) to the normal. Measured on a plane lit from four sides and from
// the front (16-bit renders, the normal recovered per pixel), each to 1e-5:
//   bumps     V(p)
//   dents     V(p) noise(p)^3
//   wrinkles  sum over k = 0..9 of |V(2^k p)| / 2^k, the absolute value per component
// at the pattern-space point; the vector keeps its length when carried to world space
// (scale 0.25 tilts as much as scale 1).
Vec3 noise_normal_vector(scene::Pattern pattern, const Vec3& q) {
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
         pattern == scene::Pattern::wrinkles;
}

Vec3 noise_normal(const scene::Normal& perturbation, const Vec3& world_point,
                  const Vec3& normal) {
  const scene::PatternSpace& space = perturbation.space;
  Vec3 q = space.transform.inverse_point(world_point);
  const scene::Turbulence& turbulence = space.turbulence;
  if (turbulence.active()) {
    q += turbulence.amount *
         turbulence_vector(q, turbulence.octaves, turbulence.omega, turbulence.lambda);
  }
  const Vec3 v_pattern = noise_normal_vector(space.pattern, q);
  Vec3 v = space.transform.normal(v_pattern);
  const double length = glm::length(v);
  if (length > 0.0) v *= glm::length(v_pattern) / length;
  const Vec3 tilted = normal + perturbation.amount * v;
  const double tilted_length = glm::length(tilted);
  return tilted_length > 0.0 && std::isfinite(tilted_length) ? tilted / tilted_length : normal;
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
  if (has_noise_normal(perturbation.space.pattern)) {
    return noise_normal(perturbation, world_point, normal);
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
