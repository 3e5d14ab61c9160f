#include "field/cauchy.hpp"

#include <glm/geometric.hpp>

namespace convray::field {

namespace {

// atan(x2) - atan(x1), given also x2 - x1 (computed from a length, so without cancellation):
// where both have the same sign the difference of two nearly equal angles would lose digits,
// and atan((x2 - x1) / (1 + x1 x2)) is exact there (1 + x1 x2 > 1, so no branch is crossed).
double atan_difference(double x2, double x1, double x2_minus_x1) {
  if (x1 * x2 > 0.0) return std::atan(x2_minus_x1 / (1.0 + x1 * x2));
  return std::atan(x2) - std::atan(x1);
}

// ---- segment ------------------------------------------------------------------------------

// The segment's frame seen from p: axial coordinate h of p from end a, the perpendicular
// vector from the axis to p, and c = 1 + s^2 q^2 with q the distance to the axis.
struct SegmentFrame {
  Vec3 axis{0.0};    // unit, a -> b
  Vec3 across{0.0};  // p minus its foot on the line
  double length = 0.0, h = 0.0, c = 1.0;
};

bool segment_frame(const Vec3& p, const Segment& segment, double s, SegmentFrame& f) {
  const Vec3 e = segment.b - segment.a;
  f.length = glm::length(e);
  if (!(f.length > 0.0)) return false;
  f.axis = e / f.length;
  const Vec3 rel = p - segment.a;
  f.h = glm::dot(rel, f.axis);
  f.across = rel - f.h * f.axis;
  f.c = 1.0 + s * s * glm::dot(f.across, f.across);
  return true;
}

// Integral over x in [x0, x1] of 1 / (c + s^2 x^2)^2, from the antiderivative
// x / (2c (c + s^2 x^2)) + atan(s x / sqrt(c)) / (2 c^(3/2) s).
double segment_integral(double x0, double x1, double length, double c, double s) {
  const double root_c = std::sqrt(c);
  const double angle = atan_difference(s * x1 / root_c, s * x0 / root_c, s * length / root_c);
  const double rational = x1 / (c + s * s * x1 * x1) - x0 / (c + s * s * x0 * x0);
  return (rational + angle / (root_c * s)) / (2.0 * c);
}

// ---- triangle -----------------------------------------------------------------------------

// One edge's signed fan triangle (p0, v_i, v_i+1), with the edge at signed in-plane distance
// d from p0 and its ends at t1 < t2 = t1 + length along it, measured from the foot of the
// perpendicular through p0. In polar coordinates around p0 the radial integral is
// (1 / (2 s^2)) (1/a - 1/(a + s^2 rho^2)), and the angular one gives
//   f = (1 / (2 s^2 a)) (s d / w) [atan(s t2 / w) - atan(s t1 / w)],  w = sqrt(a + s^2 d^2),
// which is smooth in (d, t1, t2, a) everywhere (d = 0 gives 0): no special cases are needed
// for p in the plane or p0 on an edge or a vertex.
struct FanTerm {
  double value = 0.0;
  double by_d = 0.0, by_t1 = 0.0, by_t2 = 0.0, by_a = 0.0;  // partial derivatives
};

template <bool kGradient>
FanTerm fan_term(double d, double t1, double t2, double length, double a, double s) {
  const double s2 = s * s;
  const double w2 = a + s2 * d * d, w = std::sqrt(w2);
  const double angle = atan_difference(s * t2 / w, s * t1 / w, s * length / w);
  const double scale = 1.0 / (2.0 * s2 * a);
  FanTerm f;
  f.value = scale * (s * d / w) * angle;
  if constexpr (kGradient) {
    const double k1 = 1.0 / (w2 + s2 * t1 * t1), k2 = 1.0 / (w2 + s2 * t2 * t2);
    f.by_t1 = -scale * s2 * d * k1;
    f.by_t2 = scale * s2 * d * k2;
    // g = (s d / w) angle as a function of w, then w of d and a.
    const double g_by_w = -(s * d / w2) * angle + (s * d / w) * s * (t1 * k1 - t2 * k2);
    f.by_d = scale * ((s / w) * angle + g_by_w * s2 * d / w);
    f.by_a = -f.value / a + scale * g_by_w / (2.0 * w);
  }
  return f;
}

template <bool kGradient>
FieldSample triangle_impl(const Vec3& p, const Triangle& triangle, double s) {
  const Vec3 normal_area = glm::cross(triangle.b - triangle.a, triangle.c - triangle.a);
  const double twice_area = glm::length(normal_area);
  if (!(twice_area > 0.0)) return {};
  const Vec3 n = normal_area / twice_area;
  const double h = glm::dot(p - triangle.a, n);
  const double a = 1.0 + s * s * h * h;
  const Vec3 v[3] = {triangle.a, triangle.b, triangle.c};
  FieldSample sum;
  double by_a = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = v[(i + 1) % 3] - v[i];
    const double length = glm::length(e);
    if (!(length > 0.0)) continue;  // a repeated vertex: its fan triangle is empty
    const Vec3 u = e / length;
    const Vec3 m = glm::cross(u, n);  // in-plane, pointing away from the triangle's inside
    // p and its projection p0 have the same in-plane coordinates (u, m are orthogonal to n).
    const Vec3 rel = v[i] - p;
    const double d = glm::dot(rel, m), t1 = glm::dot(rel, u), t2 = glm::dot(v[(i + 1) % 3] - p, u);
    const FanTerm f = fan_term<kGradient>(d, t1, t2, length, a, s);
    sum.value += f.value;
    if constexpr (kGradient) {
      // d, t1, t2 fall as p moves along m, u: d(d)/dp = -m, d(t)/dp = -u.
      sum.gradient -= f.by_d * m + (f.by_t1 + f.by_t2) * u;
      by_a += f.by_a;
    }
  }
  if constexpr (kGradient) sum.gradient += by_a * (2.0 * s * s * h) * n;  // da/dp
  return sum;
}

}  // namespace

