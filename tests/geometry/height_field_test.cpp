// height_field: vertical rays against the triangles' planes written out independently (each
// cell split along its diagonal from (x1, z0) to (x0, z1), as the povray binary's trace()
// shows), the water level, and inside (over the unit square, below the surface).
#include <random>

#include "geometry/height_field.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry::testing {
namespace {

// 4 x 3 vertices: h(i, j) = 0.1 i + 0.2 j + 0.05 (i j mod 3).
scene::HeightField small_field() {
  scene::HeightField f;
  f.columns = 4;
  f.rows = 3;
  for (int j = 0; j < f.rows; ++j) {
    for (int i = 0; i < f.columns; ++i) f.heights.push_back(0.1 * i + 0.2 * j + 0.05 * ((i * j) % 3));
  }
  return f;
}

// The height over (x, z) from the three corners of the triangle holding it, by barycentric
// coordinates in the x-z plane.
double expected_height(const scene::HeightField& f, double x, double z) {
  const double gx = x * (f.columns - 1), gz = z * (f.rows - 1);
  const int i = std::min(int(gx), f.columns - 2), j = std::min(int(gz), f.rows - 2);
  const auto h = [&](int a, int b) { return f.heights[size_t(b * f.columns + a)]; };
  const Vec2 p(gx - i, gz - j);
  // Triangle (0,0) (1,0) (0,1) when p.x + p.y <= 1, else (1,1) (1,0) (0,1).
  const bool lower = p.x + p.y <= 1;
  const Vec2 a = lower ? Vec2(0, 0) : Vec2(1, 1), b(1, 0), c(0, 1);
  const double ha = lower ? h(i, j) : h(i + 1, j + 1);
  const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const double wb = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
  const double wc = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
  return (1 - wb - wc) * ha + wb * h(i + 1, j) + wc * h(i, j + 1);
}

TEST(HeightField, VerticalRaysMeetTheCellTriangles) {
  const scene::HeightField f = small_field();
  const ShapePtr shape = build(f);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.001, 0.999);
  for (int k = 0; k < 500; ++k) {
    const double x = u(rng), z = u(rng);
    const auto t = crossing_distances(*shape, Ray{{x, 2.0, z}, {0, -1, 0}}, 0.0, INFINITY);
    ASSERT_EQ(t.size(), 1u) << x << ", " << z;
    EXPECT_NEAR(2.0 - t[0], expected_height(f, x, z), 1e-12) << x << ", " << z;
    EXPECT_TRUE(shape->inside({x, expected_height(f, x, z) - 1e-6, z}));
    EXPECT_TRUE(shape->inside({x, -5.0, z}));  // POV-Ray: at any depth below
    EXPECT_FALSE(shape->inside({x, expected_height(f, x, z) + 1e-6, z}));
  }
  EXPECT_FALSE(shape->inside({1.5, 0.0, 0.5}));
  EXPECT_TRUE(crossing_distances(*shape, Ray{{1.5, 2.0, 0.5}, {0, -1, 0}}, 0, INFINITY).empty());
}

TEST(HeightField, WaterLevelHidesTheSurfaceBelowIt) {
  scene::HeightField f = small_field();
  f.water_level = 0.3;
  const ShapePtr shape = build(f);
  for (double x = 0.02; x < 1.0; x += 0.07) {
    for (double z = 0.02; z < 1.0; z += 0.07) {
      const double h = expected_height(f, x, z);
      if (std::abs(h - 0.3) < 1e-9) continue;
      const auto t = crossing_distances(*shape, Ray{{x, 2.0, z}, {0, -1, 0}}, 0.0, INFINITY);
      EXPECT_EQ(t.size(), h > 0.3 ? 1u : 0u) << x << ", " << z;
    }
  }
}

}  // namespace
}  // namespace convray::geometry::testing
