#include "geometry/outline_curve.hpp"

#include "core/polynomial_roots.hpp"

namespace convray::geometry {

namespace {

// The box of the Bezier control points of the power-basis cubic c.
void control_box(OutlineCurve& curve) {
  const Vec2* c = curve.c;
  const Vec2 points[4] = {c[0], c[0] + c[1] / 3.0, c[0] + (2.0 * c[1] + c[2]) / 3.0,
                          c[0] + c[1] + c[2] + c[3]};
  curve.lo = curve.hi = points[0];
  for (const Vec2& p : points) {
    curve.lo = glm::min(curve.lo, p);
    curve.hi = glm::max(curve.hi, p);
  }
}

}  // namespace

OutlineCurve OutlineCurve::from(const scene::OutlinePiece& piece) {
  OutlineCurve curve{
      {piece.a, 2.0 * (piece.b - piece.a), piece.a - 2.0 * piece.b + piece.c, Vec2(0.0)}, {}, {}};
  control_box(curve);
  return curve;
}

OutlineCurve OutlineCurve::from(const scene::SplinePiece& piece) {
  OutlineCurve curve{{piece.c[0], piece.c[1], piece.c[2], piece.c[3]}, {}, {}};
  control_box(curve);
  return curve;
}

int unit_roots(const double k[4], double roots[3]) {
  int count = polynomial_roots({k, 4}, 0.0, 1.0, roots);
  if (count > 0 && roots[count - 1] >= 1.0) --count;
  return count;
}

int curve_winding(const std::vector<OutlineCurve>& curves, const Vec2& p) {
  int winding = 0;
  for (const OutlineCurve& curve : curves) {
    if (curve.lo.y > p.y || curve.hi.y < p.y || curve.hi.x < p.x) continue;
    const double k[4] = {curve.c[0].y - p.y, curve.c[1].y, curve.c[2].y, curve.c[3].y};
    double roots[3];
    const int count = unit_roots(k, roots);
    for (int i = 0; i < count; ++i) {
      if (curve.at(roots[i]).x <= p.x) continue;
      const double rising = curve.tangent(roots[i]).y;
      if (rising > 0.0) ++winding;
      if (rising < 0.0) --winding;
    }
  }
  return winding;
}

}  // namespace convray::geometry
