#pragma once
// POV-Ray's `torus { major, minor }`: about the y axis, in the plane y = 0; the points with
// (sqrt(x^2 + z^2) - major)^2 + y^2 < minor^2 are inside.
//
// Along a ray the surface is a quartic. Its closed-form roots lose digits (seen from afar, or
// nearly tangent), so the quartic is written about the point where the ray enters the
// torus' box, its roots are isolated on the ray's span inside the box by the derivatives'
// roots (polynomial.hpp), and each is polished by Newton's method on the distance-like
// function (sqrt(x^2 + z^2) - major)^2 + y^2 - minor^2.
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
  double polish(const Ray& ray, double t) const;

  double major_, minor_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
