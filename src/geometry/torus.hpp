#pragma once
// POV-Ray's `torus { major, minor }`: about the y axis, in the plane y = 0; the points with
// (sqrt(x^2 + z^2) - major)^2 + y^2 < minor^2 are inside.
//
// Along a ray the surface is a quartic. Its closed-form roots lose digits (seen from afar, or
// nearly tangent), so the quartic is written about the point where the ray enters the
// torus' box, its roots are bracketed on the ray's span inside the box by the one polynomial
// root finder (core/polynomial_roots.hpp), and each bracket is refined on the distance-like
// function (sqrt(x^2 + z^2) - major)^2 + y^2 - minor^2.
#include <span>

#include "core/polynomial_roots.hpp"
#include "geometry/primitive.hpp"

namespace convray::geometry {

class TorusShape final : public Shape {
 public:
  TorusShape(double major, double minor, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

  // (sqrt(x^2 + z^2) - major)^2 + y^2 - minor^2: negative inside.
  double implicit_value(const Vec3& p) const;
  Vec3 outward_normal(const Vec3& p) const;

 private:
  // The root in one bracket of the quartic (in t - enter) along the ray.
  double root_in(const Ray& ray, double enter, std::span<const double> quartic,
                 const RootBracket& bracket) const;

  double major_, minor_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
