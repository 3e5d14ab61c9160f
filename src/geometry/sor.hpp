#pragma once
// POV-Ray's `sor` (surface of revolution): about the y axis, the squared radius a cubic of
// the height between each pair of points, as the povray binary draws it (trace() on a
// six-point sor: radii within 5e-9 of this rule):
//   points P0 .. P(n-1) = <r, h>; segment i (1 <= i <= n - 3) runs from P(i) to P(i+1);
//   r^2 is the cubic Hermite curve in h through r(i)^2 and r(i+1)^2 whose slopes d(r^2)/dh
//   at its ends are 2 r(j) (r(j+1) - r(j-1)) / (h(j+1) - h(j-1)) (P0 and P(n-1) only set
//   slopes);
//   unless `open`, flat caps close it at h(1) and h(n-2); inside: below the curve's radius
//   between the caps (an open sor has no inside).
// A ray meets a segment where x^2 + z^2 - r^2(y) = 0: a cubic in the ray's parameter, solved
// by polynomial_roots.
#include <array>
#include <vector>

#include "geometry/primitive.hpp"

namespace convray::geometry {

class SorShape final : public Shape {
 public:
  // `points`: <r, h>, at least 4, heights ascending from P1 to P(n-2).
  SorShape(const std::vector<Vec2>& points, bool open, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

  // r^2 at height y (between the caps).
  double radius_squared(double y) const;

 private:
  struct Segment {
    double h0, length;                 // from h0 to h0 + length
    std::array<double, 4> c;           // r^2 = sum c[k] t^k, t = (y - h0) / length
  };
  const Segment& segment_at(double y) const;
  // The crossings of the segments and caps, in no particular order.
  void append_crossings(const Ray& ray, double tmin, double tmax,
                        std::vector<Crossing>& out) const;

  std::vector<Segment> segments_;
  double bottom_, top_, bottom_radius_, top_radius_, max_radius_;
  bool open_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
