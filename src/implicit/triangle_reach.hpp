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

// Where the window [a, b] comes nearest the triangle's plane and edges: the least |height|
// of p(t) above the plane (0 where the height changes sign), and a lower bound on how far its
// foot lies outside the triangle, past the farthest edge's line (<= 0: it may lie inside).
// Each term is linear in t, so its least value is at an end of the window; the farthest
// edge's distance at any t is at least each edge's least one.
struct PlaneNearest {
  double height, outside;
};
inline PlaneNearest triangle_plane_nearest(double h0, double h1, double o00, double o01,
                                           double o10, double o11, double o20, double o21,
                                           double a, double b) {
  const double ha = h0 + h1 * a, hb = h0 + h1 * b;
  const double nearer = std::min(std::abs(ha), std::abs(hb));
  const bool crosses = (ha > 0.0) != (hb > 0.0);
  const double e0 = std::min(o00 + o01 * a, o00 + o01 * b);
  const double e1 = std::min(o10 + o11 * a, o10 + o11 * b);
  const double e2 = std::min(o20 + o21 * a, o20 + o21 * b);
  return {crosses ? 0.0 : nearer, std::max(std::max(e0, e1), e2)};
}

// A bound on the triangle's area (`measure`) within R of any one point p(t) of the window
// (the curvature bounds hold point by point). The kernel's ball meets the plane in a disk of
// radius rho(t) = sqrt(R^2 - h(t)^2) <= sqrt(R^2 - h_min^2) around the foot of p(t); where the
// foot lies a distance e >= e_min outside an edge's line, the triangle keeps to the disk's
// segment beyond that line, of area at most 2 (rho - e) sqrt(rho^2 - e^2) (its bounding
// rectangle), which only grows with rho and shrinks with e. (The ball of radius R + w/2 around
// the window's middle, which holds every point's ball, counted up to 2.25 times the disk on
// the march's longest windows.)
inline double triangle_area_within(double radius, double measure, PlaneNearest near) {
  const double rho2 = radius * radius - near.height * near.height;
  const double e = near.outside;
  const double rho2_or_0 = std::max(rho2, 0.0);  // the square roots' arguments, never NaN
  const double segment = std::min(
      measure, 2.0 * (std::sqrt(rho2_or_0) - e) * std::sqrt(std::max(rho2_or_0 - e * e, 0.0)));
  const double past_edge = e * e >= rho2 ? 0.0 : segment;
  const double area = e <= 0.0 ? std::min(measure, kPi * rho2) : past_edge;
  return rho2 > 0.0 ? area : 0.0;  // no disk (or NaN): nothing within reach
}

// A lower bound on |x|^2 / R^2 between a point of the window and a point of the triangle:
// the squared distance to the plane plus that past an edge (`inverse_r2` = 1 / R^2).
inline double triangle_nearest_s(double inverse_r2, PlaneNearest near) {
  const double e = std::max(0.0, near.outside);
  return std::min(1.0, (near.height * near.height + e * e) * inverse_r2);
}

// A lower bound on |u.x| between a point p(t) of the window and a point q of the triangle:
// u.x = t - u.(q - origin), whose range over the triangle is [lo, hi] (its corners'), so
// |u.x| >= max(0, a - hi, lo - b).
inline double triangle_nearest_along(double lo, double hi, double a, double b) {
  return std::max(std::max(0.0, a - hi), lo - b);
}

// The most a triangle's field may bend down anywhere, from how steeply the line meets its
// plane: the kernel's downward bend integrated over the whole plane at height 0, which no part
// of it exceeds. Along a unit u with normal part u_n, at height h (R = 1), the kernel bends
// down by 4 (1 - h^2 - |xi|^2) - 8 (u_n h + |u_t| xi_1)^2 where that is positive (xi the
// point's offset in the plane from the foot, xi_1 along u_t): a concave quadratic in xi,
// positive on an ellipse, whose integral is 2 pi A^2 / sqrt(q) with q = 3 - 2 u_n^2 and
// A = 1 - 3 h^2 / q. Along the normal that is 2 pi (1 - 3 h^2)^2 (2 pi in the plane); a line
// along the plane, 2 pi (1 - h^2)^2 / sqrt(3): near a surface, the rays that graze it.
// 1 / sqrt(q) is the reach's tilt, made with the line's terms.
inline double triangle_down_limit(const TriangleReach& reach) { return 2.0 * kPi * reach.tilt; }
// 1 / limit (0 for no limit), made once per member: triangle_down_bend multiplies by it.
inline double inverse_limit(double limit) { return limit > 0.0 ? 1.0 / limit : 0.0; }

// How far a triangle's field (strength `weight` >= 0) may bend down over [a, b]. Along a unit
// u the kernel bends by u.H.u = 8 (u.x)^2 / R^4 - 4 (1 - s) / R^2, so it bends down only
// where (1 - s) > 2 (u.x)^2 / R^2, by at most 4 / R^2 times (1 - s - 2 (u.x)^2 / R^2); as
// s >= (u.x)^2 / R^2, that is also at most 1 - 3 (u.x)^2 / R^2. Over the triangle's area
// within reach each factor is bounded by its value at the nearest possible point (s by the
// height and the distance past an edge, u.x by the depth range along the line): no bend down
// at all where every point of the triangle lies further than R / sqrt(3) along the line (a
// ray approaching a surface), which the weight 4 (1 - s) / R^2 alone counted in full.
// The integrand is not that bound everywhere: at any one point p(t) it is a concave quadratic
// over the plane, bends(t) - Q(xi - xi0) with det Q = q (below), so an area A of it holds no
// more than the band of area A just under its cap: bends A - A^2 sqrt(q) / (2 pi) =
// bends A - A^2 / limit (R = 1), growing until A = bends limit / 2 (the whole ellipse).
// At most the whole plane's downward bend at the window's least height, from `limit`
// (triangle_down_limit, its value at height 0): 1 / sqrt(q) = limit / 2 pi. The reciprocals
// of R^2 and of limit are the caller's (made once per member, not per window: the divisions
// were a fifth of the sums' time on Intel's slower dividers).
inline double triangle_down_bend(double weight, double radius, double inverse_r2,
                                 double measure, double limit, double inverse_limit, double h0,
                                 double h1, double o00, double o01, double o10, double o11,
                                 double o20, double o21, double lo, double hi, double a,
                                 double b) {
  const double along = triangle_nearest_along(lo, hi, a, b);
  const double c2 = along * along * inverse_r2;  // (u.x / R)^2 at least
  const PlaneNearest near = triangle_plane_nearest(h0, h1, o00, o01, o10, o11, o20, o21, a, b);
  const double s = triangle_nearest_s(inverse_r2, near);
  const double bends = std::max(0.0, 1.0 - std::max(s + 2.0 * c2, 3.0 * c2));
  const double area = std::min(triangle_area_within(radius, measure, near) * inverse_r2,
                               0.5 * bends * limit);  // in units of R^2
  const double within = area * (bends - area * inverse_limit);
  const double inverse_root_q = limit * (0.5 / kPi);
  const double flat = std::max(
      0.0, 1.0 - 3.0 * inverse_root_q * inverse_root_q * (near.height * near.height * inverse_r2));
  return weight * std::min(4.0 * within, limit * flat * flat);
}

}  // namespace convray::implicit
