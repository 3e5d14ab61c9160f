// MeshField sums through a point query (the support grid); the grid must never miss a
// triangle whose support contains the point, whatever the radius and the mesh's shape.
#include <gtest/gtest.h>

#include <random>

#include "field/triangle.hpp"
#include "implicit/mesh_field.hpp"
#include "field/threshold.hpp"

namespace convray::implicit {
namespace {

using field::Triangle;

std::vector<Triangle> soup(std::mt19937_64& rng, size_t n, Vec3 extent) {
  std::uniform_real_distribution<double> u(0.0, 1.0), small(-0.05, 0.05);
  std::vector<Triangle> tris;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 c = Vec3(u(rng), u(rng), u(rng)) * extent;
    tris.push_back({c, c + Vec3(small(rng), small(rng), small(rng)),
                    c + Vec3(small(rng), small(rng), small(rng))});
  }
  return tris;
}

// Brute force over every triangle: the independent sum the grid must reproduce.
field::FieldSample every_triangle(const std::vector<Triangle>& tris, const Vec3& p, double r) {
  field::FieldSample sum;
  for (const Triangle& t : tris) sum += field::triangle_field(p, t, r);
  return sum;
}

TEST(MeshField, GridFindsEveryContributingTriangle) {
  std::mt19937_64 rng(99);
  for (const Vec3 extent : {Vec3(1, 1, 1), Vec3(10, 0.1, 0.1), Vec3(5, 5, 0)}) {
    const auto tris = soup(rng, 2000, extent);
    for (double r : {0.002, 0.05, 0.3, 2.0}) {
      const MeshField field(tris, r, 1.5);
      std::uniform_real_distribution<double> u(-0.1, 1.1);
      for (int k = 0; k < 200; ++k) {
        const Vec3 p = Vec3(u(rng), u(rng), u(rng)) * glm::max(extent, Vec3(0.2));
        const field::FieldSample expected = every_triangle(tris, p, r) * 1.5;
        const double tol = 1e-12 * r * r * 50;
        ASSERT_NEAR(field.value(p), expected.value, tol)
            << "R=" << r << " extent " << extent.x << "," << extent.y << "," << extent.z
            << " p " << p.x << "," << p.y << "," << p.z;
        const field::FieldSample fast = field.field(p), exact = field.field_exact(p);
        ASSERT_NEAR(fast.value, expected.value, tol);
        ASSERT_NEAR(exact.value, expected.value, tol);
        for (int a = 0; a < 3; ++a) ASSERT_NEAR(fast.gradient[a], expected.gradient[a], tol / r);
      }
    }
  }
}

TEST(MeshField, OffsetThresholdPutsAFlatSurfaceAtTheOffset) {
  // A large square: far from its rim its field is the infinite plane's, so F = T exactly at
  // height = offset (issue 3's definition of `offset`).
  const std::vector<Triangle> square = {{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}},
                                        {{-50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}};
  const double r = 2.0, s = 0.8, offset = 0.7;
  const MeshField field(square, r, s);
  const double t = field::threshold_for_offset(s, r, offset);
  EXPECT_NEAR(field.value({1.3, -2.1, offset}), t, 1e-13 * t);
  EXPECT_NEAR(field.value({0, 0, -offset}), t, 1e-13 * t);
  EXPECT_GT(field.value({0, 0, 0.9 * offset}), t);
  EXPECT_LT(field.value({0, 0, 1.1 * offset}), t);
}

TEST(MeshField, OutsideEverySupportIsZero) {
  const std::vector<Triangle> one = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const MeshField field(one, 0.5);
  EXPECT_EQ(field.value({3, 3, 3}), 0.0);
  EXPECT_EQ(field.value({std::nan(""), 0, 0}), 0.0);
}

}  // namespace
}  // namespace convray::implicit
