// The superellipsoid against shapes whose crossings are known in closed form: e = n = 1 is
// the unit sphere, e = n = 2 the octahedron |x| + |y| + |z| = 1, e = n = 3 the star
// |x|^(2/3) + |y|^(2/3) + |z|^(2/3) = 1; and, for other exponents, its crossings against
// where its inside test changes along random rays.
#include "geometry/superellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::build;

using testing::crossings_of;

TEST(Superellipsoid, OneOneIsTheUnitSphere) {
  const ShapePtr shape = build(scene::Superellipsoid{1.0, 1.0});
  const Ray ray{{0.3, -0.2, -5.0}, {0.0, 0.0, 1.0}};
  const double half = std::sqrt(1.0 - 0.09 - 0.04);
  const auto out = crossings_of(*shape, ray);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 5.0 - half, 1e-12);
  EXPECT_NEAR(out[1].t, 5.0 + half, 1e-12);
  EXPECT_NEAR(glm::length(out[0].normal - Vec3(0.3, -0.2, -half)), 0.0, 1e-9);
  EXPECT_TRUE(shape->inside({0.5, 0.5, 0.5}));
  EXPECT_FALSE(shape->inside({0.6, 0.6, 0.6}));
}

TEST(Superellipsoid, TwoTwoIsTheOctahedron) {
  const ShapePtr shape = build(scene::Superellipsoid{2.0, 2.0});
  // Along x at y = 0.2, z = 0.1: |x| = 0.7.
  const auto out = crossings_of(*shape, Ray{{-5.0, 0.2, 0.1}, {1.0, 0.0, 0.0}});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 4.3, 1e-12);
  EXPECT_NEAR(out[1].t, 5.7, 1e-12);
  const Vec3 face = glm::normalize(Vec3(-1.0, 1.0, 1.0));  // the face x < 0, y > 0, z > 0
  EXPECT_NEAR(glm::length(out[0].normal - face), 0.0, 1e-9);
}

TEST(Superellipsoid, ThreeThreeIsAStar) {
  const ShapePtr shape = build(scene::Superellipsoid{3.0, 3.0});
  const double c = std::cbrt(0.1 * 0.1);  // |0.1|^(2/3)
  const double x = std::pow(1.0 - 2.0 * c, 1.5);
  const auto out = crossings_of(*shape, Ray{{-5.0, 0.1, -0.1}, {1.0, 0.0, 0.0}});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 5.0 - x, 1e-12);
  EXPECT_NEAR(out[1].t, 5.0 + x, 1e-12);
  // Through the centre along a diagonal: the star's waist, (1/3)^(3/2) per axis.
  const double w = std::pow(1.0 / 3.0, 1.5) * std::sqrt(3.0);
  const auto diagonal = crossings_of(*shape, Ray{Vec3(-2.0), glm::normalize(Vec3(1.0))});
  ASSERT_EQ(diagonal.size(), 2u);
  EXPECT_NEAR(diagonal[0].t, 2.0 * std::sqrt(3.0) - w, 1e-12);
}

TEST(Superellipsoid, CrossingsWhereTheInsideChanges) {
  const double exponents[][2] = {{0.2, 0.5}, {0.7, 1.5}, {2.5, 0.4}, {1.0, 4.0}};
  for (const auto& en : exponents) {
    const ShapePtr shape = build(scene::Superellipsoid{en[0], en[1]});
    std::mt19937_64 rng(11);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
      const Ray ray = testing::random_ray(rng, Vec3(0.0), 4.0, 1.2);
      checked += testing::check_crossings_against_inside(*shape, ray, 1.0, 7.0, 1e-9);
    }
    EXPECT_GT(checked, 150) << en[0] << ", " << en[1];
  }
}

}  // namespace
}  // namespace convray::geometry
