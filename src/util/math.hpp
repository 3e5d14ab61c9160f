#pragma once
// Math vocabulary shared by every module: double-precision GLM vectors and constants.
#include <limits>

#include <glm/glm.hpp>

namespace convray {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;

struct Box3 {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
  Vec3 extent() const { return empty() ? Vec3(0.0) : hi - lo; }
};

}  // namespace convray
