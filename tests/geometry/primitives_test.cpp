// The classic primitives against hand-derived intersections (axis-aligned rays whose roots
// are known by heart) and against brute-force classification along random rays.
#include <gtest/gtest.h>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::build;
using testing::check_crossings_against_inside;
using testing::crossing_distances;
using testing::random_ray;

TEST(Sphere, AxisRayCrossesAtCentreMinusAndPlusRadius) {
  const ShapePtr sphere = build(scene::Sphere{{1, 2, 3}, 2.0});
  const Ray ray{{1, 2, -10}, {0, 0, 1}};
  std::vector<Crossing> out;
  TraceStats stats;
  sphere->crossings(ray, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[0].t, 11.0);
  EXPECT_DOUBLE_EQ(out[1].t, 15.0);
  EXPECT_EQ(out[0].normal, Vec3(0, 0, -1));
  EXPECT_EQ(out[1].normal, Vec3(0, 0, 1));
  // Starting inside: only the way out.
  EXPECT_EQ(crossing_distances(*sphere, ray, 12.0, INFINITY), std::vector<double>{15.0});
  EXPECT_TRUE(sphere->inside({1, 2, 3}));
  EXPECT_FALSE(sphere->inside({1, 4.1, 3}));
  const Box3 b = sphere->bounds();
  EXPECT_EQ(b.lo, Vec3(-1, 0, 1));
  EXPECT_EQ(b.hi, Vec3(3, 4, 5));
}

TEST(Sphere, RandomRaysMatchTheQuadraticAndKeepDigitsFromAfar) {
  const Vec3 c(0.5, -1.0, 2.0);
  const double r = 1.5;
  const ShapePtr sphere = build(scene::Sphere{c, r});
  std::mt19937_64 rng(1);
  for (int i = 0; i < 2000; ++i) {
    const double distance = i < 1000 ? 5.0 : 1e5;
    const Ray ray = random_ray(rng, c, distance, 1.2 * r);
    // The plain formula, every step in long double (64-bit mantissa) from the same inputs.
    // The direction's length is 1 only up to rounding, which moves roots 1e5 away by 1e-6.
    long double a = 0.0L, b = 0.0L, ww = 0.0L;
    for (int k = 0; k < 3; ++k) {
      const long double w = (long double)ray.origin[k] - (long double)c[k];
      a += (long double)ray.direction[k] * (long double)ray.direction[k];
      b += w * (long double)ray.direction[k];
      ww += w * w;
    }
    const long double disc = b * b - a * (ww - (long double)r * r);
    const auto t = crossing_distances(*sphere, ray, 0.0, INFINITY);
    if (disc < 1e-6L * r * r) continue;  // grazing: either answer
    ASSERT_EQ(t.size(), 2u) << i;
    EXPECT_NEAR(t[0], double((-b - std::sqrt(disc)) / a), 1e-12 * distance) << i;
    EXPECT_NEAR(t[1], double((-b + std::sqrt(disc)) / a), 1e-12 * distance) << i;
  }
}

