#include "field/triangle_frame.hpp"

#include <cmath>

namespace convray::field {

TriangleFrame triangle_frame(const Triangle& t) {
  TriangleFrame f;
  const Vec3 v[3] = {t.a, t.b, t.c};
  const Vec3 cross = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double cross_length = glm::length(cross);
  f.area = 0.5 * cross_length;
  // Every triangle's edges: a zero-area triangle's support is still its edges' capsules.
  for (int k = 0; k < 3; ++k) f.length[k] = glm::length(v[(k + 1) % 3] - v[k]);
  if (!(cross_length > 0.0) || !std::isfinite(cross_length)) return f;
  f.normal = cross / cross_length;
  return f;
}

std::vector<TriangleFrame> triangle_frames(std::span<const Triangle> triangles) {
  std::vector<TriangleFrame> frames;
  frames.reserve(triangles.size());
  for (const Triangle& t : triangles) frames.push_back(triangle_frame(t));
  return frames;
}

}  // namespace convray::field
