#pragma once
// Where a triangle lies relative to a window [a, b] of a line, for the window march's
// curvature bounds (line_curvature.hpp explains them), from its TriangleReach: the triangle's
// height above its plane and the outward distances past its three edges of the foot of p(t),
// each linear in t, and its corners' depth range along the line.
//
// The formulas are branch-free (every condition a select) so that one copy serves both the
// scalar LineCurvature and DownBendTable's vectorized loop, with the same bits.
#include <algorithm>
#include <cmath>

#include "accel/triangle_line.hpp"
#include "core/ray.hpp"

namespace convray::implicit {

// The plane, edges and depth range of a triangle along a line (made with its support's span).
using accel::TriangleReach;

// A bound on the triangle's area (`measure`) within R of the window: within the ball of
// radius R + w/2 around the window's middle (w the window's length), which holds every
// point's ball. That ball meets the plane in a disk of radius rho around the middle's foot;
// where the foot lies a distance e outside an edge's line, the triangle keeps to the disk's
// segment beyond that line, of area at most 2 (rho - e) sqrt(rho^2 - e^2).
inline double triangle_area_within(double radius, double measure, double h0, double h1,
                                   double o00, double o01, double o10, double o11, double o20,
                                   double o21, double a, double b) {
  const double mid = 0.5 * (a + b), reach = radius + 0.5 * (b - a);
  const double height = h0 + h1 * mid;
  const double rho2 = reach * reach - height * height;
  const double e = std::max(std::max(o00 + o01 * mid, o10 + o11 * mid), o20 + o21 * mid);
  const double rho2_or_0 = std::max(rho2, 0.0);  // the square roots' arguments, never NaN
  const double segment = std::min(
      measure, 2.0 * (std::sqrt(rho2_or_0) - e) * std::sqrt(std::max(rho2_or_0 - e * e, 0.0)));
  const double past_edge = e * e >= rho2 ? 0.0 : segment;
  const double area = e <= 0.0 ? std::min(measure, kPi * rho2) : past_edge;
  return rho2 > 0.0 ? area : 0.0;  // no disk (or NaN): nothing within reach
}

// A lower bound on |x|^2 / R^2 between a point of the window and a point of the triangle:
// the squared distance to the plane plus that past an edge, each at least its smaller value
// at the window's ends (both are linear in t; where the height changes sign it is 0).
inline double triangle_nearest_s(double r2, double h0, double h1, double o00, double o01,
                                 double o10, double o11, double o20, double o21, double a,
                                 double b) {
  const double ha = h0 + h1 * a, hb = h0 + h1 * b;
  const double nearer = std::min(std::abs(ha), std::abs(hb));
  const bool crosses = (ha > 0.0) != (hb > 0.0);
  const double h = crosses ? 0.0 : nearer;
  const double e0 = std::min(o00 + o01 * a, o00 + o01 * b);
  const double e1 = std::min(o10 + o11 * a, o10 + o11 * b);
  const double e2 = std::min(o20 + o21 * a, o20 + o21 * b);
  const double e = std::max(std::max(std::max(0.0, e0), e1), e2);
  return std::min(1.0, (h * h + e * e) / r2);
}

// A lower bound on |u.x| / R between a point p(t) of the window and a point q of the
// triangle: u.x = t - u.(q - origin), whose range over the triangle is [lo, hi] (its corners'),
// so |u.x| >= max(0, a - hi, lo - b).
inline double triangle_nearest_along(double radius, double lo, double hi, double a, double b) {
  return std::max(std::max(0.0, a - hi), lo - b) / radius;
}

// How far a triangle's field (strength `weight` >= 0) may bend down over [a, b]. Along a unit
// u the kernel bends by u.H.u = 8 (u.x)^2 / R^4 - 4 (1 - s) / R^2, so it bends down only
// where (1 - s) > 2 (u.x)^2 / R^2, by at most 4 / R^2 times (1 - s - 2 (u.x)^2 / R^2); as
// s >= (u.x)^2 / R^2, that is also at most 1 - 3 (u.x)^2 / R^2. Over the triangle's area
// within reach each factor is bounded by its value at the nearest possible point (s by the
// height and the distance past an edge, u.x by the depth range along the line): no bend down
// at all where every point of the triangle lies further than R / sqrt(3) along the line (a
// ray approaching a surface), which the weight 4 (1 - s) / R^2 alone counted in full.
// At most `limit` (2 pi) in all.
inline double triangle_down_bend(double weight, double radius, double r2, double measure,
                                 double limit, double h0, double h1, double o00, double o01,
                                 double o10, double o11, double o20, double o21, double lo,
                                 double hi, double a, double b) {
  const double c = triangle_nearest_along(radius, lo, hi, a, b);
  const double s = triangle_nearest_s(r2, h0, h1, o00, o01, o10, o11, o20, o21, a, b);
  const double bends = std::max(0.0, 1.0 - std::max(s + 2.0 * c * c, 3.0 * c * c));
  const double within =
      triangle_area_within(radius, measure, h0, h1, o00, o01, o10, o11, o20, o21, a, b) * bends;
  return weight * std::min(4.0 * within / r2, limit);
}

}  // namespace convray::implicit
