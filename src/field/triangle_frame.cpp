#include "field/triangle_frame.hpp"

#include <cmath>

namespace convray::field {

TriangleFrame triangle_frame(const Triangle& t) {
  TriangleFrame f;
  const Vec3 v[3] = {t.a, t.b, t.c};
  const Vec3 cross = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double cross_length = glm::length(cross);
  f.area = 0.5 * cross_length;
  if (!(cross_length > 0.0) || !std::isfinite(cross_length)) return f;
  f.normal = cross / cross_length;
  for (int k = 0; k < 3; ++k) f.length[k] = glm::length(v[(k + 1) % 3] - v[k]);
  return f;
}

}  // namespace convray::field
