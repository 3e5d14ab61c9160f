#include "geometry/text_shape.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/bounds.hpp"
#include "geometry/polynomial.hpp"

namespace convray::geometry {

namespace {

double cross(const Vec2& u, const Vec2& v) { return u.x * v.y - u.y * v.x; }

// The piece as a + s p1 + s^2 p2.
struct PiecePolynomial {
  Vec2 a, p1, p2;
  explicit PiecePolynomial(const scene::OutlinePiece& piece)
      : a(piece.a), p1(2.0 * (piece.b - piece.a)), p2(piece.a - 2.0 * piece.b + piece.c) {}
  Vec2 at(double s) const { return a + s * (p1 + s * p2); }
  Vec2 tangent(double s) const { return p1 + 2.0 * s * p2; }
};

// Roots in [0, 1) of c0 + c1 s + c2 s^2.
int unit_roots(double c0, double c1, double c2, double roots[2]) {
  const double c[3] = {c0, c1, c2};
  int count = polynomial_roots(c, 0.0, 1.0, roots);
  if (count > 0 && roots[count - 1] >= 1.0) --count;
  return count;
}

}  // namespace

int outline_winding(const std::vector<scene::OutlinePiece>& pieces, const Vec2& p) {
  int winding = 0;
  for (const scene::OutlinePiece& piece : pieces) {
    if (std::min({piece.a.y, piece.b.y, piece.c.y}) > p.y) continue;
    if (std::max({piece.a.y, piece.b.y, piece.c.y}) < p.y) continue;
    if (std::max({piece.a.x, piece.b.x, piece.c.x}) < p.x) continue;
    const PiecePolynomial curve(piece);
    double roots[2];
    const int count = unit_roots(curve.a.y - p.y, curve.p1.y, curve.p2.y, roots);
    for (int i = 0; i < count; ++i) {
      if (curve.at(roots[i]).x <= p.x) continue;
      const double rising = curve.tangent(roots[i]).y;
      if (rising > 0.0) ++winding;
      if (rising < 0.0) --winding;
    }
  }
  return winding;
}

TextShape::TextShape(const scene::Text& text, SurfaceInfoPtr surface)
    : thickness_(text.thickness), surface_(std::move(surface)) {
  for (const std::vector<scene::OutlinePiece>& pieces : text.glyphs) {
    Glyph glyph{pieces, {}};
    for (const scene::OutlinePiece& piece : pieces) {
      for (const Vec2& p : {piece.a, piece.b, piece.c}) {
        glyph.box.extend(Vec3(p, 0.0));
        glyph.box.extend(Vec3(p, thickness_));
      }
    }
    bounds_.extend(glyph.box.lo);
    bounds_.extend(glyph.box.hi);
    glyphs_.push_back(std::move(glyph));
  }
}

void TextShape::side_crossings(const Glyph& glyph, const Ray& ray, double enter, double leave,
                               std::vector<Crossing>& out) const {
  const Vec2 o(ray.origin), d(ray.direction);
  // t from the larger of the trace's components: well conditioned unless the ray runs along z,
  // where the sides are met at grazing angles only.
  const int axis = std::abs(d.x) >= std::abs(d.y) ? 0 : 1;
  if (d[axis] == 0.0) return;
  for (const scene::OutlinePiece& piece : glyph.pieces) {
    const PiecePolynomial curve(piece);
    // Points of the piece on the ray's trace: cross(d, curve(s) - o) = 0.
    double roots[2];
    const int count =
        unit_roots(cross(d, curve.a - o), cross(d, curve.p1), cross(d, curve.p2), roots);
    for (int i = 0; i < count; ++i) {
      const Vec2 q = curve.at(roots[i]);
      const double t = (q[axis] - o[axis]) / d[axis];
      if (!(t > enter && t < leave)) continue;
      const double z = ray.origin.z + t * ray.direction.z;
      if (z < 0.0 || z > thickness_) continue;
      // Clockwise contours: the solid lies to the right of the tangent, outside to its left.
      const Vec2 tangent = curve.tangent(roots[i]);
      const Vec3 normal(-tangent.y, tangent.x, 0.0);
      const double length = glm::length(normal);
      if (length == 0.0) continue;
      out.push_back({t, normal / length, surface_.get()});
    }
  }
}

void TextShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                          TraceStats& /*stats*/) const {
  const size_t first = out.size();
  for (const Glyph& glyph : glyphs_) {
    double enter = tmin, leave = tmax;
    Box3 box = glyph.box;
    const Vec3 margin(1e-9 * (1.0 + glm::length(box.extent())));
    box.lo -= margin;
    box.hi += margin;
    if (!clip_to_box(ray, box, enter, leave)) continue;
    side_crossings(glyph, ray, tmin, tmax, out);
    if (ray.direction.z == 0.0) continue;
    for (const double cap : {0.0, thickness_}) {
      const double t = (cap - ray.origin.z) / ray.direction.z;
      if (!(t > tmin && t < tmax)) continue;
      const Vec3 p = ray.at(t);
      if (outline_winding(glyph.pieces, Vec2(p)) == 0) continue;
      out.push_back({t, Vec3(0.0, 0.0, cap == 0.0 ? -1.0 : 1.0), surface_.get()});
    }
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

bool TextShape::inside(const Vec3& p) const {
  if (p.z < 0.0 || p.z > thickness_) return false;
  for (const Glyph& glyph : glyphs_) {
    if (!contains(glyph.box, p)) continue;
    if (outline_winding(glyph.pieces, Vec2(p)) != 0) return true;
  }
  return false;
}

}  // namespace convray::geometry
