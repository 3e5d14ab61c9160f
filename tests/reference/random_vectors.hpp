#pragma once
// Random points and directions for the tests' random lines and primitives (one definition,
// shared by the suites).
#include <random>

#include "util/math.hpp"

namespace convray::testing {

// Uniform in the cube [-scale, scale]^3.
inline Vec3 random_point(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

// Uniform on the unit sphere.
inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

}  // namespace convray::testing
