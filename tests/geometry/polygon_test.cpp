// POV-Ray's polygon: rays against the letters of POV-Ray's objects/polygon.pov (a P with a
// hole, an O with one, a V), whose covered area is written independently here as unions and
// differences of rectangles, and a tilted square in 3D against the ray-plane intersection
// and the square's own coordinates.
#include <random>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry::testing {
namespace {

std::vector<Vec3> flat(std::initializer_list<Vec2> points) {
  std::vector<Vec3> out;
  for (const Vec2& p : points) out.emplace_back(p.x, p.y, 0.0);
  return out;
}

bool in_rect(double x, double y, double x0, double y0, double x1, double y1) {
  return x > x0 && x < x1 && y > y0 && y < y1;
}

// Shoots rays along -z at a grid of points (off the letters' edges, which lie on multiples
// of 0.5 ... ) and compares each hit with `covered`.
template <class Covered>
void expect_coverage(const scene::Polygon& polygon, Covered covered) {
  const ShapePtr shape = build(polygon);
  int hits = 0;
  for (double x = -0.93; x < 5.0; x += 0.1) {
    for (double y = -0.93; y < 7.0; y += 0.1) {
      const auto t = crossing_distances(*shape, Ray{{x, y, 3.0}, {0, 0, -1}}, 0.0, INFINITY);
      ASSERT_EQ(t.size(), covered(x, y) ? 1u : 0u) << x << ", " << y;
      if (!t.empty()) {
        EXPECT_EQ(t[0], 3.0);
        ++hits;
      }
    }
  }
  EXPECT_GT(hits, 100);
}

TEST(Polygon, LetterPWithAHoleByEvenOdd) {
  scene::Polygon p;
  p.outlines = {flat({{0, 0}, {0, 6}, {4, 6}, {4, 3}, {1, 3}, {1, 0}}),
                flat({{1, 4}, {1, 5}, {3, 5}, {3, 4}})};
  expect_coverage(p, [](double x, double y) {
    const bool outer = in_rect(x, y, 0, 0, 1, 6) || in_rect(x, y, 0, 3, 4, 6);
    return outer && !in_rect(x, y, 1, 4, 3, 5);
  });
}

TEST(Polygon, LetterOAndV) {
  scene::Polygon o;
  o.outlines = {flat({{0, 0}, {0, 6}, {4, 6}, {4, 0}}), flat({{1, 1}, {1, 5}, {3, 5}, {3, 1}})};
  expect_coverage(o, [](double x, double y) {
    return in_rect(x, y, 0, 0, 4, 6) && !in_rect(x, y, 1, 1, 3, 5);
  });
  // The V: between the lines from (1, 0) to (0, 6) and (2, 1) to (1, 6) on the left, their
  // mirror images about x = 2 on the right, below y = 6.
  scene::Polygon v;
  v.outlines = {flat({{1, 0}, {0, 6}, {1, 6}, {2, 1}, {3, 6}, {4, 6}, {3, 0}})};
  expect_coverage(v, [](double x, double y) {
    if (!(y > 0 && y < 6)) return false;
    const double left_outer = 1 - y / 6, right_outer = 3 + y / 6;
    if (!(x > left_outer && x < right_outer)) return false;
    if (y <= 1) return true;
    const double left_inner = 2 - (y - 1) / 5, right_inner = 2 + (y - 1) / 5;
    return !(x > left_inner && x < right_inner);
  });
}

TEST(Polygon, TiltedSquareInThreeDimensions) {
  // The square with corners c +- a +- b, in the plane through c spanned by a and b.
  const Vec3 c(0.3, -0.2, 0.5), a = Vec3(1, 1, 0) * 0.7, b = Vec3(-1, 1, 2) * 0.4;
  scene::Polygon square;
  square.outlines = {{c - a - b, c + a - b, c + a + b, c - a + b}};
  square.normal = glm::cross(a, b);
  const ShapePtr shape = build(square);
  const Vec3 n = glm::normalize(glm::cross(a, b));
  std::mt19937_64 rng(11);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = random_ray(rng, c, 5.0, 2.0);
    const double t_plane = glm::dot(c - ray.origin, n) / glm::dot(ray.direction, n);
    const Vec3 q = ray.at(t_plane) - c;
    const double s = glm::dot(q, a) / glm::dot(a, a), r = glm::dot(q, b) / glm::dot(b, b);
    if (std::abs(std::abs(s) - 1) < 1e-9 || std::abs(std::abs(r) - 1) < 1e-9) continue;
    const bool expected = t_plane > 0 && std::abs(s) < 1 && std::abs(r) < 1;
    const auto t = crossing_distances(*shape, ray, 0.0, INFINITY);
    ASSERT_EQ(t.size(), expected ? 1u : 0u) << i;
    if (expected) {
      EXPECT_NEAR(t[0], t_plane, 1e-12);
      EXPECT_TRUE(contains(shape->bounds(), ray.at(t[0])));
      ++hits;
    }
  }
  EXPECT_GT(hits, 300);
  EXPECT_FALSE(shape->inside(c));  // POV-Ray's polygon is not solid
}

}  // namespace
}  // namespace convray::geometry::testing
