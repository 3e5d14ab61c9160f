// The World against its brute-force twin (every object asked), texture and interior
// inheritance, shadows, and the errors degenerate records give.
#include <gtest/gtest.h>

#include <chrono>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::make_object;

scene::Scene many_spheres(int count, uint64_t seed) {
  scene::Scene scene;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-20, 20), r(0.1, 0.6);
  for (int i = 0; i < count; ++i) {
    scene.objects.push_back(make_object(scene::Sphere{{u(rng), u(rng), u(rng)}, r(rng)}));
  }
  scene.objects.push_back(make_object(scene::Plane{{0, 1, 0}, -25.0}));
  scene.objects.push_back(
      make_object(scene::Torus{3.0, 1.0}, scene::Transform::rotation({90, 0, 0})));
  return scene;
}

TEST(World, FirstHitMatchesBruteForceOverThousandsOfObjects) {
  const World world(many_spheres(5000, 61));
  EXPECT_EQ(world.object_count(), 5002u);
  EXPECT_TRUE(is_finite(world.bounds()));  // the plane is left out
  std::mt19937_64 rng(62);
  int hits = 0;
  TraceStats stats;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 40.0, 25.0);
    const auto fast = world.first_hit(ray, 1e-6, INFINITY, stats);
    const auto slow = world.first_hit_brute_force(ray, 1e-6, INFINITY, stats);
    ASSERT_EQ(fast.has_value(), slow.has_value()) << i;
    if (!fast) continue;
    ++hits;
    EXPECT_EQ(fast->t, slow->t);
    EXPECT_EQ(fast->normal, slow->normal);
    EXPECT_EQ(fast->surface, slow->surface);
  }
  EXPECT_GT(hits, 1000);
}

TEST(World, FirstHitIsFastWithManyObjects) {
  const World world(many_spheres(20000, 63));
  std::mt19937_64 rng(64);
  TraceStats stats;
  const auto start = std::chrono::steady_clock::now();
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    hits += world.first_hit(testing::random_ray(rng, {0, 0, 0}, 40.0, 25.0), 0.0, INFINITY, stats)
                .has_value();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(hits, 0);
  // Brute force would ask 20,000 objects per ray (4e8 tests); the hierarchy a few dozen.
  EXPECT_LT(seconds, 2.0);
}

TEST(World, ShadowCrossingsAreEveryCastingObjectsCrossingsAscending) {
  scene::Scene scene = many_spheres(300, 65);
  auto shy = make_object(scene::Sphere{{0, 0, 0}, 5.0});
  shy->no_shadow = true;
  scene.objects.push_back(shy);
  const World world(scene);
  std::mt19937_64 rng(66);
  TraceStats stats;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 40.0, 10.0);
    std::vector<Crossing> fast, slow;
    world.shadow_crossings(ray, 0.0, 60.0, fast, stats);
    world.shadow_crossings_brute_force(ray, 0.0, 60.0, slow, stats);
    ASSERT_EQ(fast.size(), slow.size()) << i;
    for (size_t k = 0; k < fast.size(); ++k) {
      EXPECT_EQ(fast[k].t, slow[k].t);
      if (k > 0) {
        EXPECT_LE(fast[k - 1].t, fast[k].t);
      }
      EXPECT_FALSE(fast[k].surface->no_shadow);
    }
  }
  // The no_shadow sphere is seen, but casts nothing.
  const Ray through{{0, 0, -30}, {0, 0, 1}};
  const auto hit = world.first_hit(through, 0.0, INFINITY, stats);
  std::vector<Crossing> shadow;
  world.shadow_crossings(through, 24.0, 26.0, shadow, stats);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(world.inside_any({0, 0, 0}));
  EXPECT_TRUE(shadow.empty());
}

TEST(World, InsideAnyAndEmptyScenes) {
  scene::Scene scene;
  const World empty(scene);
  TraceStats stats;
  EXPECT_FALSE(empty.first_hit(Ray{}, 0.0, INFINITY, stats));
  EXPECT_FALSE(empty.inside_any({0, 0, 0}));
  EXPECT_TRUE(is_empty(empty.bounds()));
  scene.objects.push_back(make_object(scene::Box{{0, 0, 0}, {1, 1, 1}}));
  scene.objects.push_back(make_object(scene::Plane{{0, 1, 0}, -3.0}));
  const World world(scene);
  EXPECT_TRUE(world.inside_any({0.5, 0.5, 0.5}));
  EXPECT_TRUE(world.inside_any({50, -4, 0}));  // below the plane
  EXPECT_FALSE(world.inside_any({50, 0, 0}));
}

