// Placed objects against analytic forms (a scaled and rotated sphere is an ellipsoid), and
// the modifiers inverse, clipped_by and bounded_by against their definitions.
#include <gtest/gtest.h>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using scene::Transform;
using testing::build;
using testing::make_object;

TEST(Transform, ScaledRotatedSphereIsTheAnalyticEllipsoid) {
  const Transform placement = Transform::scaling({2.0, 0.5, 1.0})
                                  .then(Transform::rotation({30, 45, -20}))
                                  .then(Transform::translation({1, -2, 0.5}));
  const ShapePtr ellipsoid = build(scene::Sphere{{0, 0, 0}, 1.0}, placement);
  // The ellipsoid (p - c)^T Q (p - c) = 1 with Q = A^-T A^-1, A the linear part.
  const glm::dmat3 a(placement.forward());
  const glm::dmat3 a_inverse = glm::inverse(a);
  const glm::dmat3 q = glm::transpose(a_inverse) * a_inverse;
  const Vec3 c(1, -2, 0.5);
  std::mt19937_64 rng(31);
  int hits = 0;
  for (int i = 0; i < 1000; ++i) {
    const Ray ray = testing::random_ray(rng, c, 6.0, 2.0);
    const Vec3 w = ray.origin - c;
    const double qa = glm::dot(ray.direction, q * ray.direction);
    const double qb = glm::dot(w, q * ray.direction);
    const double qc = glm::dot(w, q * w) - 1.0;
    const double disc = qb * qb - qa * qc;
    std::vector<Crossing> out;
    TraceStats stats;
    ellipsoid->crossings(ray, 0.0, INFINITY, out, stats);
    if (disc < 1e-9) {
      if (disc < -1e-9) {
        EXPECT_TRUE(out.empty()) << i;
      }
      continue;
    }
    ASSERT_EQ(out.size(), 2u) << i;
    ++hits;
    const double roots[2] = {(-qb - std::sqrt(disc)) / qa, (-qb + std::sqrt(disc)) / qa};
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(out[size_t(k)].t, roots[k], 1e-10) << i;
      // The normal is the gradient of the quadratic form.
      const Vec3 expected = glm::normalize(q * (ray.at(roots[k]) - c));
      EXPECT_NEAR(glm::length(out[size_t(k)].normal - expected), 0.0, 1e-9) << i;
    }
    TraceStats s2;
    const auto first = ellipsoid->first_crossing(ray, 0.0, INFINITY, s2);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->t, out[0].t);
  }
  EXPECT_GT(hits, 300);
  // Inside, and the bounds hold the surface: (1, -2, 0.5) +- the half-axes.
  EXPECT_TRUE(ellipsoid->inside(c));
  const Box3 b = ellipsoid->bounds();
  for (int i = 0; i < 200; ++i) {
    const Ray ray = testing::random_ray(rng, c, 6.0, 2.0);
    for (double t : testing::crossing_distances(*ellipsoid, ray, 0.0, INFINITY)) {
      const Vec3 p = ray.at(t);
      EXPECT_TRUE(contains(Box3{b.lo - 1e-12, b.hi + 1e-12}, p));
    }
  }
}

TEST(Transform, TransformedCsgChildrenAndTorusAgreeWithInsideChanges) {
  auto torus = make_object(scene::Torus{1.0, 0.3}, Transform::rotation({90, 0, 0}));
  auto box = make_object(scene::Box{{-0.5, -2, -2}, {0.5, 2, 2}},
                         Transform::scaling({1, 1, 0.5}).then(Transform::rotation({0, 0, 30})));
  const ShapePtr shape =
      build(scene::Csg{scene::CsgOperation::difference, {torus, box}},
            Transform::scaling({1.5, 1, 1}).then(Transform::translation({0, 1, 0})));
  std::mt19937_64 rng(32);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 1, 0}, 6.0, 1.5);
    checked += testing::check_crossings_against_inside(*shape, ray, 0.0, 12.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

TEST(Modifiers, InverseSwapsInsideAndFlipsNormals) {
  auto object = make_object(scene::Sphere{{0, 0, 0}, 1.0});
  object->inverse = true;
  const ShapePtr inverted = build_shape(*object);
  EXPECT_FALSE(inverted->inside({0, 0, 0}));
  EXPECT_TRUE(inverted->inside({0, 3, 0}));
  std::vector<Crossing> out;
  TraceStats stats;
  inverted->crossings(Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].normal, Vec3(0, 0, 1));  // into the (now outside) ball: facing the ray's way
  EXPECT_FALSE(is_finite(inverted->inside_bounds()));
  EXPECT_TRUE(is_finite(inverted->bounds()));  // the surface is the same
}

