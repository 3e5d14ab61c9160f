// The quartic of a triangle's field along a line (field/triangle_quartic.hpp) against the
// closed form triangle_value, wherever the whole triangle is inside the kernel's ball.
#include "field/triangle_frame.hpp"
#include "field/triangle_quartic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <random>
#include <vector>

namespace convray::field {
namespace {

TEST(TriangleQuartic, EqualsTheClosedFormWhereTheTriangleIsInsideTheBall) {
  std::mt19937_64 rng(81);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n;
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double radius = 0.5 + 4.0 * std::abs(u(rng));
    const Vec3 centre(u(rng), u(rng), u(rng));
    // Corners within 0.6 R of the centre, so the ball holds the triangle along a stretch.
    auto corner = [&] { return centre + 0.6 * radius * Vec3(u(rng), u(rng), u(rng)) / std::sqrt(3.0); };
    const Triangle tri{corner(), corner(), corner()};
    const Vec3 direction = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    const Vec3 origin = centre - 3.0 * radius * direction + 0.2 * radius * Vec3(u(rng), u(rng), u(rng));
    const LineQuartic quartic =
        triangle_line_quartic(tri, triangle_frame(tri).area, origin, direction, radius);
    for (int k = 0; k <= 60; ++k) {
      const double s = 6.0 * radius * k / 60.0;
      const Vec3 p = origin + s * direction;
      bool inside = true;
      for (const Vec3& c : {tri.a, tri.b, tri.c}) inside &= glm::length(p - c) < radius;
      if (!inside) continue;
      const double exact = triangle_value(p, tri, radius);
      // Both are integrals of a function of size <= 1 over the triangle: the area scales the
      // rounding of either.
      const double area = 0.5 * glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a));
      EXPECT_NEAR(quartic.value(s), exact, 1e-12 * (area + 1e-300)) << trial << " " << k;
      // The slope against a central difference of the closed form.
      const double h = 1e-5 * radius;
      const double slope = (triangle_value(p + h * direction, tri, radius) -
                            triangle_value(p - h * direction, tri, radius)) / (2.0 * h);
      EXPECT_NEAR(quartic.slope(s), slope, 1e-6 * area / radius + 1e-12);
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
}

// The batch (SIMD lanes, listed triangles in any order, repeats, counts that are not whole
// widths or chunks) against the scalar function, to the bit.
TEST(TriangleQuartic, BatchEqualsTheScalarFunctionToTheBit) {
  std::mt19937_64 rng(82);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n;
  std::vector<Triangle> triangles;
  std::vector<TriangleFrame> frames;
  for (int i = 0; i < 90; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    triangles.push_back({p, p + 0.3 * Vec3(u(rng), u(rng), u(rng)),
                         p + 0.3 * Vec3(u(rng), u(rng), u(rng))});
    frames.push_back(triangle_frame(triangles.back()));
  }
  for (size_t count : {size_t(1), size_t(3), size_t(4), size_t(33), size_t(70)}) {
    std::vector<uint32_t> ids;
    for (size_t k = 0; k < count; ++k) ids.push_back(uint32_t(rng() % triangles.size()));
    const Vec3 direction = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    const Vec3 origin(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
    const double radius = 0.5 + std::abs(u(rng));
    std::vector<LineQuartic> batch(count);
    triangle_line_quartics(triangles, frames, ids, origin, direction, radius, batch);
    for (size_t k = 0; k < count; ++k) {
      const LineQuartic one = triangle_line_quartic(triangles[ids[k]], frames[ids[k]].area,
                                                    origin, direction, radius);
      for (int j = 0; j < 5; ++j) EXPECT_EQ(batch[k].c[j], one.c[j]) << count << " " << k;
    }
  }
}

}  // namespace
}  // namespace convray::field