TEST(Box, SlabsGiveTheFacesAndTheirNormals) {
  const ShapePtr box = build(scene::Box{{1, 1, 1}, {-1, -2, -3}});  // any two corners
  std::vector<Crossing> out;
  TraceStats stats;
  box->crossings(Ray{{5, 0, 0}, {-1, 0, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].t, 4.0);
  EXPECT_EQ(out[0].normal, Vec3(1, 0, 0));
  EXPECT_EQ(out[1].t, 6.0);
  EXPECT_EQ(out[1].normal, Vec3(-1, 0, 0));
  // A diagonal ray enters through the face whose slab it reaches last (y = -2 at 3 sqrt 2,
  // after x = -1 at 2 sqrt 2) and leaves through the first it leaves (x = 1 at 4 sqrt 2).
  out.clear();
  const Ray diagonal{{-3, -5, 0}, glm::normalize(Vec3(1, 1, 0))};
  box->crossings(diagonal, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 3.0 * std::sqrt(2.0), 1e-14);
  EXPECT_EQ(out[0].normal, Vec3(0, -1, 0));
  EXPECT_NEAR(out[1].t, 4.0 * std::sqrt(2.0), 1e-14);
  EXPECT_EQ(out[1].normal, Vec3(1, 0, 0));
  // Parallel to a slab and outside it: nothing.
  EXPECT_TRUE(crossing_distances(*box, Ray{{0, 5, 0}, {1, 0, 0}}, -INFINITY, INFINITY).empty());
  EXPECT_TRUE(box->inside({0.5, -1.5, -2.5}));
  EXPECT_FALSE(box->inside({0.5, -2.5, -2.5}));
}

TEST(Box, RandomRaysAgreeWithInsideChanges) {
  const ShapePtr box = build(scene::Box{{-1, -0.5, -2}, {2, 0.5, 1}});
  std::mt19937_64 rng(2);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = random_ray(rng, {0.5, 0, -0.5}, 6.0, 2.0);
    checked += check_crossings_against_inside(*box, ray, 0.0, 12.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

TEST(Plane, CrossesOnceAndHalfSpaceBelowIsInside) {
  // y = 2 with a non-unit normal: the distance is along the unit normal.
  const ShapePtr plane = build(scene::Plane{{0, 3, 0}, 2.0});
  std::vector<Crossing> out;
  TraceStats stats;
  plane->crossings(Ray{{0, 10, 0}, {0, -1, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].t, 8.0);
  EXPECT_EQ(out[0].normal, Vec3(0, 1, 0));
  EXPECT_TRUE(plane->inside({100, 1.9, -7}));
  EXPECT_FALSE(plane->inside({100, 2.1, -7}));
  EXPECT_TRUE(crossing_distances(*plane, Ray{{0, 10, 0}, {1, 0, 0}}, 0, INFINITY).empty());
  EXPECT_FALSE(is_finite(plane->bounds()));
  // A tilted plane against the formula t = (d - o.n) / (dir.n).
  const Vec3 n = glm::normalize(Vec3(1, 2, -1));
  const ShapePtr tilted = build(scene::Plane{{1, 2, -1}, -0.5});
  std::mt19937_64 rng(3);
  for (int i = 0; i < 100; ++i) {
    const Ray ray = random_ray(rng, {0, 0, 0}, 4.0, 1.0);
    const double expected = (-0.5 - glm::dot(ray.origin, n)) / glm::dot(ray.direction, n);
    const auto t = crossing_distances(*tilted, ray, 0.0, INFINITY);
    if (expected > 0.0) {
      ASSERT_EQ(t.size(), 1u);
      EXPECT_NEAR(t[0], expected, 1e-12 * std::abs(expected));
    } else {
      EXPECT_TRUE(t.empty());
    }
  }
}

TEST(Cylinder, AxisAlignedRaysHitSideAndCaps) {
  const ShapePtr cylinder = build(scene::Cylinder{{0, -1, 0}, {0, 3, 0}, 0.5, false});
  // Across the body.
  std::vector<Crossing> out;
  TraceStats stats;
  cylinder->crossings(Ray{{-5, 1, 0}, {1, 0, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[0].t, 4.5);
  EXPECT_DOUBLE_EQ(out[1].t, 5.5);
  EXPECT_NEAR(glm::length(out[0].normal - Vec3(-1, 0, 0)), 0.0, 1e-15);
  // Along the axis: through both caps.
  out.clear();
  cylinder->crossings(Ray{{0.2, 10, 0}, {0, -1, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[0].t, 7.0);
  EXPECT_EQ(out[0].normal, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(out[1].t, 11.0);
  EXPECT_EQ(out[1].normal, Vec3(0, -1, 0));
  // Open: the caps are not drawn, but (as POV-Ray) the inside is still the solid.
  const ShapePtr open = build(scene::Cylinder{{0, -1, 0}, {0, 3, 0}, 0.5, true});
  EXPECT_TRUE(crossing_distances(*open, Ray{{0.2, 10, 0}, {0, -1, 0}}, 0, INFINITY).empty());
  EXPECT_EQ(crossing_distances(*open, Ray{{-5, 1, 0}, {1, 0, 0}}, 0, INFINITY).size(), 2u);
  EXPECT_TRUE(open->inside({0, 0, 0}));
  EXPECT_FALSE(open->inside({0, 3.5, 0}));
}

TEST(Cylinder, RandomOrientationAgreesWithInsideChanges) {
  const ShapePtr cylinder = build(scene::Cylinder{{1, -1, 0.5}, {-1, 2, 1.5}, 0.7, false});
  std::mt19937_64 rng(4);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = random_ray(rng, {0, 0.5, 1}, 6.0, 2.0);
    checked += check_crossings_against_inside(*cylinder, ray, 0.0, 12.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

TEST(Cone, PointedConeAlongItsAxisAndAcross) {
  // Base radius 1 at y = 0, apex at y = 2.
  const ShapePtr cone = build(scene::Cone{{0, 0, 0}, 1.0, {0, 2, 0}, 0.0, false});
  // Horizontal ray at height 1: radius 0.5.
  const auto t = crossing_distances(*cone, Ray{{-3, 1, 0}, {1, 0, 0}}, 0.0, INFINITY);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[0], 2.5);
  EXPECT_DOUBLE_EQ(t[1], 3.5);
  // Down the axis: apex then base cap.
  std::vector<Crossing> out;
  TraceStats stats;
  cone->crossings(Ray{{0, 5, 0}, {0, -1, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[0].t, 3.0);
  EXPECT_DOUBLE_EQ(out[1].t, 5.0);
  EXPECT_EQ(out[1].normal, Vec3(0, -1, 0));
  // The side's normal at (0.5, 1, 0): the slope is 1/2, so (2, 1, 0) / sqrt 5.
  out.clear();
  cone->crossings(Ray{{-3, 1, 0}, {1, 0, 0}}, 0.0, INFINITY, out, stats);
  EXPECT_NEAR(glm::length(out[1].normal - glm::normalize(Vec3(2, 1, 0))), 0.0, 1e-15);
  // The mirror nappe above the apex is not part of the cone.
  EXPECT_TRUE(crossing_distances(*cone, Ray{{-3, 3, 0}, {1, 0, 0}}, 0, INFINITY).empty());
}

TEST(Cone, FrustumAndOpenConeAgreeWithInsideChanges) {
  const ShapePtr frustum = build(scene::Cone{{0, 0, 0}, 1.0, {0.5, 2, -0.5}, 0.3, false});
  const ShapePtr pointed = build(scene::Cone{{0, 2, 0}, 0.0, {0, -1, 1}, 1.2, false});
  std::mt19937_64 rng(5);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = random_ray(rng, {0.2, 1, -0.2}, 6.0, 1.5);
    checked += check_crossings_against_inside(*frustum, ray, 0.0, 12.0, 1e-9);
    checked += check_crossings_against_inside(*pointed, ray, 0.0, 12.0, 1e-9);
  }
  EXPECT_GT(checked, 500);
  // Open: only the side, and every side crossing is on the cone's surface.
  const ShapePtr open = build(scene::Cone{{0, 0, 0}, 1.0, {0, 2, 0}, 0.4, true});
  for (int i = 0; i < 200; ++i) {
    const Ray ray = random_ray(rng, {0, 1, 0}, 5.0, 1.5);
    for (double t : crossing_distances(*open, ray, 0.0, INFINITY)) {
      const Vec3 p = ray.at(t);
      EXPECT_NEAR(std::hypot(p.x, p.z), 1.0 - 0.3 * p.y, 1e-12);
      EXPECT_GE(p.y, -1e-12);
      EXPECT_LE(p.y, 2.0 + 1e-12);
    }
  }
}

TEST(Disc, HitsTheAnnulusOnlyAndItsInsideIsBehindTheNormal) {
  const ShapePtr disc = build(scene::Disc{{0, 1, 0}, {0, 2, 0}, 2.0, 0.5});
  std::vector<Crossing> out;
  TraceStats stats;
  disc->crossings(Ray{{1, 5, 0}, {0, -1, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].t, 4.0);
  EXPECT_EQ(out[0].normal, Vec3(0, 1, 0));
  EXPECT_TRUE(crossing_distances(*disc, Ray{{0.2, 5, 0}, {0, -1, 0}}, 0, INFINITY).empty());
  EXPECT_TRUE(crossing_distances(*disc, Ray{{2.1, 5, 0}, {0, -1, 0}}, 0, INFINITY).empty());
  EXPECT_TRUE(disc->inside({50, 0.5, 50}));  // POV-Ray: behind the normal is inside
  EXPECT_FALSE(disc->inside({0, 1.5, 0}));
  const Box3 b = disc->bounds();
  EXPECT_EQ(b.lo, Vec3(-2, 1, -2));
  EXPECT_EQ(b.hi, Vec3(2, 1, 2));
  // Tilted: crossings lie in the plane, within the annulus.
  const Vec3 n = glm::normalize(Vec3(1, 1, 1));
  const ShapePtr tilted = build(scene::Disc{{0, 0, 0}, {1, 1, 1}, 1.0, 0.25});
  std::mt19937_64 rng(6);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = random_ray(rng, {0, 0, 0}, 4.0, 1.2);
    const double t_plane = -glm::dot(ray.origin, n) / glm::dot(ray.direction, n);
    const double r = glm::length(ray.at(t_plane));
    const auto t = crossing_distances(*tilted, ray, 0.0, INFINITY);
    const bool expected = t_plane > 0 && r >= 0.25 && r <= 1.0;
    if (std::abs(r - 1.0) < 1e-9 || std::abs(r - 0.25) < 1e-9) continue;
    ASSERT_EQ(t.size(), expected ? 1u : 0u) << i;
    if (expected) {
      EXPECT_NEAR(t[0], t_plane, 1e-13);
      ++hits;
    }
    EXPECT_TRUE(contains(tilted->bounds(), ray.at(t_plane)) || !expected);
  }
  EXPECT_GT(hits, 100);
}

TEST(Bounds, TransformedInfiniteBoxesStayInfiniteWithoutNaN) {
  const Box3 half{Vec3(-INFINITY, -INFINITY, -INFINITY), Vec3(INFINITY, 2.0, INFINITY)};
  const Box3 moved = transform_box(scene::Transform::translation({1, 1, 1}).forward(), half);
  EXPECT_EQ(moved.hi.y, 3.0);
  EXPECT_EQ(moved.lo.x, -INFINITY);
  const Box3 turned = transform_box(scene::Transform::rotation({0, 0, 90}).forward(), half);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_FALSE(std::isnan(turned.lo[axis]) || std::isnan(turned.hi[axis]));
  }
  EXPECT_EQ(turned.lo.x, -2.0);  // rotate z 90: y becomes -x in POV-Ray's convention
  EXPECT_EQ(turned.hi.x, INFINITY);
}

}  // namespace
}  // namespace convray::geometry
