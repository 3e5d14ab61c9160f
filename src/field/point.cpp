#include "field/point.hpp"

namespace convray::field {

double point_value(const Vec3& p, const Vec3& center, double radius) {
  const Vec3 rel = p - center;
  const double k = 1.0 - glm::dot(rel, rel) / (radius * radius);
  return k > 0.0 ? k * k : 0.0;
}

FieldSample point_field(const Vec3& p, const Vec3& center, double radius) {
  const Vec3 rel = p - center;
  const double inv_r2 = 1.0 / (radius * radius);
  const double k = 1.0 - glm::dot(rel, rel) * inv_r2;
  if (k <= 0.0) return {};
  // d/dP (1 - |rel|^2/R^2)^2 = -4 (1 - |rel|^2/R^2) rel / R^2
  return {k * k, (-4.0 * k * inv_r2) * rel};
}

}  // namespace convray::field
