#pragma once
// Math vocabulary shared by every module: double-precision GLM vectors and constants.
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace convray {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
// Affine maps as GLM's column-major 4x4 matrices acting on column vectors (p' = M (p, 1)).
using Mat4 = glm::dmat4;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Box3 {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Empty when any axis is: intersections of boxes can empty any of them.
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  Vec3 extent() const { return empty() ? Vec3(0.0) : hi - lo; }
};

// The affine point map of m: Vec3(m * (p, 1)).
inline Vec3 transform_point(const Mat4& m, const Vec3& p) { return Vec3(m * glm::dvec4(p, 1.0)); }

// Whether m is a rigid motion (rotation + translation): affine, orthonormal linear part to
// within `tolerance`, determinant +1 (no mirror). Rigid maps keep lengths, so a ray's t and a
// point's distances are the same on both sides of them.
inline bool is_rigid(const Mat4& m, double tolerance = 1e-12) {
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return false;
  const glm::dmat3 l(m);
  const glm::dmat3 g = glm::transpose(l) * l;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (!(std::abs(g[i][j] - (i == j ? 1.0 : 0.0)) <= tolerance)) return false;
    }
  }
  return glm::determinant(l) > 0.0 && std::isfinite(m[3][0] + m[3][1] + m[3][2]);
}

}  // namespace convray
