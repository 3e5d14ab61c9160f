// CSG against brute-force point classification: along random rays, where the combined
// inside() changes is found by dense sampling, and the crossings must be exactly there,
// with normals facing out of the combined solid. Union keeps internal surfaces, which the
// classification cannot see: it is checked against the children's crossings instead.
#include <gtest/gtest.h>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using scene::CsgOperation;
using testing::make_object;

scene::ObjectPtr sphere(const Vec3& c, double r) { return make_object(scene::Sphere{c, r}); }
scene::ObjectPtr box(const Vec3& a, const Vec3& b) { return make_object(scene::Box{a, b}); }

ShapePtr csg(CsgOperation op, std::vector<scene::ObjectPtr> children) {
  return build_shape(*make_object(scene::Csg{op, std::move(children)}));
}

// Three overlapping solids of different kinds: the children of every test.
std::vector<scene::ObjectPtr> three_children() {
  return {sphere({0, 0, 0}, 1.0), box({0, -0.5, -0.5}, {1.5, 0.5, 0.5}),
          make_object(scene::Cylinder{{0.2, -1.5, 0}, {0.2, 1.5, 0}, 0.4, false})};
}

void check_operation(CsgOperation op, uint64_t seed) {
  const ShapePtr shape = csg(op, three_children());
  std::mt19937_64 rng(seed);
  int checked = 0, with_crossings = 0;
  for (int i = 0; i < 400; ++i) {
    const Ray ray = testing::random_ray(rng, {0.2, 0, 0}, 5.0, 1.2);
    const bool resolved = testing::check_crossings_against_inside(*shape, ray, 0.0, 10.0, 1e-9);
    checked += resolved;
    if (resolved) with_crossings += !testing::crossing_distances(*shape, ray, 0, 10).empty();
    // first_crossing is the first of crossings.
    TraceStats stats;
    const auto all = testing::crossing_distances(*shape, ray, 0.0, 10.0);
    const auto first = shape->first_crossing(ray, 0.0, 10.0, stats);
    ASSERT_EQ(first.has_value(), !all.empty());
    if (first) {
      EXPECT_EQ(first->t, all.front());
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(with_crossings, 100);
}

TEST(Csg, IntersectionMatchesPointClassification) {
  check_operation(CsgOperation::intersection, 21);
}
TEST(Csg, DifferenceMatchesPointClassification) { check_operation(CsgOperation::difference, 22); }
TEST(Csg, MergeMatchesPointClassification) { check_operation(CsgOperation::merge, 23); }

TEST(Csg, InsideFollowsTheOperations) {
  const Vec3 in_sphere_only(-0.8, 0, 0.5), in_all(0.3, 0, 0.1);
  const ShapePtr u = csg(CsgOperation::union_, three_children());
  const ShapePtr i = csg(CsgOperation::intersection, three_children());
  const ShapePtr d = csg(CsgOperation::difference, three_children());
  EXPECT_TRUE(u->inside(in_sphere_only));
  EXPECT_FALSE(i->inside(in_sphere_only));
  EXPECT_TRUE(d->inside(in_sphere_only));
  EXPECT_TRUE(i->inside(in_all));
  EXPECT_FALSE(d->inside(in_all));  // in the box: cut away
  EXPECT_FALSE(u->inside(Vec3(3, 0, 0)));
}

TEST(Csg, UnionKeepsEveryChildsCrossings) {
  const auto children = three_children();
  const ShapePtr u = csg(CsgOperation::union_, children);
  std::vector<ShapePtr> parts;
  for (const auto& c : children) parts.push_back(build_shape(*c));
  std::mt19937_64 rng(24);
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, {0.2, 0, 0}, 5.0, 1.2);
    std::vector<double> expected;
    for (const auto& p : parts) {
      for (double t : testing::crossing_distances(*p, ray, 0.0, 10.0)) expected.push_back(t);
    }
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(testing::crossing_distances(*u, ray, 0.0, 10.0), expected);
    TraceStats stats;
    const auto first = u->first_crossing(ray, 0.0, 10.0, stats);
    ASSERT_EQ(first.has_value(), !expected.empty());
    if (first) {
      EXPECT_EQ(first->t, expected.front());
    }
  }
}

TEST(Csg, DifferenceFlipsTheCutSurfacesNormals) {
  // A box minus a sphere centred on its top face: a ray down the axis meets the sphere's
  // surface from inside the sphere, where it is the box's outside.
  const ShapePtr d =
      csg(CsgOperation::difference, {box({-1, -1, -1}, {1, 1, 1}), sphere({0, 1, 0}, 0.5)});
  std::vector<Crossing> out;
  TraceStats stats;
  d->crossings(Ray{{0, 5, 0}, {0, -1, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 4.5, 1e-14);  // the bottom of the dimple
  EXPECT_NEAR(glm::length(out[0].normal - Vec3(0, 1, 0)), 0.0, 1e-14);
  EXPECT_NEAR(out[1].t, 6.0, 1e-14);  // the box's bottom
  EXPECT_EQ(out[1].normal, Vec3(0, -1, 0));
}

TEST(Csg, NestedCsgAndPlanesInIntersections) {
  // A half-sphere: the intersection of a sphere and the half-space below y = 0, minus a
  // small box; nested inside a merge with another sphere.
  auto half =
      make_object(scene::Csg{CsgOperation::intersection,
                             {sphere({0, 0, 0}, 1.0), make_object(scene::Plane{{0, 1, 0}, 0})}});
  auto cut = make_object(
      scene::Csg{CsgOperation::difference, {half, box({-0.2, -2, -0.2}, {0.2, -0.5, 0.2})}});
  const ShapePtr shape = build_shape(
      *make_object(scene::Csg{CsgOperation::merge, {cut, sphere({0.8, -0.3, 0}, 0.4)}}));
  // Bounded although a child is a plane.
  EXPECT_TRUE(is_finite(shape->bounds()));
  std::mt19937_64 rng(25);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = testing::random_ray(rng, {0, -0.3, 0}, 5.0, 1.0);
    checked += testing::check_crossings_against_inside(*shape, ray, 0.0, 10.0, 1e-9);
  }
  EXPECT_GT(checked, 250);
}

TEST(Csg, IntersectionWithADiscUsesItsHalfSpace) {
  // POV-Ray's disc is inside behind its normal, so intersecting a sphere with it halves it.
  const ShapePtr shape =
      csg(CsgOperation::intersection,
          {sphere({0, 0, 0}, 1.0), make_object(scene::Disc{{0, 0, 0}, {0, 1, 0}, 5.0, 0.0})});
  const auto t = testing::crossing_distances(*shape, Ray{{0.5, 5, 0}, {0, -1, 0}}, 0, INFINITY);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0], 5.0);  // the disc, inside the sphere
  EXPECT_NEAR(t[1], 5.0 + std::sqrt(0.75), 1e-14);
}

}  // namespace
}  // namespace convray::geometry
