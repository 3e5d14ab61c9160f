// The lathe against surfaces of revolution whose crossings are known in closed form: a
// closed rectangle profile (a cylinder with caps), the parabola rho = 1 + y^2 of pieces
// through points on it, a cubic Bezier piece that is a straight line; rays along and across
// the axis, and (nearly) horizontal ones, which take the other branch of the solver.
#include "geometry/lathe.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::build;

scene::SplinePiece line(Vec2 a, Vec2 b) { return {{a, b - a, Vec2(0.0), Vec2(0.0)}}; }

// The closed profile <0,0> <1,0> <1,2> <0,2> <0,0>: a capped cylinder of radius 1, height 2.
scene::Lathe cylinder() {
  const Vec2 p[5] = {{0, 0}, {1, 0}, {1, 2}, {0, 2}, {0, 0}};
  scene::Lathe lathe;
  for (int i = 0; i < 4; ++i) lathe.pieces.push_back(line(p[i], p[i + 1]));
  return lathe;
}

using testing::crossings_of;

TEST(Lathe, CylinderProfileAcrossAndAlongTheAxis) {
  const ShapePtr shape = build(cylinder());
  auto across = crossings_of(*shape, Ray{{-5.0, 1.0, 0.3}, {1.0, 0.0, 0.0}});
  const double half = std::sqrt(1.0 - 0.09);
  ASSERT_EQ(across.size(), 2u);
  EXPECT_NEAR(across[0].t, 5.0 - half, 1e-12);
  EXPECT_NEAR(across[1].t, 5.0 + half, 1e-12);
  EXPECT_NEAR(glm::length(across[0].normal - Vec3(-half, 0.0, 0.3)), 0.0, 1e-12);
  auto down = crossings_of(*shape, Ray{{0.5, 5.0, -0.2}, {0.0, -1.0, 0.0}});
  ASSERT_EQ(down.size(), 2u);
  EXPECT_NEAR(down[0].t, 3.0, 1e-12);
  EXPECT_NEAR(down[1].t, 5.0, 1e-12);
  EXPECT_NEAR(glm::length(down[0].normal - Vec3(0.0, 1.0, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(down[1].normal - Vec3(0.0, -1.0, 0.0)), 0.0, 1e-12);
  EXPECT_TRUE(shape->inside({0.5, 1.0, 0.5}));
  EXPECT_FALSE(shape->inside({0.8, 1.0, 0.8}));
  EXPECT_FALSE(shape->inside({0.0, 2.5, 0.0}));
}

TEST(Lathe, NearlyHorizontalRays) {
  const ShapePtr shape = build(cylinder());
  for (double dy : {0.0, 1e-12, 1e-8, 1e-6, 1e-3}) {
    const Vec3 d = glm::normalize(Vec3(1.0, dy, 0.0));
    auto out = crossings_of(*shape, Ray{{-5.0, 1.0, 0.0}, d});
    ASSERT_EQ(out.size(), 2u) << dy;
    // Where the ray is at |x| = 1.
    EXPECT_NEAR(out[0].t, 4.0 / d.x, 1e-9) << dy;
    EXPECT_NEAR(out[1].t, 6.0 / d.x, 1e-9) << dy;
  }
}

TEST(Lathe, ParabolaOfQuadraticPieces) {
  // rho = 1 + y^2 for y in [0, 2], as two pieces (1 + s^2, s) and (2 + 2s + s^2, 1 + s),
  // closed by the axis and two caps.
  scene::Lathe lathe;
  lathe.pieces.push_back(line({0, 0}, {1, 0}));
  lathe.pieces.push_back({{Vec2(1, 0), Vec2(0, 1), Vec2(1, 0), Vec2(0.0)}});
  lathe.pieces.push_back({{Vec2(2, 1), Vec2(2, 1), Vec2(1, 0), Vec2(0.0)}});
  lathe.pieces.push_back(line({5, 2}, {0, 2}));
  lathe.pieces.push_back(line({0, 2}, {0, 0}));
  const ShapePtr shape = build(lathe);
  for (double y : {0.25, 0.5, 1.3, 1.9}) {
    auto out = crossings_of(*shape, Ray{{-10.0, y, 0.0}, {1.0, 0.0, 0.0}});
    ASSERT_EQ(out.size(), 2u) << y;
    EXPECT_NEAR(out[0].t, 10.0 - (1.0 + y * y), 1e-12) << y;
    // The normal is perpendicular to the profile's slope (d rho / dy = 2y).
    EXPECT_NEAR(glm::length(out[0].normal - glm::normalize(Vec3(-1.0, -2.0 * y, 0.0))), 0.0, 1e-12);
  }
  // A slanted ray meets the parabola where -10 + t cos a = -(1 + y^2), y = 0.1 + t sin a.
  const double a = 0.05;
  auto out = crossings_of(*shape, Ray{{-10.0, 0.1, 0.0}, {std::cos(a), std::sin(a), 0.0}});
  ASSERT_GE(out.size(), 1u);
  const Vec3 p = Ray{{-10.0, 0.1, 0.0}, {std::cos(a), std::sin(a), 0.0}}.at(out[0].t);
  EXPECT_NEAR(-p.x, 1.0 + p.y * p.y, 1e-12);
}

TEST(Lathe, CrossingsWhereTheInsideChanges) {
  // A closed Bezier profile (a bulb) turned about the axis.
  auto bezier = [](Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    return scene::SplinePiece{
        {a, 3.0 * (b - a), 3.0 * (a - 2.0 * b + c), -a + 3.0 * b - 3.0 * c + d}};
  };
  scene::Lathe lathe;
  lathe.pieces.push_back(bezier({0.2, -1}, {2, -1}, {2, 1}, {0.5, 1}));
  lathe.pieces.push_back(bezier({0.5, 1}, {0.3, 0.5}, {0.3, -0.5}, {0.2, -1}));
  const ShapePtr shape = build(lathe);
  std::mt19937_64 rng(5);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, Vec3(0.0), 5.0, 1.5);
    checked += testing::check_crossings_against_inside(*shape, ray, 1.0, 9.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

}  // namespace
}  // namespace convray::geometry
