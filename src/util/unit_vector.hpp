#pragma once
// Directions from vectors of any finite size: the gradient of a field of strength 1e200 or
// 1e-160 overflows or underflows when squared, and glm::normalize would give a NaN or zero.
#include <algorithm>
#include <cmath>

#include "util/math.hpp"

namespace convray {

// v / |v|, scaled by v's largest component first when squaring v would overflow or underflow;
// zero for a zero or non-finite v, which has no direction.
inline Vec3 unit_or_zero(const Vec3& v) {
  const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  if (length > 1e-150 && length < 1e150) return v / length;
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0.0) || !std::isfinite(largest)) return Vec3(0.0);
  const Vec3 scaled = v / largest;
  return scaled / std::sqrt(scaled.x * scaled.x + scaled.y * scaled.y + scaled.z * scaled.z);
}

}  // namespace convray
