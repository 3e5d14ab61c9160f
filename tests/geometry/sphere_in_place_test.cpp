// A sphere under a similarity (translation, rotation, uniform scale, mirror) is built in its
// placed position instead of behind a TransformedShape: the same crossings, normals and inside
// answers as the sphere in its own space seen through the transform.
#include <gtest/gtest.h>

#include "geometry/sphere.hpp"
#include "geometry/transformed.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::make_object;

TEST(SphereInPlace, MatchesTheSphereSeenThroughItsTransform) {
  const std::vector<scene::Transform> placements = {
      scene::Transform::translation({0.3, -2.0, 5.0}),
      scene::Transform::rotation({20, 30, 40}).then(scene::Transform::translation({1, 2, 3})),
      scene::Transform::scaling(Vec3(2.5)).then(scene::Transform::rotation({0, 45, 0})),
      scene::Transform::scaling({-1.5, 1.5, 1.5}),  // a mirror
  };
  const scene::Sphere own{{0.5, -0.25, 1.0}, 0.8};
  std::mt19937_64 rng(31);
  for (const scene::Transform& placement : placements) {
    const ShapePtr placed = testing::build(own, placement);
    auto surface = std::make_shared<SurfaceInfo>();
    surface->texture = std::make_shared<const scene::Texture>(scene::default_texture());
    const TransformedShape reference(std::make_unique<SphereShape>(own.center, own.radius, surface),
                                     placement);
    EXPECT_EQ(dynamic_cast<const TransformedShape*>(placed.get()), nullptr);  // built in place
    const Vec3 center = placement.point(own.center);
    int hits = 0;
    TraceStats stats;
    for (int i = 0; i < 500; ++i) {
      const Ray ray = testing::random_ray(rng, center, 12.0, 1.0);
      std::vector<Crossing> fast, slow;
      placed->crossings(ray, 0.0, 30.0, fast, stats);
      reference.crossings(ray, 0.0, 30.0, slow, stats);
      ASSERT_EQ(fast.size(), slow.size()) << i;
      hits += !fast.empty();
      for (size_t k = 0; k < fast.size(); ++k) {
        EXPECT_NEAR(fast[k].t, slow[k].t, 1e-9 * (1.0 + slow[k].t)) << i;
        EXPECT_LT(glm::length(fast[k].normal - slow[k].normal), 1e-7) << i;
      }
      const Vec3 p = ray.at(std::uniform_real_distribution<double>(8.0, 16.0)(rng));
      EXPECT_EQ(placed->inside(p), reference.inside(p)) << i;
    }
    EXPECT_GT(hits, 100);
  }
}

TEST(SphereInPlace, OtherPlacementsStayBehindTheirTransform) {
  // A stretched sphere is an ellipsoid; clipped_by lives in the sphere's own space.
  const scene::Sphere own{{0, 0, 0}, 1.0};
  const ShapePtr stretched = testing::build(own, scene::Transform::scaling({1, 2, 1}));
  EXPECT_NE(dynamic_cast<const TransformedShape*>(stretched.get()), nullptr);
  auto clipped = make_object(own, scene::Transform::translation({1, 0, 0}));
  clipped->clipped_by.push_back(make_object(scene::Plane{{0, 1, 0}, 0.0}));
  const ShapePtr shape = build_shape(*clipped);
  EXPECT_NE(dynamic_cast<const TransformedShape*>(shape.get()), nullptr);
  TraceStats stats;
  // Kept below y = 0 of its own space, which is y = 0 once translated along x.
  EXPECT_TRUE(shape->first_crossing(Ray{{1, -0.5, 5}, {0, 0, -1}}, 0.0, 10.0, stats));
  EXPECT_FALSE(shape->first_crossing(Ray{{1, 0.5, 5}, {0, 0, -1}}, 0.0, 10.0, stats));
}

}  // namespace
}  // namespace convray::geometry
