#include "geometry/extruded_outline.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {

namespace {

double cross(const Vec2& u, const Vec2& v) { return u.x * v.y - u.y * v.x; }

}  // namespace

int outline_winding(const std::vector<scene::OutlinePiece>& pieces, const Vec2& p) {
  std::vector<OutlineCurve> curves;
  for (const scene::OutlinePiece& piece : pieces) curves.push_back(OutlineCurve::from(piece));
  return curve_winding(curves, p);
}

ExtrudedOutlineShape::ExtrudedOutlineShape(
    const std::vector<std::vector<scene::OutlinePiece>>& groups, const ExtrusionAxes& axes,
    SurfaceInfoPtr surface)
    : axes_(axes), surface_(std::move(surface)) {
  for (const std::vector<scene::OutlinePiece>& pieces : groups) {
    std::vector<OutlineCurve> curves;
    for (const scene::OutlinePiece& piece : pieces) curves.push_back(OutlineCurve::from(piece));
    add_group(std::move(curves));
  }
}

ExtrudedOutlineShape::ExtrudedOutlineShape(
    const std::vector<std::vector<scene::SplinePiece>>& groups, const ExtrusionAxes& axes,
    SurfaceInfoPtr surface)
    : axes_(axes), surface_(std::move(surface)) {
  for (const std::vector<scene::SplinePiece>& pieces : groups) {
    std::vector<OutlineCurve> curves;
    for (const scene::SplinePiece& piece : pieces) curves.push_back(OutlineCurve::from(piece));
    add_group(std::move(curves));
  }
}

void ExtrudedOutlineShape::add_group(std::vector<OutlineCurve> pieces) {
  Group group{std::move(pieces), {}};
  for (const OutlineCurve& curve : group.pieces) {
    for (const Vec2& p : {curve.lo, curve.hi}) {
      group.box.extend(object_vector(p.x, p.y, axes_.w0));
      group.box.extend(object_vector(p.x, p.y, axes_.w1));
    }
  }
  bounds_.extend(group.box.lo);
  bounds_.extend(group.box.hi);
  groups_.push_back(std::move(group));
}

Vec3 ExtrudedOutlineShape::object_vector(double u, double v, double w) const {
  Vec3 p(0.0);
  p[axes_.u] = u;
  p[axes_.v] = v;
  p[axes_.w] = w;
  return p;
}

bool ExtrudedOutlineShape::inside_outline(const std::vector<OutlineCurve>& pieces,
                                          const Vec2& p) const {
  const int winding = curve_winding(pieces, p);
  // Each crossing changes the winding by one: its parity is the crossings' parity.
  return axes_.even_odd ? winding % 2 != 0 : winding != 0;
}

void ExtrudedOutlineShape::side_crossings(const Group& group, const Ray& ray, double tmin,
                                          double tmax, std::vector<Crossing>& out) const {
  const Vec2 o = plane_point(ray.origin), d = plane_point(ray.direction);
  // t from the larger of the trace's components: well conditioned unless the ray runs along
  // the extrusion, where the sides are met at grazing angles only.
  const int axis = std::abs(d.x) >= std::abs(d.y) ? 0 : 1;
  if (d[axis] == 0.0) return;
  for (const OutlineCurve& curve : group.pieces) {
    // Points of the piece on the ray's trace: cross(d, curve(s) - o) = 0.
    const double k[4] = {cross(d, curve.c[0] - o), cross(d, curve.c[1]), cross(d, curve.c[2]),
                         cross(d, curve.c[3])};
    double roots[3];
    const int count = unit_roots(k, roots);
    for (int i = 0; i < count; ++i) {
      const Vec2 q = curve.at(roots[i]);
      const double t = (q[axis] - o[axis]) / d[axis];
      if (!(t > tmin && t < tmax)) continue;
      const double w = ray.origin[axes_.w] + t * ray.direction[axes_.w];
      if (w < axes_.w0 || w > axes_.w1) continue;
      // Clockwise contours: the solid lies to the right of the tangent, outside to its left.
      const Vec2 tangent = curve.tangent(roots[i]);
      Vec2 outward(-tangent.y, tangent.x);
      const double length = glm::length(outward);
      if (length == 0.0) continue;
      outward /= length;
      if (axes_.even_odd) {
        // Any orientation: the outside is the side where the point just off the piece is not
        // inside.
        const double step = 1e-7 * (1.0 + glm::length(group.box.extent()));
        if (inside_outline(group.pieces, q + step * outward)) outward = -outward;
      }
      out.push_back({t, object_vector(outward.x, outward.y, 0.0), surface_.get()});
    }
  }
}

void ExtrudedOutlineShape::crossings(const Ray& ray, double tmin, double tmax,
                                     std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  const size_t first = out.size();
  const double dw = ray.direction[axes_.w];
  for (const Group& group : groups_) {
    double enter = tmin, leave = tmax;
    Box3 box = group.box;
    const Vec3 margin(1e-9 * (1.0 + glm::length(box.extent())));
    box.lo -= margin;
    box.hi += margin;
    if (!clip_to_box(ray, box, enter, leave)) continue;
    side_crossings(group, ray, tmin, tmax, out);
    if (dw == 0.0) continue;
    for (const double cap : {axes_.w0, axes_.w1}) {
      const double t = (cap - ray.origin[axes_.w]) / dw;
      if (!(t > tmin && t < tmax)) continue;
      if (!inside_outline(group.pieces, plane_point(ray.at(t)))) continue;
      out.push_back({t, object_vector(0.0, 0.0, cap == axes_.w0 ? -1.0 : 1.0), surface_.get()});
    }
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

bool ExtrudedOutlineShape::inside(const Vec3& p) const {
  if (p[axes_.w] < axes_.w0 || p[axes_.w] > axes_.w1) return false;
  for (const Group& group : groups_) {
    if (!contains(group.box, p)) continue;
    if (inside_outline(group.pieces, plane_point(p))) return true;
  }
  return false;
}

}  // namespace convray::geometry
