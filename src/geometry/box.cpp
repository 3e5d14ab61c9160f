#include "geometry/box.hpp"

#include <limits>

namespace convray::geometry {

BoxShape::BoxShape(const Vec3& corner1, const Vec3& corner2, SurfaceInfoPtr surface)
    : lo_(glm::min(corner1, corner2)),
      hi_(glm::max(corner1, corner2)),
      surface_(std::move(surface)) {}

Box3 BoxShape::bounds() const { return Box3{lo_, hi_}; }

void BoxShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                         TraceStats& /*stats*/) const {
  // Slab test, remembering which slab the ray enters last and leaves first: their faces are
  // the ones crossed.
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  int enter_axis = 0, leave_axis = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0) {
      if (o < lo_[axis] || o > hi_[axis]) return;  // parallel to the slab and outside it
      continue;
    }
    double near = (lo_[axis] - o) / d, far = (hi_[axis] - o) / d;
    if (near > far) std::swap(near, far);
    if (near > enter) enter = near, enter_axis = axis;
    if (far < leave) leave = far, leave_axis = axis;
  }
  if (enter > leave) return;
  Vec3 enter_normal(0.0), leave_normal(0.0);
  enter_normal[enter_axis] = ray.direction[enter_axis] > 0.0 ? -1.0 : 1.0;
  leave_normal[leave_axis] = ray.direction[leave_axis] > 0.0 ? 1.0 : -1.0;
  add_crossing(enter, enter_normal, surface_.get(), tmin, tmax, out);
  add_crossing(leave, leave_normal, surface_.get(), tmin, tmax, out);
}

bool BoxShape::inside(const Vec3& p) const {
  return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && p.z >= lo_.z &&
         p.z <= hi_.z;
}

}  // namespace convray::geometry
