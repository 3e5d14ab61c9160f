#pragma once
// One-sided bounds on how fast a primitive's field bends along a line: the window march's
// certificate (window_march.hpp). For the kernel K(x) = (1 - s)^2, s = |x|^2/R^2, the second
// derivative along a unit direction u is
//   u.H.u = 8 (u.x)^2 / R^4 - 4 (1 - s) / R^2        (|x| < R; 0 outside)
// so it bends up by at most 8 (u.x)^2 / R^4 and down by at most 4 (1 - s) / R^2. A primitive's
// field is K integrated over its skeleton (or, for blob cylinders, K of the distance), so:
//   up   <= 8 c^2 / R^4 times its measure within R,   c = the largest |u.x| over the window
//   down <= 4 / R^2  times its measure within R
// and for a triangle each is also at most 2 pi: over the disk where a plane meets the ball,
// the integral of 8 (u.x)^2 / R^4 is 8 pi (h^2 u_n^2 (R^2-h^2) + |u_t|^2 (R^2-h^2)^2 / 4) / R^4
// <= 2 pi, and that of 4 (1 - s) / R^2 is 2 pi (1 - h^2/R^2)^2 <= 2 pi (h the plane's distance,
// u_n and u_t the parts of u along its normal and in it). The plane's own field
// (pi R^2 / 3)(1 - h^2/R^2)^3 has F'' = -2 pi at h = 0, so the downward bound is reached.
// Downwards a triangle is also held to the plane's own downward bend, the integral of the
// kernel's negative second derivative over the whole plane (triangle_reach.hpp's
// triangle_down_limit): 2 pi along the normal, 2 pi / sqrt(3) along the plane, less away from
// it. It binds for triangles about as wide as R and wider, which the rays grazing a surface
// cross at a shallow angle: the dragon at R = 1 took a sixth fewer windows.
//
// c comes from the primitive's extent along the line: for t in the window [a, b] and q on the
// skeleton, u.x = t - u.(q - origin), so |u.x| <= max(|a - hi|, |b - lo|) with [lo, hi] the
// skeleton's range of u.(q - origin) (and never more than R, inside the ball). Better still
// for a tilted triangle or segment, the integral of (u.x)^2 over the whole skeleton is its
// measure times (t - mean)^2 + var, mean and var those of u.(q - origin) over the skeleton
// (a linear function: var = sum over corner pairs of (difference)^2 / 36 on a triangle, / 12
// on a segment), largest at an end of the window. Near a surface the rays that approach or
// leave it see both well below R^2, where the old symmetric bound 8/R^2 per unit measure
// (4 pi per wide triangle) was up to four times looser.
//
// A triangle's measure within R of a point of the window is its area within that point's
// ball, which meets the triangle's plane in a disk of radius rho <= sqrt(R^2 - h^2) (h the
// window's least height); where the foot lies a distance e outside one of the triangle's
// edges, the triangle keeps to the disk's segment beyond that edge's line, of area at most
// 2 (rho - e) sqrt(rho^2 - e^2) (its bounding rectangle). Where triangles are wider than R,
// the few that tile the disk then count for their part of it each, not for the whole disk
// each. Downwards, the weight 4 (1 - s) / R^2 is also at most its value at the triangle's
// nearest possible point (the window's least height above the plane and least distance past
// an edge).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/ray.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/triangle_reach.hpp"

namespace convray::implicit {

// How far a field may bend above and below its tangent over a window, both >= 0 and with the
// strength included: F(a + s) <= F(a) + F'(a) s + up s^2 / 2 and >= ... - down s^2 / 2.
struct CurvatureBounds {
  double up = 0.0, down = 0.0;
};

// A primitive's curvature along one line, prepared once per ray for any window of it.
class LineCurvature {
 public:
  LineCurvature(const ConvolutionSurface::Impl& surface, uint32_t id, const Ray& ray);
  // A triangle of a mesh with this strength and radius (what the surface's id gives).
  // `frame` gives its area (computed once per mesh).
  LineCurvature(const field::Triangle& triangle, const field::TriangleFrame& frame,
                double strength, double radius, const Ray& ray);

  // How far the field may bend up over the window t in [a, b] of the line, and down.
  double up(double a, double b) const { return flipped_ ? bend_down(a, b) : bend_up(a, b); }
  double down(double a, double b) const { return flipped_ ? bend_up(a, b) : bend_down(a, b); }
  CurvatureBounds over(double a, double b) const { return {up(a, b), down(a, b)}; }
  // How far it may bend down anywhere on the line (a triangle's whole area counted, at most
  // its plane's bound, triangle_down_limit; up: no cheap bound, infinity): a constant for a
  // first test before down().
  double down_anywhere() const { return flipped_ ? kInfinity : down_anywhere_; }

