#include "geometry/plane.hpp"

#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {

PlaneShape::PlaneShape(const Vec3& normal, double distance, SurfaceInfoPtr surface)
    : normal_(glm::normalize(normal)), distance_(distance), surface_(std::move(surface)) {}

Box3 PlaneShape::bounds() const {
  // A plane perpendicular to an axis is flat along it: worth saying for CSG bounds.
  Box3 box = infinite_box();
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(normal_[axis]) == 1.0) box.lo[axis] = box.hi[axis] = distance_ * normal_[axis];
  }
  return box;
}

Box3 PlaneShape::inside_bounds() const {
  Box3 box = infinite_box();
  for (int axis = 0; axis < 3; ++axis) {
    if (normal_[axis] == 1.0) box.hi[axis] = distance_;
    if (normal_[axis] == -1.0) box.lo[axis] = -distance_;
  }
  return box;
}

void PlaneShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                           TraceStats& /*stats*/) const {
  const double approach = glm::dot(ray.direction, normal_);
  if (approach == 0.0) return;  // parallel: in the plane or beside it, never through it
  const double t = (distance_ - glm::dot(ray.origin, normal_)) / approach;
  add_crossing(t, normal_, surface_.get(), tmin, tmax, out);
}

bool PlaneShape::inside(const Vec3& p) const { return glm::dot(p, normal_) < distance_; }

}  // namespace convray::geometry