double cauchy_point_value(const Vec3& p, const Vec3& center, double s) {
  const Vec3 rel = p - center;
  const double k = 1.0 / (1.0 + s * s * glm::dot(rel, rel));
  return k * k;
}

FieldSample cauchy_point_field(const Vec3& p, const Vec3& center, double s) {
  const Vec3 rel = p - center;
  const double k = 1.0 / (1.0 + s * s * glm::dot(rel, rel));
  // d/dp (1 + s^2 r^2)^-2 = -4 s^2 (p - center) (1 + s^2 r^2)^-3
  return {k * k, (-4.0 * s * s * k * k * k) * rel};
}

double cauchy_segment_value(const Vec3& p, const Segment& segment, double s) {
  SegmentFrame f;
  if (!segment_frame(p, segment, s, f)) return 0.0;
  return segment_integral(-f.h, f.length - f.h, f.length, f.c, s);
}

FieldSample cauchy_segment_field(const Vec3& p, const Segment& segment, double s) {
  SegmentFrame f;
  if (!segment_frame(p, segment, s, f)) return {};
  const double s2 = s * s, c = f.c;
  const double x0 = -f.h, x1 = f.length - f.h;
  const double value = segment_integral(x0, x1, f.length, c, s);
  const double k0 = 1.0 / (c + s2 * x0 * x0), k1 = 1.0 / (c + s2 * x1 * x1);
  // The integration bounds move against h: dF/dh = -(kernel at x1 - kernel at x0).
  const double by_h = -(k1 * k1 - k0 * k0);
  // dF/dc = -2 * integral of (c + s^2 x^2)^-3, by the reduction formula
  // J3 = x / (4c (c + s^2 x^2)^2) + (3 / (4c)) J2.
  const double j3 = (x1 * k1 * k1 - x0 * k0 * k0) / (4.0 * c) + 3.0 * value / (4.0 * c);
  const double by_c = -2.0 * j3;
  return {value, by_h * f.axis + by_c * (2.0 * s2) * f.across};
}

double cauchy_triangle_value(const Vec3& p, const Triangle& triangle, double s) {
  return triangle_impl<false>(p, triangle, s).value;
}

FieldSample cauchy_triangle_field(const Vec3& p, const Triangle& triangle, double s) {
  return triangle_impl<true>(p, triangle, s);
}

}  // namespace convray::field
