#pragma once
// POV-Ray's prism with conic_sweep: closed outlines (x, z) of polynomial pieces, scaled by
// the height y for y between height1 and height2, so that the sides are cones with their
// apex at the origin: the point h (x(s), 1, z(s)) for each outline point (x(s), z(s)).
//
// A ray o + t d meets the side of a piece where (x(s), 1, z(s)) lies in the plane through
// the origin that holds the ray: dot((x(s), 1, z(s)), o x d) = 0, a polynomial of the piece's
// degree in s (outline_curve.hpp finds its roots). The caps are the outline scaled by the
// heights; inside where the outline, scaled to the point's height, encloses the point an odd
// number of times.
#include "geometry/outline_curve.hpp"
#include "geometry/primitive.hpp"

namespace convray::geometry {

class ConicPrismShape final : public Shape {
 public:
  ConicPrismShape(const std::vector<std::vector<scene::SplinePiece>>& outlines, double height1,
                  double height2, SurfaceInfoPtr surface);

  Box3 bounds() const override { return bounds_; }
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  bool inside_outline(const Vec2& p) const { return curve_winding(curves_, p) % 2 != 0; }
  void side_crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out) const;
  Vec3 side_normal(const OutlineCurve& curve, double s, double h) const;

  std::vector<OutlineCurve> curves_;
  double height1_, height2_;
  Vec2 lo_{0.0}, hi_{0.0};  // the outline's box at height 1
  Box3 bounds_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
