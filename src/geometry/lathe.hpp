#pragma once
// POV-Ray's `lathe`: a 2D curve of polynomial pieces (r(s), y(s)), s in [0, 1], turned about
// the y axis. A point (x, y, z) lies on the surface where some piece has y(s) = y and
// r(s)^2 = x^2 + z^2.
//
// Along a ray o + t d, y(s) = o.y + t d.y gives t = (y(s) - o.y) / d.y; substituted into
// x^2 + z^2 = r(s)^2 and multiplied by d.y^2 this is one polynomial in s of twice the
// piece's degree (6 for cubic pieces), whose roots on [0, 1] the shared root finder
// (polynomial.hpp) isolates. A ray (nearly) parallel to the plane y = const instead solves
// y(s) = o.y and meets the circle of radius r(s) there. Inside is where a point's (rho, y)
// is enclosed an odd number of times by the curve; normals point away from that side.
#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class LatheShape final : public Shape {
 public:
  LatheShape(std::vector<scene::SplinePiece> pieces, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  struct Piece {
    double r[4], y[4];         // power-basis coefficients of r(s) and y(s)
    double y_lo, y_hi, r_max;  // bounds of the piece over s in [0, 1]
  };
  struct Root {
    double t, s;
    const Piece* piece;
  };

  void piece_roots(const Piece& piece, const Ray& ray, double span, std::vector<Root>& roots) const;
  bool may_meet(const Piece& piece, const Ray& ray, double span) const;
  Vec3 outward_normal(const Piece& piece, double s, const Vec3& p) const;

  std::vector<Piece> pieces_;
  Box3 box_;
  double margin_ = 0.0;       // slack for the boxes, relative to the lathe's size
  double orientation_ = 1.0;  // +1 when the curve runs counter-clockwise in the (r, y) plane
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
