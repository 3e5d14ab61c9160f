// A declared union placed many times (`object { U translate ... }`) is one shared hierarchy
// traced through each placement (scene/instance.hpp, geometry/instance.hpp). Checked against
// the copying path written out in the scene itself: the same union written inline with the
// same transforms, whose textures the parser moves member by member. Rays must meet the same
// surfaces at the same distances with the same normals, and the textures there must give the
// same colours and bumped normals, against a brute-force loop over the copies' members.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/world.hpp"
#include "items_test_support.hpp"
#include "render/normal_perturbation.hpp"
#include "render/pigment.hpp"
#include "render/texture_map.hpp"
#include "render/texture_space.hpp"
#include "scene/instance.hpp"

namespace convray::sdl {
namespace {

using testing::parse;

// Members with patterned pigments, bumps, a texture pattern, a nested union and a mesh
// of textures; `union { Members() ... }` is the union.
const char* const kMembers = R"(
#macro Members()
  sphere { <0, 0, 0>, 0.5 pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> scale 0.2 }
           normal { bumps 0.6 scale 0.1 } }
  box { <0.6, -0.3, -0.3>, <1.2, 0.3, 0.3>
        texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } }
                  normal { ripples 0.4 scale 0.2 } finish { phong 0.5 } } rotate y * 20 }
  cylinder { <-1.2, 0, 0>, <-0.6, 0.5, 0>, 0.2 }
  sphere { <0, 1, 0>, 0.35
           texture { checker texture { pigment { rgb 1 } }
                             texture { pigment { rgb <1, 0, 0> } normal { dents 0.5 } }
                     scale 0.1 } }
  union { sphere { <0, -1, 0>, 0.3 } torus { 0.5, 0.1 } pigment { wood scale 0.3 }
          translate x * 0.2 }
  sphere { <0, 0, 1>, 0.3 pigment { rgb <0.2, 0.8, 0.3> } }
#end
)";

// Placement i: a non-uniform scale, a turn and a move, so that bumps are carried through a
// stretch as well as a rotation.
const char* const kPlacement = R"(
#macro Placement(i)
  scale <1, 1.4, 0.8> rotate <i * 20, i * 37, 0> translate <mod(i, 5) * 4, div(i, 5) * 4, 0>
#end
)";

std::string instance_scene(int n) {
  return std::string(kMembers) + kPlacement +
         "#declare U = union { Members() rotate z * 15 }\n"
         "#declare i = 0; #while (i < " + std::to_string(n) + ")\n"
         "  object { U Placement(i) }\n"
         "#declare i = i + 1; #end\n"
         // A placement inside a patterned union, and one that gives its own texture: both the
         // copy (the members inherit or wear a texture in the world's space).
         "union { object { U translate <-5, 0, 0> } pigment { checker scale 0.3 } }\n"
         "object { U translate <-5, 4, 0> pigment { onion scale 0.2 } }\n";
}

std::string copy_scene(int n) {
  return std::string(kMembers) + kPlacement +
         "#declare i = 0; #while (i < " + std::to_string(n) + ")\n"
         "  union { Members() rotate z * 15 Placement(i) }\n"
         "#declare i = i + 1; #end\n"
         "union { union { Members() rotate z * 15 translate <-5, 0, 0> }"
         " pigment { checker scale 0.3 } }\n"
         "union { Members() rotate z * 15 translate <-5, 4, 0> pigment { onion scale 0.2 } }\n";
}

// What a texture shows at a hit, as the renderer asks it: the pigments of the textures its
// patterns pick, weighted, and their bumped normals.
struct Look {
  Vec3 color{0.0};
  Vec3 normal{0.0};
};

Look look_at(const geometry::Crossing& crossing, const Vec3& world_point) {
  Look look;
  const Vec3 at = render::texture_point(crossing, world_point);
  render::for_each_texture(*crossing.surface->texture, at, 1.0,
                           [&](const scene::Texture& plain, double weight) {
                             look.color += weight * render::evaluate_pigment(plain.pigment, at).rgb;
                             look.normal += weight * render::perturb_normal(
                                                         plain.normal, crossing.texture_space,
                                                         world_point, crossing.normal);
                           });
  return look;
}

Ray ray_towards(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), target_x(-7.0, 18.0), target_y(-2.0, 7.0);
  const Vec3 origin(u(rng) * 30.0, u(rng) * 30.0, -30.0 + 10.0 * u(rng));
  const Vec3 target(target_x(rng), target_y(rng), u(rng) * 1.5);
  return Ray{origin, glm::normalize(target - origin)};
}

