#include "geometry/disc.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {

Box3 disc_bounds(const Vec3& center, const Vec3& normal, double radius) {
  Vec3 reach;
  for (int axis = 0; axis < 3; ++axis) {
    reach[axis] = radius * std::sqrt(std::max(0.0, 1.0 - normal[axis] * normal[axis]));
  }
  return Box3{center - reach, center + reach};
}

DiscShape::DiscShape(const Vec3& center, const Vec3& normal, double radius, double hole_radius,
                     SurfaceInfoPtr surface)
    : center_(center),
      normal_(glm::normalize(normal)),
      radius_(radius),
      hole_radius_(hole_radius),
      surface_(std::move(surface)) {}

Box3 DiscShape::bounds() const { return disc_bounds(center_, normal_, radius_); }

Box3 DiscShape::inside_bounds() const { return infinite_box(); }

void DiscShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                          TraceStats& /*stats*/) const {
  const double approach = glm::dot(ray.direction, normal_);
  if (approach == 0.0) return;
  const double t = glm::dot(center_ - ray.origin, normal_) / approach;
  if (!(t > tmin && t < tmax)) return;
  const Vec3 offset = ray.at(t) - center_;
  const double r2 = glm::dot(offset, offset);
  if (r2 > radius_ * radius_ || r2 < hole_radius_ * hole_radius_) return;
  out.push_back({t, normal_, surface_.get()});
}

bool DiscShape::inside(const Vec3& p) const { return glm::dot(p - center_, normal_) < 0.0; }

}  // namespace convray::geometry
