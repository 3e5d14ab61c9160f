#include "render/patterns.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/block_patterns.hpp"
#include "render/noise.hpp"
#include "render/noise_patterns.hpp"
#include "render/sample_hash.hpp"
#include "render/warps.hpp"

namespace convray::render {

using scene::Pattern;

namespace {

// POV-Ray floors checker coordinates after adding this tolerance: a plane at y = 0 then
// shows the colour of y = +0 whatever the rounding of its hit points (measured by bisection
// with the povray binary: the boundaries at 0, 1, 3 and 7 lie 1e-10 below, to 1e-15).
constexpr double kCheckerTolerance = 1e-10;

// Wave sources of ripples and waves: fixed points in the unit cube around the origin.
constexpr int kWaveSources = 10;

const std::array<Vec3, kWaveSources>& wave_sources() {
  static const std::array<Vec3, kWaveSources> sources = [] {
    std::array<Vec3, kWaveSources> s;
    for (int k = 0; k < kWaveSources; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        s[k][axis] = unit_from_hash(hash_values(0x3a7e5, uint64_t(k), uint64_t(axis))) - 0.5;
      }
    }
    return s;
  }();
  return sources;
}

double fract(double v) { return v - std::floor(v); }

// POV-Ray's ramp wave: values already in [0, 1] stay (a pattern's 1 is not its 0), others
// wrap around.
double wrap_to_unit(double v) { return v >= 0.0 && v <= 1.0 ? v : fract(v); }

// Ripples and waves take frequency and phase inside their sines, as POV-Ray's do: the
// frequency sets the rings' spacing, the phase moves them outwards.
bool shapes_its_own_wave(Pattern pattern) {
  return pattern == Pattern::ripples || pattern == Pattern::waves;
}

double ripples(const Vec3& q, double frequency, double phase) {
  double sum = 0.0;
  for (const Vec3& source : wave_sources()) {
    sum += std::sin(2.0 * kPi * (glm::length(q - source) * frequency + phase));
  }
  return std::clamp(0.5 + 0.5 * sum / std::sqrt(double(kWaveSources)), 0.0, 1.0);
}

double waves(const Vec3& q, double frequency, double phase) {
  double sum = 0.0;
  for (const Vec3& source : wave_sources()) {
    const double d = glm::length(q - source);
    sum += std::cos(2.0 * kPi * (d * frequency + phase)) / (1.0 + d);
  }
  return std::clamp(0.5 + 0.5 * sum / std::sqrt(double(kWaveSources)), 0.0, 1.0);
}

// 1 at the centre falling linearly to 0 at distance 1, 0 beyond: planar, spherical,
// cylindrical and boxed, each with its own distance.
double falling_from_one(double distance) { return std::max(0.0, 1.0 - distance); }

// POV-Ray's spiral1: the distance from the z axis plus the arms times the turn about it
// (counted from -y, counter-clockwise), plus z, wrapped by the wave (measured against the
// povray binary: spiral1 1 ramp_wave gives fract(r + theta / 2 pi + 1/4 + z)).
double spiral1(const Vec3& q, double arms) {
  const double turn = std::atan2(q.y, q.x) / (2.0 * kPi) + 0.25;
  return std::hypot(q.x, q.y) + arms * turn + q.z;
}

// POV-Ray's mandel: z = c = x + iy, then z = z^2 + c until |z|^2 > 4; the value is the
// number of steps taken before the one that escaped over `iterations`, 1 inside the set
// (matches the povray binary's 16-bit renders pixel for pixel at 7, 20 and 50 iterations).
double mandel(const Vec3& q, int iterations) {
  double zr = q.x, zi = q.y;
  for (int k = 0; k < iterations; ++k) {
    const double r = zr * zr - zi * zi + q.x;
    zi = 2.0 * zr * zi + q.y;
    zr = r;
    if (zr * zr + zi * zi > 4.0) return double(k) / iterations;
  }
  return 1.0;
}

// POV-Ray's quilted, measured with the povray binary at random points and along rays from a
// cell's centre for several controls (agrees to 5e-9, the probes' printing): with v the
// point's offset from its unit cell's centre, quilted_cubic(|v|) times
// (|v.x| + |v.y| + |v.z|) * 2 / (3 sqrt 3), its absolute value (negative controls).
double quilted(const Vec3& q, double control0, double control1) {
  const Vec3 v = q - glm::floor(q) - Vec3(0.5);
  const double l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
  return std::abs(quilted_cubic(glm::length(v), control0, control1) * l1 * 2.0 /
                  (3.0 * std::sqrt(3.0)));
}

double gradient(const Vec3& q, const Vec3& axis) {
  const double length = glm::length(axis);
  return length > 0.0 ? glm::dot(q, axis) / length : 0.0;
}

}  // namespace

