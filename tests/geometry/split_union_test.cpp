// POV-Ray's split_union: a union's members go into the World's hierarchy one by one. The
// World must see the same surfaces as with the union kept whole (`split_union off`, where
// the union is one CsgShape with its own hierarchy) and as its brute-force twin: the same
// distances, the same inherited textures, interiors and no_shadow.
#include <gtest/gtest.h>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using scene::CsgOperation;
using testing::make_object;

// `n` spheres and boxes, every third with a texture of its own, to be put into two unions.
struct Members {
  std::vector<scene::ObjectPtr> outer, inner;
  scene::TexturePtr texture = testing::make_texture(0.5);  // the outer union's
};

Members make_members(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-8.0, 8.0), r(0.1, 0.5);
  Members m;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    auto member = i % 4 == 3 ? make_object(scene::Box{c - r(rng), c + r(rng)})
                             : make_object(scene::Sphere{c, r(rng)},
                                           scene::Transform::scaling({1.0, 1.5, 1.0}));
    if (i % 3 == 0) member->texture = testing::make_texture(0.01 * (i % 90));
    (i % 2 ? m.inner : m.outer).push_back(member);
  }
  return m;
}

// The members in a union nested in a union, placed by a rotation and translation, the outer
// one with its own texture and interior (the inner one with an interior only).
scene::Scene union_scene(const Members& m, bool split, bool no_shadow) {
  auto nested = make_object(scene::Csg{CsgOperation::union_, m.inner},
                            scene::Transform::translation({0.5, 0.0, 0.0}));
  nested->split_union = split;
  nested->interior = scene::Interior{1.2};
  std::vector<scene::ObjectPtr> outer = m.outer;
  outer.push_back(nested);
  auto group = make_object(scene::Csg{CsgOperation::union_, outer},
                           scene::Transform::rotation({10, 20, 30})
                               .then(scene::Transform::translation({1, 2, 3})));
  group->split_union = split;
  group->texture = m.texture;
  group->interior = scene::Interior{1.5};
  group->no_shadow = no_shadow;
  scene::Scene scene;
  scene.objects.push_back(group);
  auto floor = make_object(scene::Plane{{0, 1, 0}, -12.0});
  floor->texture = m.texture;  // every texture the worlds show comes from the records
  scene.objects.push_back(floor);
  return scene;
}

TEST(SplitUnion, MembersJoinTheWorldAndLookAsInTheWholeUnion) {
  const int n = 3000;
  const Members members = make_members(n, 5);
  const World split(union_scene(members, true, false)), whole(union_scene(members, false, false));
  EXPECT_EQ(split.object_count(), size_t(n) + 1);  // the members and the plane
  EXPECT_EQ(whole.object_count(), 2u);
  std::mt19937_64 rng(6);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = testing::random_ray(rng, {1, 2, 3}, 30.0, 12.0);
    const auto fast = split.first_hit(ray, 1e-6, INFINITY, stats);
    const auto slow = split.first_hit_brute_force(ray, 1e-6, INFINITY, stats);
    const auto kept = whole.first_hit(ray, 1e-6, INFINITY, stats);
    ASSERT_EQ(fast.has_value(), slow.has_value()) << i;
    ASSERT_EQ(fast.has_value(), kept.has_value()) << i;
    if (!fast) continue;
    hits += fast->t < 25.0;  // not the plane
    EXPECT_EQ(fast->t, slow->t);
    EXPECT_EQ(fast->surface, slow->surface);
    // The whole union places members through two transforms, the split one through their
    // product: the same surface to rounding.
    EXPECT_NEAR(fast->t, kept->t, 1e-9 * (1.0 + fast->t)) << i;
    EXPECT_LT(glm::length(fast->normal - kept->normal), 1e-7) << i;
    EXPECT_EQ(fast->surface->texture, kept->surface->texture) << i;
    EXPECT_EQ(fast->surface->interior.ior, kept->surface->interior.ior) << i;
    EXPECT_EQ(fast->surface->no_shadow, kept->surface->no_shadow) << i;
  }
  EXPECT_GT(hits, 1000);
}

