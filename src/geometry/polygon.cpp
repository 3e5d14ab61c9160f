#include "geometry/polygon.hpp"

#include <cmath>

namespace convray::geometry {

PolygonShape::PolygonShape(std::vector<std::vector<Vec3>> outlines, const Vec3& normal,
                           SurfaceInfoPtr surface)
    : normal_(glm::normalize(normal)), surface_(std::move(surface)) {
  offset_ = glm::dot(normal_, outlines.front().front());
  // Project along the normal's largest component: the projection keeps the even-odd count,
  // and it is the one least distorted.
  int drop = 0;
  for (int axis = 1; axis < 3; ++axis) {
    if (std::abs(normal_[axis]) > std::abs(normal_[drop])) drop = axis;
  }
  u_ = (drop + 1) % 3;
  v_ = (drop + 2) % 3;
  for (const std::vector<Vec3>& outline : outlines) {
    std::vector<Vec2>& projected = outlines_.emplace_back();
    for (const Vec3& corner : outline) {
      projected.push_back(Vec2(corner[u_], corner[v_]));
      bounds_.extend(corner);
    }
  }
}

Box3 PolygonShape::bounds() const { return bounds_; }

Box3 PolygonShape::inside_bounds() const { return Box3{}; }  // empty: no inside

bool PolygonShape::inside(const Vec3& /*p*/) const { return false; }

bool PolygonShape::covers(const Vec3& p) const {
  // Even-odd rule over every edge of every outline: a ray from the point towards +u crosses
  // the edges an odd number of times exactly when the point is inside.
  const double u = p[u_], v = p[v_];
  bool odd = false;
  for (const std::vector<Vec2>& outline : outlines_) {
    const size_t n = outline.size();
    for (size_t k = 0, previous = n - 1; k < n; previous = k++) {
      const Vec2& a = outline[previous];
      const Vec2& b = outline[k];
      if ((a.y > v) == (b.y > v)) continue;
      const double crossing_u = a.x + (v - a.y) * (b.x - a.x) / (b.y - a.y);
      if (crossing_u > u) odd = !odd;
    }
  }
  return odd;
}

void PolygonShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                             TraceStats& /*stats*/) const {
  const double approach = glm::dot(ray.direction, normal_);
  if (approach == 0.0) return;
  const double t = (offset_ - glm::dot(ray.origin, normal_)) / approach;
  if (!(t > tmin && t < tmax)) return;
  if (!covers(ray.at(t))) return;
  out.push_back({t, normal_, surface_.get()});
}

}  // namespace convray::geometry
