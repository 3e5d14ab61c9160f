#include "geometry/conic_prism.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {

ConicPrismShape::ConicPrismShape(const std::vector<std::vector<scene::SplinePiece>>& outlines,
                                 double height1, double height2, SurfaceInfoPtr surface)
    : height1_(height1), height2_(height2), surface_(std::move(surface)) {
  bool first = true;
  for (const auto& outline : outlines) {
    for (const scene::SplinePiece& piece : outline) {
      curves_.push_back(OutlineCurve::from(piece));
      lo_ = first ? curves_.back().lo : glm::min(lo_, curves_.back().lo);
      hi_ = first ? curves_.back().hi : glm::max(hi_, curves_.back().hi);
      first = false;
    }
  }
  for (const double h : {height1_, height2_}) {
    bounds_.extend(Vec3(h * lo_.x, h, h * lo_.y));
    bounds_.extend(Vec3(h * hi_.x, h, h * hi_.y));
  }
}

// The cone's normal (x'(s), 0, z'(s)) x (x(s), 1, z(s)), turned to the side where the
// outline does not enclose the point.
Vec3 ConicPrismShape::side_normal(const OutlineCurve& curve, double s, double h) const {
  const Vec2 q = curve.at(s), tangent = curve.tangent(s);
  Vec3 normal(-tangent.y, tangent.y * q.x - tangent.x * q.y, tangent.x);
  const double length = glm::length(normal);
  if (length == 0.0) return Vec3(0.0, 1.0, 0.0);
  normal /= length;
  // At height 1 the outline's plane is the xz plane: step off the curve along the normal's
  // (x, z) and see whether that is inside.
  const Vec2 across(normal.x, normal.z);
  const double step = 1e-7 * (1.0 + glm::length(hi_ - lo_));
  const double side = h < 0.0 ? -1.0 : 1.0;  // below the apex the outline is mirrored
  if (inside_outline(q + side * step * across / std::max(glm::length(across), 1e-300))) {
    normal = -normal;
  }
  return normal;
}

void ConicPrismShape::side_crossings(const Ray& ray, double tmin, double tmax,
                                     std::vector<Crossing>& out) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const Vec3 n = glm::cross(o, d);  // the normal of the plane through the origin and the ray
  if (n == Vec3(0.0)) return;       // the ray runs through the apex
  for (const OutlineCurve& curve : curves_) {
    const double k[4] = {
        n.x * curve.c[0].x + n.y + n.z * curve.c[0].y, n.x * curve.c[1].x + n.z * curve.c[1].y,
        n.x * curve.c[2].x + n.z * curve.c[2].y, n.x * curve.c[3].x + n.z * curve.c[3].y};
    double roots[3];
    const int count = unit_roots(k, roots);
    for (int i = 0; i < count; ++i) {
      const Vec2 q = curve.at(roots[i]);
      // o + t d = h (q.x, 1, q.y) with h = o.y + t d.y: t from the better conditioned of the
      // x and z equations.
      const double ax = d.x - d.y * q.x, az = d.z - d.y * q.y;
      const double t =
          std::abs(ax) >= std::abs(az) ? (o.y * q.x - o.x) / ax : (o.y * q.y - o.z) / az;
      if (!(t > tmin && t < tmax) || !std::isfinite(t)) continue;
      const double h = o.y + t * d.y;
      if (h < height1_ || h > height2_) continue;
      out.push_back({t, side_normal(curve, roots[i], h), surface_.get()});
    }
  }
}

void ConicPrismShape::crossings(const Ray& ray, double tmin, double tmax,
                                std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  Box3 box = bounds_;
  const Vec3 margin(1e-9 * (1.0 + glm::length(box.extent())));
  box.lo -= margin;
  box.hi += margin;
  double enter = tmin, leave = tmax;
  if (!clip_to_box(ray, box, enter, leave)) return;
  const size_t first = out.size();
  side_crossings(ray, tmin, tmax, out);
  if (ray.direction.y != 0.0) {
    for (const double cap : {height1_, height2_}) {
      if (cap == 0.0) continue;  // the apex: no cap
      const double t = (cap - ray.origin.y) / ray.direction.y;
      if (!(t > tmin && t < tmax)) continue;
      const Vec3 p = ray.at(t);
      if (!inside_outline(Vec2(p.x / cap, p.z / cap))) continue;
      out.push_back({t, Vec3(0.0, cap == height1_ ? -1.0 : 1.0, 0.0), surface_.get()});
    }
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

bool ConicPrismShape::inside(const Vec3& p) const {
  if (p.y < height1_ || p.y > height2_ || p.y == 0.0) return false;
  return inside_outline(Vec2(p.x / p.y, p.z / p.y));
}

}  // namespace convray::geometry
