// Prisms of spline outlines against closed forms: a conic_sweep square is a frustum of a
// pyramid with its apex at the origin; a linear_sweep outline with a cubic piece z = x^3;
// and, for a curved conic outline, crossings against where inside() changes along rays.
#include "geometry/conic_prism.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/extruded_outline.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

scene::SplinePiece line(Vec2 a, Vec2 b) { return {{a, b - a, Vec2(0.0), Vec2(0.0)}}; }

std::vector<scene::SplinePiece> square() {
  const Vec2 p[5] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  std::vector<scene::SplinePiece> pieces;
  for (int i = 0; i < 4; ++i) pieces.push_back(line(p[i], p[i + 1]));
  return pieces;
}

using testing::crossings_of;

TEST(ConicPrism, SquareIsAFrustumOfAPyramid) {
  const ConicPrismShape shape({square()}, 0.5, 1.0, nullptr);
  // At height 0.75 the square's half side is 0.75.
  const auto across = crossings_of(shape, Ray{{-5.0, 0.75, 0.1}, {1.0, 0.0, 0.0}});
  ASSERT_EQ(across.size(), 2u);
  EXPECT_NEAR(across[0].t, 4.25, 1e-12);
  EXPECT_NEAR(across[1].t, 5.75, 1e-12);
  // The face x = -y: outward (-1, -1, 0) / sqrt 2.
  EXPECT_NEAR(glm::length(across[0].normal - glm::normalize(Vec3(-1, -1, 0))), 0.0, 1e-12);
  const auto down = crossings_of(shape, Ray{{0.2, 5.0, 0.1}, {0.0, -1.0, 0.0}});
  ASSERT_EQ(down.size(), 2u);
  EXPECT_NEAR(down[0].t, 4.0, 1e-12);
  EXPECT_NEAR(down[1].t, 4.5, 1e-12);
  EXPECT_EQ(down[0].normal, Vec3(0, 1, 0));
  EXPECT_EQ(down[1].normal, Vec3(0, -1, 0));
  EXPECT_TRUE(shape.inside({0.7, 0.75, -0.7}));
  EXPECT_FALSE(shape.inside({0.8, 0.75, 0.0}));
  EXPECT_FALSE(shape.inside({0.0, 0.4, 0.0}));
}

TEST(ConicPrism, CrossingsWhereTheInsideChanges) {
  // A curved outline: a cubic Bezier bulge closed by a line.
  const Vec2 a(-1, 0), b(-1, 2), c(1, 2), d(1, 0);
  const scene::SplinePiece bulge{
      {a, 3.0 * (b - a), 3.0 * (a - 2.0 * b + c), -a + 3.0 * b - 3.0 * c + d}};
  const ConicPrismShape shape({{bulge, line(d, a)}}, 0.3, 1.5, nullptr);
  std::mt19937_64 rng(3);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, Vec3(0.0, 0.9, 0.5), 5.0, 1.2);
    checked += testing::check_crossings_against_inside(shape, ray, 1.0, 9.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

TEST(ExtrudedSplines, CubicPieceZEqualsXCubed) {
  // Bounded by z = x^3 (x from 0 to 1), the line z = 1 and the axis x = 0.
  const scene::SplinePiece cubic{{Vec2(0, 0), Vec2(1, 0), Vec2(0, 0), Vec2(0, 1)}};
  const ExtrudedOutlineShape shape(
      std::vector<std::vector<scene::SplinePiece>>{
          {cubic, line({1, 1}, {0, 1}), line({0, 1}, {0, 0})}},
      ExtrusionAxes{0, 2, 1, 0.0, 1.0, true}, nullptr);
  for (double x : {0.2, 0.5, 0.9}) {
    const auto out = crossings_of(shape, Ray{{x, 0.5, -5.0}, {0.0, 0.0, 1.0}});
    ASSERT_EQ(out.size(), 2u) << x;
    EXPECT_NEAR(out[0].t, 5.0 + x * x * x, 1e-12) << x;
    EXPECT_NEAR(out[1].t, 6.0, 1e-12) << x;
    // Outward from the curve: perpendicular to its tangent (1, 3x^2), away from the inside.
    EXPECT_NEAR(glm::length(out[0].normal - glm::normalize(Vec3(3 * x * x, 0, -1))), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace convray::geometry