TEST(SplitUnion, InheritanceFollowsTheNesting) {
  // union { A  B(texture)  union { C  D(texture, interior 2) interior 1.2 }  texture T
  //         interior 1.5  scale 2 translate y }: A takes T and 1.5, B its own and 1.5, C takes
  // T (the inner union has no texture) and 1.2, D its own and 2.
  const auto t = testing::make_texture(0.5), tb = testing::make_texture(0.2),
             td = testing::make_texture(0.8);
  auto a = make_object(scene::Sphere{{0, 0, 0}, 1.0});
  auto b = make_object(scene::Sphere{{3, 0, 0}, 1.0});
  b->texture = tb;
  auto c = make_object(scene::Sphere{{6, 0, 0}, 1.0});
  auto d = make_object(scene::Box{{8, -1, -1}, {10, 1, 1}});
  d->texture = td;
  d->interior = scene::Interior{2.0};
  auto inner = make_object(scene::Csg{CsgOperation::union_, {c, d}});
  inner->interior = scene::Interior{1.2};
  auto group = make_object(scene::Csg{CsgOperation::union_, {a, b, inner}},
                           scene::Transform::scaling(Vec3(2.0))
                               .then(scene::Transform::translation({0, 1, 0})));
  group->texture = t;
  group->interior = scene::Interior{1.5};
  scene::Scene scene;
  scene.objects.push_back(group);
  const World world(scene);
  EXPECT_EQ(world.object_count(), 4u);
  struct Expected {
    double x;
    scene::TexturePtr texture;
    double ior;
  };
  TraceStats stats;
  for (const Expected& e : {Expected{0, t, 1.5}, Expected{3, tb, 1.5}, Expected{6, t, 1.2},
                            Expected{9, td, 2.0}}) {
    // The member's centre is at (2x, 1, 0) once placed; its top at z = 2 (radius 1 scaled).
    const auto hit = world.first_hit(Ray{{2 * e.x, 1, 10}, {0, 0, -1}}, 0.0, INFINITY, stats);
    ASSERT_TRUE(hit) << e.x;
    EXPECT_NEAR(hit->t, 8.0, 1e-12) << e.x;
    EXPECT_EQ(hit->surface->texture, e.texture) << e.x;
    EXPECT_EQ(hit->surface->interior.ior, e.ior) << e.x;
  }
}

TEST(SplitUnion, NoShadowReachesEveryMember) {
  scene::Scene scene = union_scene(make_members(500, 11), true, true);
  scene.objects.pop_back();  // the floor, which casts shadows
  const World world(scene);
  std::mt19937_64 rng(12);
  TraceStats stats;
  int seen = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = testing::random_ray(rng, {1, 2, 3}, 30.0, 8.0);
    if (auto hit = world.first_hit(ray, 1e-6, 25.0, stats)) {
      ++seen;
      EXPECT_TRUE(hit->surface->no_shadow);
    }
    std::vector<Crossing> shadow;
    world.shadow_crossings(ray, 1e-6, 25.0, shadow, stats);
    EXPECT_TRUE(shadow.empty()) << i;
  }
  EXPECT_GT(seen, 50);
}

TEST(SplitUnion, UnionsThatMustStayWholeDo) {
  // inverse and clipped_by ask the union's inside as a whole: it is not split.
  auto a = make_object(scene::Sphere{{-1, 0, 0}, 1.0}), b = make_object(scene::Sphere{{1, 0, 0}, 1.0});
  auto inverted = make_object(scene::Csg{CsgOperation::union_, {a, b}});
  inverted->inverse = true;
  auto clipped = make_object(scene::Csg{CsgOperation::union_, {a, b}});
  clipped->clipped_by.push_back(make_object(scene::Plane{{0, 1, 0}, 0.0}));
  auto bounded = make_object(scene::Csg{CsgOperation::union_, {a, b}});
  bounded->bounded_by = make_object(scene::Sphere{{0, 0, 0}, 3.0});
  for (const auto& object : {inverted, clipped, bounded}) {
    scene::Scene scene;
    scene.objects.push_back(object);
    EXPECT_EQ(World(scene).object_count(), 1u);
  }
  scene::Scene scene;
  scene.objects.push_back(make_object(scene::Csg{CsgOperation::union_, {a, b}}));
  scene.objects.push_back(make_object(scene::Csg{CsgOperation::merge, {a, b}}));
  const World world(scene);
  EXPECT_EQ(world.object_count(), 3u);  // the union's two members and the merge
  // The clipped union keeps only y < 0.
  scene::Scene clip_scene;
  clip_scene.objects.push_back(clipped);
  const World clip_world(clip_scene);
  TraceStats stats;
  EXPECT_FALSE(clip_world.first_hit(Ray{{-1, 0.5, 5}, {0, 0, -1}}, 0.0, INFINITY, stats));
  EXPECT_TRUE(clip_world.first_hit(Ray{{-1, -0.5, 5}, {0, 0, -1}}, 0.0, INFINITY, stats));
}

}  // namespace
}  // namespace convray::geometry