double quilted_cubic(double t, double control0, double control1) {
  const double s = 1.0 - t;
  return t * t * t + 3.0 * t * s * s * control0 + 3.0 * t * t * s * control1;
}

double triangle_wave(double v) {
  const double f = fract(v);
  return f < 0.5 ? 2.0 * f : 2.0 - 2.0 * f;
}

int checker_block(const Vec3& q) {
  const double sum = std::floor(q.x + kCheckerTolerance) + std::floor(q.y + kCheckerTolerance) +
                     std::floor(q.z + kCheckerTolerance);
  return std::fmod(std::abs(sum), 2.0) == 1.0 ? 1 : 0;
}

double raw_pattern_value(const scene::PatternSpace& space, const Vec3& q) {
  switch (space.pattern) {
    case Pattern::solid:
    case Pattern::average:  // pigment.cpp mixes an average's pigments itself
    case Pattern::image_map:  // and reads an image_map's colours (render/image_map.hpp)
      return 0.0;
    case Pattern::checker:
      return checker_block(q);
    case Pattern::gradient:
      return fract(gradient(q, space.gradient_axis));
    case Pattern::marble:
      return marble_value(space, q);
    case Pattern::wood:
      return wood_value(space, q);
    case Pattern::granite:
    case Pattern::agate:
    case Pattern::bozo:
    case Pattern::spotted:
    case Pattern::bumps:
    case Pattern::dents:
    case Pattern::wrinkles:
      return noise_pattern_value(space, q);
    case Pattern::radial:
      return fract(std::atan2(-q.z, q.x) / (2.0 * kPi));
    case Pattern::onion:
      return fract(glm::length(q));
    case Pattern::leopard: {
      const double s = (std::sin(q.x) + std::sin(q.y) + std::sin(q.z)) / 3.0;
      return s * s;
    }
    case Pattern::ripples:
      return ripples(q, space.frequency, space.phase);
    case Pattern::waves:
      return waves(q, space.frequency, space.phase);
    case Pattern::planar:
      return falling_from_one(std::abs(q.y));
    case Pattern::spherical:
      return falling_from_one(glm::length(q));
    case Pattern::cylindrical:
      return falling_from_one(std::hypot(q.x, q.z));
    case Pattern::boxed:
      return falling_from_one(std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}));
    case Pattern::spiral1:
      return spiral1(q, space.arms);
    case Pattern::mandel:
      return mandel(q, space.iterations);
    case Pattern::brick:
      return brick_block(q, space.brick_size, space.mortar);
    case Pattern::hexagon:
      return hexagon_block(q);
    case Pattern::function:
      return (*space.function)(q.x, q.y, q.z);
    case Pattern::quilted:
      return quilted(q, space.control0, space.control1);
  }
  return 0.0;
}

double pattern_value(const scene::PatternSpace& space, const Vec3& world_point) {
  return pattern_value_in_space(space, pattern_point(space, world_point));
}

double pattern_value_in_space(const scene::PatternSpace& space, const Vec3& pattern_point) {
  return pattern_value_after_turbulence(space, turbulent_point(space, pattern_point));
}

Vec3 turbulent_point(const scene::PatternSpace& space, const Vec3& pattern_point) {
  if (!space.turbulence.active() || has_own_turbulence(space.pattern)) return pattern_point;
  const scene::Turbulence& turbulence = space.turbulence;
  return pattern_point + turbulence.amount * turbulence_vector(pattern_point, turbulence.octaves,
                                                               turbulence.omega,
                                                               turbulence.lambda);
}

double pattern_value_after_turbulence(const scene::PatternSpace& space, const Vec3& q) {
  const double raw = raw_pattern_value(space, q);
  if (scene::is_block_pattern(space.pattern) || shapes_its_own_wave(space.pattern)) return raw;
  return shaped_by_wave(space, raw * space.frequency + space.phase);
}

double shaped_by_wave(const scene::PatternSpace& space, double v) {
  using scene::Wave;
  Wave wave = space.wave;
  if (wave == Wave::pattern_default) {
    const bool triangular = space.pattern == Pattern::marble || space.pattern == Pattern::wood ||
                            space.pattern == Pattern::spiral1;
    wave = triangular ? Wave::triangle : Wave::ramp;
  }
  // The shapes as the povray binary draws them over a gradient (tests/render).
  switch (wave) {
    case Wave::triangle:
      return triangle_wave(v);
    case Wave::sine:
      return 0.5 * (1.0 + std::sin(2.0 * kPi * v));
    case Wave::scallop:
      return std::abs(std::sin(kPi * v));
    case Wave::cubic: {
      const double t = wrap_to_unit(v);
      return t * t * (3.0 - 2.0 * t);
    }
    case Wave::poly:
      return std::pow(wrap_to_unit(v), space.wave_exponent);
    default:
      return wrap_to_unit(v);
  }
}

}  // namespace convray::render
