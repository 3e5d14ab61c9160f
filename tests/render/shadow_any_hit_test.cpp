// Shadow rays settle the objects that block light outright (opaque convolution objects) with
// one any-hit query and follow the rest crossing by crossing. Checked against the rule it
// replaces, written out here as the specification: walk the crossings of every object, nearest
// first, multiplying the light by what each surface lets through, until an opaque one.
#include <gtest/gtest.h>

#include <random>

#include "geometry/world.hpp"
#include "render/pigment.hpp"
#include "render/shadows.hpp"
#include "scene/texture_opacity.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;

// The specification: every object asked for its nearest crossing, one layer at a time.
Vec3 transmittance_crossing_by_crossing(const geometry::World& world, const Ray& ray,
                                        double tmin, double tmax, double step) {
  TraceStats stats;
  Vec3 passed(1.0);
  for (int layer = 0; layer < 256 && tmin < tmax; ++layer) {
    const auto crossing = world.first_hit(ray, tmin, tmax, stats);
    if (!crossing) return passed;
    tmin = crossing->t + step;
    if (crossing->surface->no_shadow) continue;
    passed *= surface_transmittance(*crossing->surface, ray.at(crossing->t));
    if (std::max({passed.r, passed.g, passed.b}) <= 0.0) return Vec3(0.0);
  }
  return tmin < tmax ? Vec3(0.0) : passed;
}

// A soup of random triangles around `center` as one convolution object.
scene::Implicit soup(const Vec3& center, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  scene::MeshComponent mesh;
  mesh.weight = {1.0, 0.6};
  for (int i = 0; i < 40; ++i) {
    const Vec3 a = center + Vec3(u(rng), u(rng), u(rng));
    mesh.triangles.push_back({a, a + 0.5 * Vec3(u(rng), u(rng), u(rng)),
                              a + 0.5 * Vec3(u(rng), u(rng), u(rng))});
  }
  scene::Implicit implicit;
  implicit.object.meshes.push_back(mesh);
  implicit.object.threshold = 0.05;
  return implicit;
}

scene::Implicit rod(const Vec3& a, const Vec3& b) {
  scene::Implicit implicit;
  implicit.object.segments.push_back({{a, b}, {1.0, 0.5}});
  implicit.object.threshold = 0.2;
  return implicit;
}

TEST(ShadowAnyHit, AgreesWithCrossingByCrossingThroughOpaqueTransparentAndShadowlessObjects) {
  scene::Scene scene;
  const auto opaque = plain_texture(rgb(0.8, 0.5, 0.3), 0.1, 0.8);
  const auto clear = plain_texture(rgb(0.9, 0.6, 0.3, 0.4, 0.2), 0.1, 0.8);
  scene.objects.push_back(object(soup(Vec3(0.0), 71), opaque));
  scene.objects.push_back(object(soup(Vec3(2.5, 0.5, 0.0), 72), opaque,
                                 std::nullopt, scene::Transform::rotation({30, 10, 0})));
  scene.objects.push_back(object(rod(Vec3(-3, -1, 0), Vec3(3, -1, 1)), clear));
  auto shy = std::make_shared<scene::Object>(*object(rod(Vec3(-1, 2, -2), Vec3(1, 2, 2)), opaque));
  shy->no_shadow = true;
  scene.objects.push_back(shy);
  scene.objects.push_back(sphere(Vec3(-2.0, 0.5, 0.5), 0.8, clear));
  const geometry::World world(scene);
  ASSERT_TRUE(world.shape(0).blocks_light());
  ASSERT_TRUE(world.shape(1).blocks_light());  // through its transform
  EXPECT_FALSE(world.shape(2).blocks_light());  // transparent
  EXPECT_FALSE(world.shape(3).blocks_light());  // casts no shadow
  EXPECT_FALSE(world.shape(4).blocks_light());  // only implicit surfaces answer any-hit

  std::mt19937_64 rng(73);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  int dark = 0, dimmed = 0, lit = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 from(u(rng), u(rng), u(rng)), light(u(rng), 8.0, u(rng));
    const Vec3 to_light = light - from;
    const Ray ray{from, glm::normalize(to_light)};
    const double tmax = glm::length(to_light);
    RenderStats stats;
    const Vec3 fast = shadow_transmittance(world, ray, 1e-6, tmax, 1e-6, stats);
    const Vec3 spec = transmittance_crossing_by_crossing(world, ray, 1e-6, tmax, 1e-6);
    ASSERT_EQ(fast, spec) << "ray " << i;
    if (fast == Vec3(0.0)) {
      ++dark;
    } else if (fast == Vec3(1.0)) {
      ++lit;
    } else {
      ++dimmed;
    }
  }
  // Every case is exercised.
  EXPECT_GT(dark, 50) << dimmed << " dimmed, " << lit << " lit";
  EXPECT_GT(dimmed, 50) << dark << " dark";
  EXPECT_GT(lit, 50);
}

