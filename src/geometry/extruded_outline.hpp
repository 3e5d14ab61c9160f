#pragma once
// Closed outlines of polynomial pieces (outline_curve.hpp) extruded along an axis: POV-Ray's
// text object (quadratic Bezier outlines in x, y; from z = 0 to the thickness) and prisms with
// linear_sweep (spline outlines in x, z; from height 1 to height 2 along y). Along a ray the
// crossings are exact: the two caps where the outline winds around the ray's point in the
// cap's plane, and each side piece where the piece's cubic meets the ray's trace in the
// outline's plane.
#include <vector>

#include "geometry/outline_curve.hpp"
#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

// Winding number of the closed contours made of `pieces` around `p` (nonzero: inside). A
// ray towards +u counts the pieces it crosses, each piece taken over s in [0, 1) so that a
// shared end is counted once.
int outline_winding(const std::vector<scene::OutlinePiece>& pieces, const Vec2& p);

// Where the outline lies: outline coordinates (u, v) are the object's axes `u` and `v`, the
// extrusion runs along axis `w` from `w0` to `w1`. `even_odd`: inside where an odd number of
// contours enclose a point, whatever their orientation (POV-Ray's prisms); else inside
// where the contours wind around it, every contour clockwise around what it encloses
// (TrueType's rule, the text object's).
struct ExtrusionAxes {
  int u = 0, v = 1, w = 2;
  double w0 = 0.0, w1 = 1.0;
  bool even_odd = false;
};

class ExtrudedOutlineShape final : public Shape {
 public:
  // Each group is a set of closed contours (in u, v); a point is inside the shape where it is
  // inside any group, by the rule `axes` names.
  ExtrudedOutlineShape(const std::vector<std::vector<scene::OutlinePiece>>& groups,
                       const ExtrusionAxes& axes, SurfaceInfoPtr surface);
  ExtrudedOutlineShape(const std::vector<std::vector<scene::SplinePiece>>& groups,
                       const ExtrusionAxes& axes, SurfaceInfoPtr surface);

  Box3 bounds() const override { return bounds_; }
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  struct Group {
    std::vector<OutlineCurve> pieces;
    Box3 box;  // of the control points (the curves stay in their hull), w from w0 to w1
  };
  void add_group(std::vector<OutlineCurve> pieces);
  Vec2 plane_point(const Vec3& p) const { return Vec2(p[axes_.u], p[axes_.v]); }
  Vec3 object_vector(double u, double v, double w) const;
  bool inside_outline(const std::vector<OutlineCurve>& pieces, const Vec2& p) const;
  void side_crossings(const Group& group, const Ray& ray, double tmin, double tmax,
                      std::vector<Crossing>& out) const;

  std::vector<Group> groups_;
  ExtrusionAxes axes_;
  Box3 bounds_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
