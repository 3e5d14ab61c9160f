#include "render/noise_patterns.hpp"

#include <cmath>

#include "render/noise.hpp"

namespace convray::render {

using scene::Pattern;

namespace {

double granite(const Vec3& q, int generator) {
  double sum = 0.0, frequency = 1.0;
  for (int octave = 0; octave < 6; ++octave) {
    sum += std::abs(turbulence_noise(4.0 * frequency * q, generator) - 0.5) / frequency;
    frequency *= 2.0;
  }
  return sum;
}

double wrinkles(const Vec3& q, int generator) {
  double sum = 0.0, frequency = 1.0;
  for (int octave = 0; octave < 10; ++octave) {
    sum += 0.5 * turbulence_noise(frequency * q, generator) / frequency;
    frequency *= 2.0;
  }
  return sum;
}

double agate(const Vec3& q, double agate_turb, int generator) {
  const double turbulence = turbulence_scalar(q, 6, 0.5, 2.0, generator);
  // agate_turb is kept in single precision, as the binary's values at agate_turb 0.001 show.
  const double angle = 2.0 * kPi * (1.1 * q.z + 1.3 * double(float(agate_turb)) * turbulence);
  return std::pow(0.5 + 0.5 * std::sin(angle), 0.77);
}

// Marble and wood wrap their value as fmod(v, 1.00001), plus 1 below zero: measured, the
// binary's marble at x = 19.3 gives 0.3 - 0.00019 and at x = -1.3 gives 0.70001.
double drifting_wrap(double v) {
  const double wrapped = v - 1.00001 * std::trunc(v);
  return wrapped < 0.0 ? wrapped + 1.0 : wrapped;
}

}  // namespace

double noise_pattern_value(const scene::PatternSpace& space, const Vec3& q) {
  const int generator = space.noise_generator;
  switch (space.pattern) {
    case Pattern::granite:
      return granite(q, generator);
    case Pattern::wrinkles:
      return wrinkles(q, generator);
    case Pattern::agate:
      return agate(q, space.agate_turb, generator);
    case Pattern::dents:
      return std::pow(noise_of_generator(q, generator), 3.0);
    default:  // bozo, spotted, bumps
      return noise_of_generator(q, generator);
  }
}

double marble_value(const scene::PatternSpace& space, const Vec3& q) {
  const scene::Turbulence& turbulence = space.turbulence;
  if (!turbulence.active()) return drifting_wrap(q.x);
  return drifting_wrap(q.x + turbulence.amount.x *
                                 turbulence_scalar(q, turbulence.octaves, turbulence.omega,
                                                   turbulence.lambda, space.noise_generator));
}

double wood_value(const scene::PatternSpace& space, const Vec3& q) {
  const scene::Turbulence& turbulence = space.turbulence;
  if (!turbulence.active()) return drifting_wrap(std::hypot(q.x, q.y));
  const Vec3 d = turbulence_vector(q, turbulence.octaves, turbulence.omega, turbulence.lambda);
  const double x = q.x + std::sin(2.0 * kPi * turbulence.amount.x * (q.x + d.x));
  const double y = q.y + std::sin(2.0 * kPi * turbulence.amount.y * (q.y + d.y));
  return drifting_wrap(std::hypot(x, y));
}

bool has_own_turbulence(Pattern pattern) {
  return pattern == Pattern::marble || pattern == Pattern::wood;
}

}  // namespace convray::render