  // What down(a, b) is made of, for DownBendTable's vectorized sums (a triangle's plane and
  // edges are prepared here). Only for a positive strength (not flipped).
  struct DownTerms {
    double weight, radius, r2, measure, limit, anywhere;
    bool triangle;
    TriangleReach reach;
  };
  bool flipped() const { return flipped_; }
  DownTerms down_terms() const;
  // The same for a mesh's triangle, without the rest of a LineCurvature (the march's table
  // needs only these; `up` is rarely asked). For a positive strength.
  static DownTerms triangle_down_terms(const field::Triangle& triangle,
                                       const field::TriangleFrame& frame, double strength,
                                       double radius, const Ray& ray);
  // The same from the triangle's reach along the ray and its area, made with its span
  // (accel's TriangleLineTable): what the march's table takes. `twice_area` as field's
  // triangle_frame makes it: a triangle has an area where it is positive and finite.
  static DownTerms triangle_down_terms(double twice_area, double strength, double radius,
                                       const TriangleReach& reach) {
    // As the constructor sets them (a triangle without a finite area has no field).
    const double weight = std::abs(strength), r2 = radius * radius;
    const bool area = twice_area > 0.0 && twice_area < kInfinity;
    const double limit = triangle_down_limit(area ? reach : TriangleReach{});
    const double measure = area ? 0.5 * twice_area : 0.0;
    return {weight, radius, r2, measure, limit,
            triangle_down_anywhere(weight, measure, r2, limit), area,
            area ? reach : TriangleReach{}};
  }

 private:
  // The same for the skeleton's integral of K with a positive strength.
  double bend_up(double a, double b) const;
  double bend_down(double a, double b) const;
  // bend_down's largest value: the triangle's whole area within reach, s >= 0.
  static double triangle_down_anywhere(double weight, double measure, double r2, double limit) {
    return weight * std::min(4.0 * measure / r2, limit);
  }
  // A bound on the triangle's area within R of the window (triangle_reach.hpp).
  double area_within(double a, double b) const;

  double weight_ = 0.0;            // |strength|
  double radius_ = 0.0, r2_ = 0.0;  // R, R^2
  double measure_ = 0.0;           // length or area within R (a point's: 1)
  double length_ = 1.0;            // the whole length or area, for mean_ and var_
  double lo_ = 0.0, hi_ = 0.0;     // the skeleton's range of u.(q - origin)
  double mean_ = 0.0, var_ = 0.0;  // its mean and variance over the skeleton
  bool has_extent_ = false;        // lo_, hi_ bound u.x (not for arcs)
  bool has_moments_ = false;       // mean_, var_ give the integral of (u.x)^2 (not for blob
                                   // cylinders, whose kernel is not an integral)
  double limit_ = kInfinity;       // 2 pi for a triangle, upwards
  double down_limit_ = kInfinity;  // a triangle's downwards: triangle_down_limit
  double down_anywhere_ = kInfinity;  // bend_down's bound over any window
  bool flipped_ = false;           // a negative strength swaps the two sides
  // Triangles: the distance to the plane and the outward distances past each edge of the
  // foot of p(t), each linear in t (value at t = 0 and slope), and the plane's tilt, which
  // the downward limit needs from the start.
  bool triangle_ = false;
  TriangleReach reach_;
};

// Inline: the march sums it over every primitive near each window it weighs.
inline double LineCurvature::bend_up(double a, double b) const {
  // The integral of (u.x)^2 over the skeleton's part within R of a window point.
  double second_moment = kInfinity;
  if (has_moments_) {
    const double spread = std::max((a - mean_) * (a - mean_), (b - mean_) * (b - mean_)) + var_;
    second_moment = length_ * spread;  // over the whole skeleton, not only within R
  }
  double c2 = r2_;
  if (has_extent_) {
    const double c = std::max(std::abs(a - hi_), std::abs(b - lo_));
    c2 = std::min(c * c, r2_);
  }
  // Only a triangle's area within reach can do better than its whole area, and only where
  // the bound is not already below what that area allows.
  const double whole = measure_ * c2;
  if (whole < second_moment) {
    second_moment = triangle_ && 8.0 * whole > limit_ * r2_ * r2_ ? area_within(a, b) * c2 : whole;
  }
  return weight_ * std::min(8.0 * second_moment / (r2_ * r2_), limit_);
}

}  // namespace convray::implicit
