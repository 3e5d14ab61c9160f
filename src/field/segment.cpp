#include "field/segment.hpp"

#include <algorithm>
#include <cmath>

#include "field/dual.hpp"

namespace convray::field {

namespace {

// With s the coordinate along the segment's line measured from the foot of p, the kernel is
// (a - s^2/R^2)^2 where a = 1 - q^2/R^2 and q is the distance from p to the line. Its
// antiderivative is G(s) = a^2 s - (2a/(3R^2)) s^3 + s^5/(5R^4) (DESIGN.md section 4).
// The support is |s| <= w = R sqrt(a). The clip bounds +-w move with p, but the kernel is zero
// with zero slope there, so treating w as a constant leaves the gradient exact.
template <class S>
S segment_integral(const Vec3& p, const Segment& segment, double radius) {
  const Vec3 axis = segment.b - segment.a;
  const double length = glm::length(axis);
  if (!(length > 0.0)) return S(0.0);
  const Vec3 u = axis / length;
  const Vec3 rel = p - segment.a;
  const double h_value = glm::dot(rel, u);
  const Vec3 off_axis = rel - h_value * u;  // from the foot of p on the line to p
  const double r2 = radius * radius;
  const S a = variable<S>(1.0 - glm::dot(off_axis, off_axis) / r2, (-2.0 / r2) * off_axis);
  if (value_of(a) <= 0.0) return S(0.0);
  const double w = radius * std::sqrt(value_of(a));
  const S h = variable<S>(h_value, u);
  const S s_begin = -h;
  const S s_end = length - h;
  const S lo = value_of(s_begin) > -w ? s_begin : S(-w);
  const S hi = value_of(s_end) < w ? s_end : S(w);
  if (!(value_of(lo) < value_of(hi))) return S(0.0);
  const auto antiderivative = [&](const S& s) {
    const S s2 = s * s;
    return a * a * s - (2.0 / (3.0 * r2)) * a * s2 * s + s2 * s2 * s / (5.0 * r2 * r2);
  };
  return antiderivative(hi) - antiderivative(lo);
}

}  // namespace

double segment_value(const Vec3& p, const Segment& segment, double radius) {
  return segment_integral<double>(p, segment, radius);
}

FieldSample segment_field(const Vec3& p, const Segment& segment, double radius) {
  const Dual f = segment_integral<Dual>(p, segment, radius);
  return {f.v, f.d};
}

}  // namespace convray::field
