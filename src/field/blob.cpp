#include "field/blob.hpp"

#include <algorithm>

namespace convray::field {

namespace {

// strength * (1 - |rel|^2/r^2)^2 and its gradient, where rel points from the skeleton to p.
FieldSample distance_kernel(const Vec3& rel, double radius, double strength) {
  const double inv_r2 = 1.0 / (radius * radius);
  const double k = 1.0 - glm::dot(rel, rel) * inv_r2;
  if (k <= 0.0) return {};
  return {strength * k * k, (-4.0 * strength * k * inv_r2) * rel};
}

}  // namespace

FieldSample blob_sphere_field(const Vec3& p, const Vec3& center, double radius, double strength) {
  return distance_kernel(p - center, radius, strength);
}

FieldSample blob_cylinder_field(const Vec3& p, const Vec3& base, const Vec3& apex, double radius,
                                double strength) {
  // POV-Ray splits the component into a body (distance to the axis) and two hemispherical
  // caps (distance to the end points); together that is the distance to the closest point
  // of the axis segment.
  const Vec3 axis = apex - base;
  const double len2 = glm::dot(axis, axis);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - base, axis) / len2, 0.0, 1.0) : 0.0;
  return distance_kernel(p - (base + t * axis), radius, strength);
}

}  // namespace convray::field