TEST(Instances, PlacementsLookAsTheirCopies) {
  const int n = 10;
  const ParseResult instanced = parse(instance_scene(n));
  const ParseResult copied = parse(copy_scene(n));
  ASSERT_EQ(instanced.scene.objects.size(), size_t(n) + 2);
  for (int i = 0; i < n; ++i) EXPECT_TRUE(instanced.scene.objects[i]->instance) << i;
  EXPECT_FALSE(instanced.scene.objects[n + 1]->instance);  // it gave a pigment: the copy

  const geometry::World shared(instanced.scene), copies(copied.scene);
  EXPECT_EQ(shared.shared_union_count(), 1u);
  EXPECT_EQ(shared.object_count(), size_t(n) + 2 * 7);  // the two copies: 7 members each
  EXPECT_EQ(copies.object_count(), size_t(n + 2) * 7);

  std::mt19937_64 rng(24);
  TraceStats stats;
  int hits = 0, bumped = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ray ray = ray_towards(rng);
    const auto a = shared.first_hit(ray, 1e-6, INFINITY, stats);
    const auto b = copies.first_hit_brute_force(ray, 1e-6, INFINITY, stats);
    ASSERT_EQ(a.has_value(), b.has_value()) << i;
    if (!a) continue;
    ++hits;
    ASSERT_NEAR(a->t, b->t, 1e-9 * b->t) << i;
    EXPECT_GT(glm::dot(a->normal, b->normal), 1.0 - 1e-12) << i;
    const Look seen = look_at(*a, ray.at(a->t)), expected = look_at(*b, ray.at(b->t));
    EXPECT_NEAR(glm::length(seen.color - expected.color), 0.0, 1e-6) << i;
    EXPECT_NEAR(glm::length(seen.normal - expected.normal), 0.0, 1e-6) << i;
    bumped += glm::length(expected.normal - b->normal) > 1e-3;
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(bumped, 300);  // the bumps are seen, not only plain normals
}

TEST(Instances, InsideAsTheCopies) {
  const ParseResult instanced = parse(instance_scene(6));
  const ParseResult copied = parse(copy_scene(6));
  const geometry::World shared(instanced.scene), copies(copied.scene);
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> x(-7.0, 18.0), y(-2.0, 7.0), z(-1.5, 1.5);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(x(rng), y(rng), z(rng));
    ASSERT_EQ(shared.inside_any(p), copies.inside_any(p)) << i;
    inside += copies.inside_any(p);
  }
  EXPECT_GT(inside, 200);
}

// 1000 placements of a 1000-member union: the scene holds the members once, and so does the
// World (each placement one shape over the shared hierarchy).
TEST(Instances, ManyPlacementsHoldTheMembersOnce) {
  const ParseResult parsed = parse(R"(
#declare U = union {
  #declare k = 0;
  #while (k < 1000)
    sphere { <mod(k, 10), div(k, 100), mod(div(k, 10), 10)> * 0.5, 0.2 pigment { rgb k / 1000 } }
    #declare k = k + 1;
  #end
}
#declare i = 0;
#while (i < 1000)
  object { U rotate y * i translate <mod(i, 40) * 6, 0, div(i, 40) * 6> }
  #declare i = i + 1;
#end
)");
  ASSERT_EQ(parsed.scene.objects.size(), 1000u);
  // The placements, the declared union, its members.
  EXPECT_EQ(scene::distinct_records(parsed.scene.objects), 1000u + 1u + 1000u);
  const geometry::World world(parsed.scene);
  EXPECT_EQ(world.object_count(), 1000u);
  EXPECT_EQ(world.shared_union_count(), 1u);
  EXPECT_EQ(world.shared_member_count(), 1000u);
}

// Instances of instances compose their placements; a placement's own modifiers other than
// transforms make it the copy.
TEST(Instances, NestedPlacementsAndModifiers) {
  const std::string members = std::string(kMembers) +
                              "#declare U = union { Members() }\n"
                              "#declare V = object { U rotate x * 30 }\n";
  const ParseResult instanced = parse(members +
                                      "object { V scale <1, 2, 1> translate x * 3 }\n"
                                      "object { V translate y * 4 no_shadow }\n");
  const ParseResult copied = parse(members +
                                   "union { Members() rotate x * 30 scale <1, 2, 1> "
                                   "translate x * 3 }\n"
                                   "union { Members() rotate x * 30 translate y * 4 no_shadow }\n");
  EXPECT_TRUE(instanced.scene.objects[0]->instance);
  EXPECT_FALSE(instanced.scene.objects[1]->instance);
  EXPECT_TRUE(instanced.scene.objects[1]->no_shadow);
  const geometry::World shared(instanced.scene), copies(copied.scene);
  std::mt19937_64 rng(26);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Ray ray = ray_towards(rng);
    const auto a = shared.first_hit(ray, 1e-6, INFINITY, stats);
    const auto b = copies.first_hit_brute_force(ray, 1e-6, INFINITY, stats);
    ASSERT_EQ(a.has_value(), b.has_value()) << i;
    if (!a) continue;
    ++hits;
    ASSERT_NEAR(a->t, b->t, 1e-9 * b->t) << i;
    EXPECT_EQ(a->surface->no_shadow, b->surface->no_shadow) << i;
    const Look seen = look_at(*a, ray.at(a->t)), expected = look_at(*b, ray.at(b->t));
    EXPECT_NEAR(glm::length(seen.color - expected.color), 0.0, 1e-6) << i;
    EXPECT_NEAR(glm::length(seen.normal - expected.normal), 0.0, 1e-6) << i;
  }
  EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace convray::sdl
