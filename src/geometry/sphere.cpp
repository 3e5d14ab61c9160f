#include "geometry/sphere.hpp"

#include <cmath>

namespace convray::geometry {

SphereShape::SphereShape(const Vec3& center, double radius, SurfaceInfoPtr surface)
    : center_(center), radius_(radius), surface_(std::move(surface)) {}

Box3 SphereShape::bounds() const { return Box3{center_ - radius_, center_ + radius_}; }

void SphereShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                            TraceStats& /*stats*/) const {
  // a t^2 + 2 half_b t + c = 0 with w = o - c, a = |d|^2 (1 up to rounding, which matters
  // 1e5 away). The discriminant is a (r^2 - |w - (half_b / a) d|^2), the squared distance from
  // the centre to the line, which keeps its digits when the ray starts far away (Ray Tracing
  // Gems, ch. 7).
  const Vec3 w = ray.origin - center_;
  const double a = glm::dot(ray.direction, ray.direction);
  const double half_b = glm::dot(w, ray.direction);
  const Vec3 closest = w - (half_b / a) * ray.direction;
  const double discriminant = a * (radius_ * radius_ - glm::dot(closest, closest));
  if (discriminant < 0.0) return;
  const double c = glm::dot(w, w) - radius_ * radius_;
  const double q = -(half_b + std::copysign(std::sqrt(discriminant), half_b));
  double t0 = q / a, t1 = q != 0.0 ? c / q : -half_b / a;
  if (t0 > t1) std::swap(t0, t1);
  for (const double t : {t0, t1}) {
    add_crossing(t, glm::normalize(ray.at(t) - center_), surface_.get(), tmin, tmax, out);
  }
}

bool SphereShape::inside(const Vec3& p) const {
  const Vec3 w = p - center_;
  return glm::dot(w, w) <= radius_ * radius_;
}

}  // namespace convray::geometry
