#pragma once
// Thresholds of convolution surfaces F = T.
#include "util/math.hpp"

namespace convray::implicit {

// The threshold that puts the surface of a flat region at distance `offset` from its
// triangles: the infinite plane's field s (π/3) R^2 (1 - d^2/R^2)^3 at d = offset, that is
// T = s (π/3) (R^2 - d^2)^3 / R^4. Needs 0 <= offset < radius.
inline double threshold_for_offset(double strength, double radius, double offset) {
  const double r2 = radius * radius;
  const double k = r2 - offset * offset;
  return strength * (kPi / 3.0) * k * k * k / (r2 * r2);
}

}  // namespace convray::implicit
