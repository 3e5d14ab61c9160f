#include "field/triangle_quartic.hpp"

#include <initializer_list>
#include <tuple>

namespace convray::field {

namespace {

// Dunavant's degree-4 rule: two orbits of three points (barycentric a, b, b and its
// permutations), weights summing to 1 (times the area).
constexpr double kWeight1 = 0.223381589678011, kA1 = 0.108103018168070, kB1 = 0.445948490915965;
constexpr double kWeight2 = 0.109951743655322, kA2 = 0.816847572980459, kB2 = 0.091576213509771;

}  // namespace

LineQuartic triangle_line_quartic(const Triangle& t, double area, const Vec3& origin,
                                  const Vec3& direction, double radius) {
  const double inv_r2 = 1.0 / (radius * radius);
  LineQuartic sum;
  auto add_point = [&](const Vec3& q, double weight) {
    // |p(s) - q|^2 = s^2 + 2 s (d.w) + |w|^2 with w = origin - q, so the kernel's base is
    // u = A + B s + C s^2 and u^2 = A^2 + 2AB s + (B^2 + 2AC) s^2 + 2BC s^3 + C^2 s^4.
    const Vec3 w = origin - q;
    const double a = 1.0 - glm::dot(w, w) * inv_r2;
    const double b = -2.0 * glm::dot(direction, w) * inv_r2;
    const double c = -inv_r2;
    sum.c[0] += weight * a * a;
    sum.c[1] += weight * 2.0 * a * b;
    sum.c[2] += weight * (b * b + 2.0 * a * c);
    sum.c[3] += weight * 2.0 * b * c;
    sum.c[4] += weight * c * c;
  };
  for (const auto& [weight, x, y] : {std::tuple{kWeight1, kA1, kB1}, std::tuple{kWeight2, kA2, kB2}}) {
    const double z = 1.0 - x - y;
    add_point(x * t.a + y * t.b + z * t.c, weight);
    add_point(y * t.a + z * t.b + x * t.c, weight);
    add_point(z * t.a + x * t.b + y * t.c, weight);
  }
  for (double& c : sum.c) c *= area;
  return sum;
}

}  // namespace convray::field
