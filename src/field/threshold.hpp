#pragma once
// Thresholds of convolution surfaces F = T: the field of a flat region, a line or a point at
// a given distance, under each kernel.
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "field/cauchy.hpp"
#include "field/kernel.hpp"
#include "util/math.hpp"

namespace convray::field {

// The threshold that puts the surface of a flat region at distance `offset` from its
// triangles: the infinite plane's field s (π/3) R^2 (1 - d^2/R^2)^3 at d = offset, that is
// T = s (π/3) (R^2 - d^2)^3 / R^4. Needs 0 <= offset < radius.
inline double threshold_for_offset(double strength, double radius, double offset) {
  const double r2 = radius * radius;
  const double k = r2 - offset * offset;
  return strength * (kPi / 3.0) * k * k * k / (r2 * r2);
}

// The same under `kernel`: the quartic's above, or the Cauchy kernel's infinite plane
// (cauchy.hpp). Needs 0 <= offset < radius for the quartic.
inline double plane_threshold(const Kernel& kernel, double strength, double radius, double offset) {
  switch (kernel.type) {
    case KernelType::cauchy: return strength * cauchy_plane_value(offset, kernel.sharpness);
    case KernelType::quartic: break;
  }
  return threshold_for_offset(strength, radius, offset);
}

// The threshold that puts the surface around a lone straight segment, far from its ends, at
// distance `offset`: the infinite line's field s (16/15) (R^2 - d^2)^(5/2) / R^4 at d = offset
// (the kernel integrated along the line). Needs 0 <= offset < radius.
inline double threshold_for_line_offset(double strength, double radius, double offset) {
  const double r2 = radius * radius;
  const double a2 = r2 - offset * offset;
  return strength * (16.0 / 15.0) * a2 * a2 * std::sqrt(a2) / (r2 * r2);
}

// The threshold that puts the surface around a lone point at distance `offset`: the kernel
// itself, s (1 - d^2/R^2)^2 at d = offset. Needs 0 <= offset < radius.
inline double threshold_for_point_offset(double strength, double radius, double offset) {
  const double k = 1.0 - (offset * offset) / (radius * radius);
  return strength * k * k;
}

// What an offset is measured from: the skeleton's most extended kind of primitive. A file
// with triangles is a surface; segments without triangles are tubes; points alone are balls.
enum class OffsetFrom { plane, line, point };

// Throws std::invalid_argument unless double precision carries a kernel of this radius: the
// closed forms divide by R^4, which must be a normal, finite number (about 1e-77 < R < 1e77).
inline void check_radius_in_range(double radius) {
  const double r4 = radius * radius * radius * radius;
  if (radius > 0.0 && std::isfinite(r4) && r4 >= std::numeric_limits<double>::min()) return;
  std::ostringstream message;
  message << "the kernel radius " << radius
          << " is outside what double precision carries (R^4 must be a normal number: about "
             "1e-77 < R < 1e77); scale the model (quick and polygonize: --fit-box) or the radius";
  throw std::invalid_argument(message.str());
}

// The threshold a user asked for: T itself when given, else the one for `offset` (R/2 when
// neither is given) from a plane, a line or a point. Throws std::invalid_argument unless the
// radius is in range and 0 <= offset < radius.
inline double resolve_threshold(double strength, double radius, std::optional<double> offset,
                                std::optional<double> threshold,
                                OffsetFrom from = OffsetFrom::plane) {
  check_radius_in_range(radius);
  if (threshold) return *threshold;
  const double d = offset.value_or(0.5 * radius);
  if (!(d >= 0.0 && d < radius)) {
    std::ostringstream message;
    message << "--offset must satisfy 0 <= offset < radius (offset " << d << ", radius " << radius
            << ")";
    throw std::invalid_argument(message.str());
  }
  switch (from) {
    case OffsetFrom::line: return threshold_for_line_offset(strength, radius, d);
    case OffsetFrom::point: return threshold_for_point_offset(strength, radius, d);
    case OffsetFrom::plane: break;
  }
  return threshold_for_offset(strength, radius, d);
}

}  // namespace convray::field