TEST(ShadowAnyHit, BlockedMatchesItsBruteForceTwin) {
  scene::Scene scene;
  const auto opaque = plain_texture(rgb(0.8, 0.5, 0.3), 0.1, 0.8);
  for (int k = 0; k < 12; ++k) {
    scene.objects.push_back(object(soup(Vec3(3.0 * (k % 4) - 4.5, 3.0 * (k / 4) - 3.0, 0.0),
                                        uint64_t(80 + k)), opaque));
  }
  const geometry::World world(scene);
  std::mt19937_64 rng(74);
  std::uniform_real_distribution<double> u(-6.0, 6.0);
  TraceStats stats;
  int blocked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 from(u(rng), u(rng), -6.0), to(u(rng), u(rng), 6.0);
    const Ray ray{from, glm::normalize(to - from)};
    const double tmax = glm::length(to - from);
    const bool fast = world.blocked(ray, 0.0, tmax, stats);
    ASSERT_EQ(fast, world.blocked_brute_force(ray, 0.0, tmax, stats)) << i;
    blocked += fast;
  }
  EXPECT_GT(blocked, 200);
  EXPECT_LT(blocked, 1800);
}

// scene::always_opaque trusts that the renderer's default colour maps are opaque.
TEST(ShadowAnyHit, DefaultColourMapsAreOpaque) {
  for (int p = 0; p <= int(scene::Pattern::function); ++p) {
    for (const scene::ColorMapEntry& entry : default_color_map(scene::Pattern(p))) {
      EXPECT_TRUE(entry.color.opaque()) << "pattern " << p;
    }
  }
}

TEST(ShadowAnyHit, OpacityOfTextures) {
  scene::Texture plain;
  plain.pigment.color = rgb(0.5, 0.5, 0.5);
  EXPECT_TRUE(scene::always_opaque(plain));
  scene::Texture filtered = plain;
  filtered.pigment.color.filter = 0.1;
  EXPECT_FALSE(scene::always_opaque(filtered));
  scene::Texture mapped = plain;
  mapped.pigment.space.pattern = scene::Pattern::gradient;
  mapped.pigment.color_map = {{0.0, rgb(1, 1, 1)}, {1.0, rgb(0, 0, 0, 0.0, 0.5)}};
  EXPECT_FALSE(scene::always_opaque(mapped));
  mapped.pigment.color_map.back().color.transmit = 0.0;
  EXPECT_TRUE(scene::always_opaque(mapped));
  scene::Texture checker = plain;
  checker.pigment.space.pattern = scene::Pattern::checker;
  checker.pigment.block_colors = {rgb(1, 1, 1), rgb(0, 0, 0, 1.0, 0.0)};
  EXPECT_FALSE(scene::always_opaque(checker));
  // A texture map is opaque where every texture it can pick is.
  scene::Texture picked;
  auto map = std::make_shared<scene::TextureMap>();
  map->textures = {std::make_shared<const scene::Texture>(plain),
                   std::make_shared<const scene::Texture>(filtered)};
  picked.map = map;
  EXPECT_FALSE(scene::always_opaque(picked));
  map->textures.back() = std::make_shared<const scene::Texture>(plain);
  EXPECT_TRUE(scene::always_opaque(picked));
  // Image maps may carry transparency.
  scene::Texture image = plain;
  image.pigment.space.pattern = scene::Pattern::image_map;
  EXPECT_FALSE(scene::always_opaque(image));
}

}  // namespace
}  // namespace convray::render
