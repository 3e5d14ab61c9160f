#pragma once
// One piece of a closed 2D outline as a cubic polynomial in power basis, the form the text
// object's quadratic Bezier pieces and the prisms' splines (linear, quadratic, cubic, Bezier)
// share, with the box of its Bezier control points (the curve stays in their hull). The
// winding number of closed contours of such pieces around a point; the roots of cubics on
// [0, 1).
#include <vector>

#include "scene/object.hpp"
#include "util/math.hpp"

namespace convray::geometry {

struct OutlineCurve {
  Vec2 c[4];    // the point at s: c[0] + c[1] s + c[2] s^2 + c[3] s^3, s in [0, 1]
  Vec2 lo, hi;  // the box of the control points

  static OutlineCurve from(const scene::OutlinePiece& piece);
  static OutlineCurve from(const scene::SplinePiece& piece);
  Vec2 at(double s) const { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }
  Vec2 tangent(double s) const { return c[1] + s * (2.0 * c[2] + s * 3.0 * c[3]); }
};

// Roots in [0, 1) of k[0] + k[1] s + k[2] s^2 + k[3] s^3, ascending; returns how many.
int unit_roots(const double k[4], double roots[3]);

// Winding number of the closed contours made of `curves` around `p` (nonzero: inside). A
// ray towards +u counts the pieces it crosses, each piece taken over s in [0, 1) so that a
// shared end is counted once.
int curve_winding(const std::vector<OutlineCurve>& curves, const Vec2& p);

}  // namespace convray::geometry
