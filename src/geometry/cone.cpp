#include "geometry/cone.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"
#include "core/polynomial_roots.hpp"
#include "geometry/disc.hpp"

namespace convray::geometry {

ConeShape::ConeShape(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius,
                     bool open, SurfaceInfoPtr surface)
    : base_(base),
      cap_(cap),
      axis_(glm::normalize(cap - base)),
      length_(glm::length(cap - base)),
      base_radius_(base_radius),
      cap_radius_(cap_radius),
      slope_((cap_radius - base_radius) / length_),
      open_(open),
      surface_(std::move(surface)) {}

Box3 ConeShape::bounds() const {
  // The convex hull of the two end discs; its box is the box of theirs.
  return hull(disc_bounds(base_, axis_, base_radius_), disc_bounds(cap_, axis_, cap_radius_));
}

void ConeShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                          TraceStats& /*stats*/) const {
  const size_t first = out.size();
  side_crossings(ray, tmin, tmax, out);
  if (!open_) {
    cap_crossing(ray, 0.0, base_radius_, tmin, tmax, out);
    cap_crossing(ray, length_, cap_radius_, tmin, tmax, out);
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

void ConeShape::side_crossings(const Ray& ray, double tmin, double tmax,
                               std::vector<Crossing>& out) const {
  // Split the ray into its part along the axis (height h) and across it (q):
  // |q0 + t qd|^2 = (radius(h0) + slope * t hd)^2.
  const Vec3 w = ray.origin - base_;
  const double h0 = glm::dot(w, axis_), hd = glm::dot(ray.direction, axis_);
  const Vec3 q0 = w - h0 * axis_, qd = ray.direction - hd * axis_;
  const double r0 = radius_at(h0);
  const double a = glm::dot(qd, qd) - slope_ * slope_ * hd * hd;
  const double half_b = glm::dot(q0, qd) - slope_ * r0 * hd;
  const double c = glm::dot(q0, q0) - r0 * r0;
  double roots[2];
  int count = quadratic_roots(a, half_b, c, roots);
  if (count == 2 && roots[0] == roots[1]) {
    // A double root: the ray touches the side, or goes through the apex (a ray down the
    // axis enters there). Keep one crossing where the inside changes, none where it does not.
    const double t = roots[0], step = 1e-9 * (length_ + std::abs(t));
    count = inside(ray.at(t - step)) != inside(ray.at(t + step)) ? 1 : 0;
  }
  for (int i = 0; i < count; ++i) {
    const double t = roots[i], h = h0 + t * hd;
    // Keep the body between the caps (which also drops the cone's mirror nappe).
    if (h < 0.0 || h > length_ || !(t > tmin && t < tmax)) continue;
    // Gradient of |q|^2 - radius(h)^2, halved: q - radius(h) * slope * axis.
    const Vec3 q = q0 + t * qd;
    Vec3 normal = q - radius_at(h) * slope_ * axis_;
    const double length = glm::length(normal);
    normal = length > 0.0 ? normal / length : -ray.direction;  // the apex: face the ray
    out.push_back({t, normal, surface_.get()});
  }
}

void ConeShape::cap_crossing(const Ray& ray, double height, double radius, double tmin, double tmax,
                             std::vector<Crossing>& out) const {
  if (radius <= 0.0) return;
  const double hd = glm::dot(ray.direction, axis_);
  if (hd == 0.0) return;
  const double t = (height - glm::dot(ray.origin - base_, axis_)) / hd;
  if (!(t > tmin && t < tmax)) return;
  const Vec3 across = ray.at(t) - (base_ + height * axis_);
  const Vec3 q = across - glm::dot(across, axis_) * axis_;
  if (glm::dot(q, q) > radius * radius) return;
  out.push_back({t, height == 0.0 ? -axis_ : axis_, surface_.get()});
}

bool ConeShape::inside(const Vec3& p) const {
  const Vec3 w = p - base_;
  const double h = glm::dot(w, axis_);
  if (h < 0.0 || h > length_) return false;
  const Vec3 q = w - h * axis_;
  const double r = radius_at(h);
  return glm::dot(q, q) <= r * r;
}

}  // namespace convray::geometry