TEST(Modifiers, ClippedByKeepsThePartInsideWithoutCapping) {
  // The lower half of a sphere: clipped by the half-space y < 0.
  auto object = make_object(scene::Sphere{{0, 0, 0}, 1.0});
  object->clipped_by.push_back(make_object(scene::Plane{{0, 1, 0}, 0.0}));
  const ShapePtr bowl = build_shape(*object);
  // Down the axis: the top is clipped away and nothing caps the cut; only the bottom.
  const auto t = testing::crossing_distances(*bowl, Ray{{0, 5, 0}, {0, -1, 0}}, 0, INFINITY);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0], 6.0);
  EXPECT_TRUE(bowl->inside({0, -0.5, 0}));
  EXPECT_FALSE(bowl->inside({0, 0.5, 0}));
  EXPECT_LE(bowl->bounds().hi.y, 0.0);  // the clip's half-space bounds the result
  // Every crossing of random rays is a sphere crossing below the plane.
  std::mt19937_64 rng(33);
  const ShapePtr whole = build(scene::Sphere{{0, 0, 0}, 1.0});
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 4.0, 1.2);
    std::vector<double> expected;
    for (double x : testing::crossing_distances(*whole, ray, 0.0, INFINITY)) {
      if (ray.at(x).y < 0.0) expected.push_back(x);
    }
    EXPECT_EQ(testing::crossing_distances(*bowl, ray, 0.0, INFINITY), expected);
  }
}

TEST(Modifiers, ClipMovesWithTheObjectsTransform) {
  // Clipping objects are in the object's own space: translating the clipped sphere moves
  // the cut with it.
  auto object = make_object(scene::Sphere{{0, 0, 0}, 1.0}, Transform::translation({0, 10, 0}));
  object->clipped_by.push_back(make_object(scene::Plane{{0, 1, 0}, 0.0}));
  const ShapePtr bowl = build_shape(*object);
  const auto t = testing::crossing_distances(*bowl, Ray{{0, 15, 0}, {0, -1, 0}}, 0, INFINITY);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0], 6.0);
}

TEST(Modifiers, BoundedByChangesNothingWhenItHoldsTheObject) {
  auto bounded = make_object(scene::Torus{1.0, 0.25});
  bounded->bounded_by = make_object(scene::Box{{-1.3, -0.3, -1.3}, {1.3, 0.3, 1.3}});
  const ShapePtr with = build_shape(*bounded);
  const ShapePtr without = build(scene::Torus{1.0, 0.25});
  std::mt19937_64 rng(34);
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 5.0, 2.0);
    EXPECT_EQ(testing::crossing_distances(*with, ray, 0.0, INFINITY),
              testing::crossing_distances(*without, ray, 0.0, INFINITY));
    EXPECT_EQ(with->inside(ray.at(5.0)), without->inside(ray.at(5.0)));
  }
  // A ray that misses the bound skips the object.
  auto tight = make_object(scene::Sphere{{0, 0, 0}, 1.0});
  tight->bounded_by = make_object(scene::Box{{-1, -1, -1}, {1, 0, 1}});
  EXPECT_TRUE(
      testing::crossing_distances(*build_shape(*tight), Ray{{-5, 0.5, 0}, {1, 0, 0}}, 0, INFINITY)
          .empty());
}

}  // namespace
}  // namespace convray::geometry
