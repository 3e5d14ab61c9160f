#pragma once
// Small helpers shared by the field tests: error ratios against tolerances (a ratio <= 1
// passes), the 5-point central-difference gradient, the worst case seen, and printing inputs
// with every digit so that a failing case can be replayed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "util/math.hpp"

namespace convray::reference {

// |value - reference| / (tolerance * scale).
inline double value_error_ratio(double value, double reference, double tolerance, double scale) {
  return std::abs(value - reference) / (tolerance * scale);
}

// |g - g_ref| / (tolerance * max(|g_ref|, floor)): relative to the reference gradient, or to
// the natural gradient scale (field scale / R) where the reference gradient is small.
inline double gradient_error_ratio(const Vec3& gradient, const Vec3& reference, double tolerance,
                                   double floor) {
  return glm::length(gradient - reference) / (tolerance * std::max(glm::length(reference), floor));
}

// Fourth-order central difference (f(-2s) - 8 f(-s) + 8 f(s) - f(2s)) / 12s along each axis.
// The step is rounded down to a power of two; returns nothing when p +- k step is not exact in
// floating point (far from the origin), since the stencil assumes equal spacing.
template <class ValueFunction>
std::optional<Vec3> five_point_gradient(const ValueFunction& value, const Vec3& p, double step) {
  constexpr double kOffsets[] = {-2.0, -1.0, 1.0, 2.0};
  constexpr double kWeights[] = {1.0, -8.0, 8.0, -1.0};
  step = std::ldexp(1.0, std::ilogb(step));
  Vec3 gradient;
  for (int axis = 0; axis < 3; ++axis) {
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double offset = kOffsets[k], weight = kWeights[k];
      Vec3 q = p;
      q[axis] += offset * step;
      if (q[axis] - p[axis] != offset * step) return std::nullopt;
      sum += weight * value(q);
    }
    gradient[axis] = sum / (12.0 * step);
  }
  return gradient;
}

inline std::string format_vec(const Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "{%.17g, %.17g, %.17g}", v.x, v.y, v.z);
  return text;
}

inline std::string format_double(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// The largest error ratio seen, and the inputs that produced it.
struct WorstCase {
  double ratio = 0.0;
  std::string inputs;

  void update(double candidate, const std::string& candidate_inputs) {
    if (candidate > ratio || std::isnan(candidate)) {
      ratio = std::isnan(candidate) ? INFINITY : candidate;
      inputs = candidate_inputs;
    }
  }
};

// Seed for the random suites: CONVRAY_TEST_SEED when set (to replay or explore), else `fixed`.
inline unsigned long long test_seed(unsigned long long fixed) {
  const char* text = std::getenv("CONVRAY_TEST_SEED");
  return text ? std::strtoull(text, nullptr, 0) : fixed;
}

}  // namespace convray::reference
