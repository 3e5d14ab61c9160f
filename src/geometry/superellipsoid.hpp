#pragma once
// POV-Ray's `superellipsoid { <e, n> }`: the points of the box [-1, 1]^3 with
//   f(x, y, z) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1 < 0
// are inside (e: the east-west exponent, across x and y; n: the north-south one, along z).
//
// f + 1 is a norm-like function: for e, n <= 2 it is convex, so along a ray f has one
// minimum and at most two roots, found by bisection on the sign of f's slope, then of f. For
// larger exponents (star-like, pinched shapes) f is sampled densely on each piece of the ray
// between the coordinate planes (where |x|^p has its kinks) and every sign change is refined.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class SuperellipsoidShape final : public Shape {
 public:
  SuperellipsoidShape(double e, double n, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

  double implicit_value(const Vec3& p) const;  // f above: negative inside
  Vec3 outward_normal(const Vec3& p) const;

 private:
  double slope_along(const Ray& ray, double t) const;  // d f(ray.at(t)) / dt
  void convex_roots(const Ray& ray, double lo, double hi, std::vector<double>& roots) const;
  void sampled_roots(const Ray& ray, double lo, double hi, std::vector<double>& roots) const;
  double refine(const Ray& ray, double lo, double hi) const;

  double p_;  // 2 / e: the exponent across x and y
  double q_;  // 2 / n: the exponent along z
  double r_;  // e / n: the power of the xy part
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
