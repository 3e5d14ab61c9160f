#pragma once
// The Cauchy kernel of McCormack and Sherstyuk, h(r) = 1 / (1 + s^2 r^2)^2, and its
// convolution with points, segments and triangles, in closed form with exact gradients.
// Unlike the quartic kernel it has infinite support; the per-primitive bounding-box
// truncation that makes it usable lives with the surface (implicit/cauchy_surface.hpp), so
// these are the untruncated raw fields (strength 1). `s` (> 0) is the kernel's sharpness:
// h falls to 1/4 at r = 1/s.
#include <algorithm>
#include <cmath>

#include "field/sample.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"

namespace convray::field {

// The kernel itself at p: 1 / (1 + s^2 |p - center|^2)^2.
double cauchy_point_value(const Vec3& p, const Vec3& center, double s);
FieldSample cauchy_point_field(const Vec3& p, const Vec3& center, double s);

// Integral over the segment of h(|p - q|) dq (an atan plus rational terms).
double cauchy_segment_value(const Vec3& p, const Segment& segment, double s);
FieldSample cauchy_segment_field(const Vec3& p, const Segment& segment, double s);

// Integral over the triangle's area of h(|p - q|) dA(q), as three signed fan triangles around
// the projection of p on the plane. Zero-area triangles give 0.
double cauchy_triangle_value(const Vec3& p, const Triangle& triangle, double s);
FieldSample cauchy_triangle_field(const Vec3& p, const Triangle& triangle, double s);

// The infinite plane's field at distance h: pi / (s^2 (1 + s^2 h^2)). An offset D gives the
// threshold strength * cauchy_plane_value(D, s).
inline double cauchy_plane_value(double h, double s) {
  return kPi / (s * s * (1.0 + s * s * h * h));
}

// max over r of |h'(r)| = 4 s^2 r / (1 + s^2 r^2)^3, reached at r = 1 / (sqrt(5) s):
// 125 s / (54 sqrt(5)), about 1.035 s.
inline double cauchy_kernel_slope_bound(double s) { return 125.0 * s / (54.0 * std::sqrt(5.0)); }
// max over r >= rho of |h'(r)|: the bound above up to the peak r = 1 / (sqrt(5) s), beyond
// which |h'| falls, so |h'(rho)| itself. A primitive all of whose points are at least rho away
// has |grad F| <= its measure (area, length, 1) times this.
inline double cauchy_kernel_slope_beyond(double rho, double s) {
  if (rho * s * std::sqrt(5.0) <= 1.0) return cauchy_kernel_slope_bound(s);
  const double k = 1.0 / (1.0 + s * s * rho * rho);
  return 4.0 * s * s * rho * k * k * k;
}
// A bound on |grad F| of a triangle of area `area` anywhere: the smaller of area times the
// kernel's slope bound and the integral of |h'| over a whole plane through p, pi^2 / (2 s).
inline double cauchy_triangle_gradient_bound(double area, double s) {
  return std::min(area * cauchy_kernel_slope_bound(s), kPi * kPi / (2.0 * s));
}

}  // namespace convray::field