TEST(Inheritance, ChildrenTakeTheirParentsTextureAndInteriorDefaultOtherwise) {
  const auto parent_texture = testing::make_texture(0.3), own = testing::make_texture(0.9);
  auto a = make_object(scene::Sphere{{-2, 0, 0}, 1.0});  // nothing of its own
  auto b = make_object(scene::Sphere{{2, 0, 0}, 1.0});
  b->texture = own;
  b->interior = scene::Interior{1.5};
  auto group = make_object(scene::Csg{scene::CsgOperation::union_, {a, b}});
  group->texture = parent_texture;
  group->interior = scene::Interior{1.33};
  scene::Scene scene;
  scene.objects.push_back(group);
  auto bare = make_object(scene::Sphere{{0, 5, 0}, 1.0});
  scene.objects.push_back(bare);
  const World world(scene);
  TraceStats stats;
  const auto hit_a = world.first_hit(Ray{{-2, 0, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  const auto hit_b = world.first_hit(Ray{{2, 0, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  const auto hit_bare = world.first_hit(Ray{{0, 5, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  ASSERT_TRUE(hit_a && hit_b && hit_bare);
  EXPECT_EQ(hit_a->surface->texture, parent_texture);
  EXPECT_EQ(hit_a->surface->interior.ior, 1.33);
  EXPECT_EQ(hit_b->surface->texture, own);
  EXPECT_EQ(hit_b->surface->interior.ior, 1.5);
  // POV-Ray's default: a black pigment, the default finish, interior ior 1.
  ASSERT_TRUE(hit_bare->surface->texture);
  EXPECT_EQ(hit_bare->surface->texture->pigment.color.rgb, Vec3(0.0));
  EXPECT_EQ(hit_bare->surface->texture->finish.diffuse, scene::default_texture().finish.diffuse);
  EXPECT_EQ(hit_bare->surface->interior.ior, 1.0);
}

TEST(Errors, DegenerateRecordsAreInputErrorsAtTheObject) {
  auto expect_error = [](scene::Shape shape, scene::Transform transform = {}) {
    try {
      build_shape(*make_object(std::move(shape), transform));
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.loc().file, "test.pov");
      EXPECT_EQ(e.loc().line, 7);
      EXPECT_FALSE(e.message().empty());
    }
  };
  expect_error(scene::Sphere{{0, 0, 0}, 0.0});
  expect_error(scene::Cone{{0, 0, 0}, 0.0, {0, 1, 0}, 0.0, false});
  expect_error(scene::Cylinder{{1, 1, 1}, {1, 1, 1}, 0.5, false});
  expect_error(scene::Cylinder{{0, 0, 0}, {0, 1, 0}, 0.0, false});
  expect_error(scene::Torus{1.0, 0.0});
  expect_error(scene::Disc{{0, 0, 0}, {0, 0, 0}, 1.0, 0.0});
  expect_error(scene::Plane{{0, 0, 0}, 1.0});
  expect_error(scene::Sphere{{0, 0, 0}, NAN});
  // Two tiny scales make a transform whose determinant underflows to zero.
  const auto tiny = scene::Transform::scaling(Vec3(1e-110));
  expect_error(scene::Sphere{{0, 0, 0}, 1.0}, tiny.then(tiny));
  // A CSG child's error points at the child.
  auto child = make_object(scene::Sphere{{0, 0, 0}, 0.0});
  child->loc = SourceLoc{"child.pov", 12, 1};
  try {
    build_shape(*make_object(scene::Csg{scene::CsgOperation::union_, {child}}));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().file, "child.pov");
  }
  // A negative sphere radius draws the same sphere (POV-Ray squares it).
  const ShapePtr negative = testing::build(scene::Sphere{{0, 0, 0}, -2.0});
  EXPECT_TRUE(negative->inside({1.9, 0, 0}));
}

}  // namespace
}  // namespace convray::geometry
