// Anti-aliasing through whole renders (a pixel straddling an edge gets the mean of its
// samples, as in POV-Ray) and determinism: the same settings give the same bytes for any thread
// count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <vector>

#include "geometry/world.hpp"
#include "render/render_scene.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;

// One unit per pixel: pixel i covers x in [i - 2, i - 1]. A white box from x = -0.6 on: its
// edge lies 0.4 of the way across pixel 1, whose centre (x = -0.5) is white.
scene::Scene edge_scene() {
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 4, 4);
  scene.objects.push_back(box(Vec3(-0.6, -100, 0), Vec3(100, 100, 1), glowing(rgb(1, 1, 1))));
  return scene;
}

RenderResult render(const scene::Scene& scene, const RenderSettings& settings) {
  const geometry::World world(scene);
  return render_scene(scene, world, settings);
}

RenderSettings antialiased(int width, int height, int depth) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.antialias = true;
  settings.aa_depth = depth;
  return settings;
}

TEST(RenderAntialias, PixelAcrossAnEdgeGetsTheMeanOfItsSamples) {
  // As POV-Ray 3.7 (which gives 0.7 and 9/17 in this very scene): the mean of the white centre
  // sample and the R x R sub-samples. Depth 3: sample columns at 1/6, 1/2, 5/6 of the pixel,
  // two of three white: (1 + 6) / 10.
  const RenderResult three = render(edge_scene(), antialiased(4, 4, 3));
  // Depth 4: columns at 1/8, 3/8, 5/8, 7/8, two of four white: (1 + 8) / 17.
  const RenderResult four = render(edge_scene(), antialiased(4, 4, 4));
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(three.film.at(1, j).r, 0.7, 1e-6);
    EXPECT_NEAR(four.film.at(1, j).r, 9.0 / 17.0, 1e-6);
    EXPECT_EQ(three.film.at(0, j).r, 0.0f);  // supersampled too, but all black
    EXPECT_EQ(three.film.at(2, j).r, 1.0f);  // like its neighbours: not supersampled
    EXPECT_EQ(three.film.at(3, j).r, 1.0f);
  }
  EXPECT_EQ(three.stats.supersampled_pixels, 8u);
  EXPECT_EQ(three.stats.camera_rays, 16u + 8u * 9u);

  RenderSettings plain = antialiased(4, 4, 3);
  plain.antialias = false;
  EXPECT_EQ(render(edge_scene(), plain).film.at(1, 0).r, 1.0f);
}

// Everything that could depend on the order of work: jittered anti-aliasing, a jittered area
// light, glass and a mirror.
scene::Scene busy_scene(int width, int height) {
  scene::Scene scene;
  scene.camera = look_at_camera(Vec3(0, 2, -5), Vec3(0, 0.6, 0), 50, width, height);
  scene::Light light = point_light(Vec3(-3, 6, -4));
  scene::AreaLight area;
  area.axis1 = Vec3(1, 0, 0);
  area.axis2 = Vec3(0, 0, 1);
  area.size1 = area.size2 = 3;
  area.jitter = true;
  light.area = area;
  scene.lights.push_back(light);
  auto floor = plain_texture(rgb(0, 0, 0), 0.1, 0.7);
  floor->pigment.space.pattern = scene::Pattern::checker;
  floor->pigment.block_colors = {rgb(0.9, 0.9, 0.9), rgb(0.2, 0.3, 0.5)};
  scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, floor));
  scene.objects.push_back(sphere(Vec3(-0.9, 0.8, 0), 0.8,
                                 plain_texture(rgb(1, 1, 1, 0.2, 0.7), 0.0, 0.1),
                                 scene::Interior{1.5}));
  auto mirror = plain_texture(rgb(0.7, 0.2, 0.2), 0.1, 0.4);
  mirror->finish.reflection = Vec3(0.5);
  mirror->pigment.space.pattern = scene::Pattern::bozo;
  scene.objects.push_back(sphere(Vec3(0.9, 0.8, 0.5), 0.8, mirror));
  return scene;
}

std::vector<float> pixels_with_threads(int threads, const RenderSettings& settings) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  const RenderResult result = render(busy_scene(settings.width, settings.height), settings);
  return {result.film.rgb().begin(), result.film.rgb().end()};
}

TEST(RenderDeterminism, SameBytesForOneAndFourThreads) {
  RenderSettings settings = antialiased(48, 36, 3);
  settings.jitter = true;
  settings.seed = 1234;
  settings.tile_size = 5;  // many tiles, uneven at the edges
  const std::vector<float> one = pixels_with_threads(1, settings);
  const std::vector<float> four = pixels_with_threads(4, settings);
  EXPECT_EQ(one, four);

  settings.seed = 1235;  // and the seed matters
  EXPECT_NE(pixels_with_threads(4, settings), one);
}

}  // namespace
}  // namespace convray::render
