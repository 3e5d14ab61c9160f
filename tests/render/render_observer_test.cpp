// The renderer's one hook for a preview window (render/render_observer.hpp): every pixel of
// the window reaches the observer, from whatever thread rendered it, with the values the film
// ends with (after assumed_gamma); anti-aliasing's pass sends its tiles again; an observer that
// throws stops the render.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <vector>

#include "geometry/world.hpp"
#include "render/render_scene.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;

scene::Scene ball_scene(double assumed_gamma) {
  scene::Scene scene;
  scene.camera = look_at_camera(Vec3(0, 0, -5), Vec3(0, 0, 0), 40, 4, 3);
  scene.objects.push_back(sphere(Vec3(0), 1.0, plain_texture(rgb(0.8, 0.5, 0.2), 0.1, 0.8)));
  scene.lights.push_back(point_light(Vec3(5, 5, -5)));
  scene.settings.assumed_gamma = assumed_gamma;
  return scene;
}

// Collects what it is told into a picture of its own; counts the tiles of each pass.
class Collector : public RenderObserver {
 public:
  Collector(int width, int height)
      : width_(width), rgb_(3 * size_t(width) * size_t(height), -1.0f), seen_(rgb_.size() / 3) {}

  void tile_done(const FinishedTile& tile) override {
    std::lock_guard<std::mutex> hold(lock_);
    (tile.refinement ? refinement_tiles : first_tiles)++;
    size_t k = 0;
    for (int j = tile.area.y0; j < tile.area.y1; ++j) {
      for (int i = tile.area.x0; i < tile.area.x1; ++i, k += 3) {
        const size_t at = size_t(j) * size_t(width_) + size_t(i);
        if (!tile.refinement) ++seen_[at];
        for (int c = 0; c < 3; ++c) rgb_[3 * at + c] = tile.rgb[k + c];
      }
    }
    EXPECT_EQ(k, tile.rgb.size());
  }

  int width_;
  std::vector<float> rgb_;
  std::vector<int> seen_;  // first-pass reports per pixel
  int first_tiles = 0, refinement_tiles = 0;
  std::mutex lock_;
};

RenderSettings settings(int width, int height) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.tile_size = 8;
  return s;
}

TEST(RenderObserver, SeesEveryPixelOnceWithTheFilmsFinalValues) {
  for (double gamma : {1.0, 2.2}) {
    const scene::Scene scene = ball_scene(gamma);
    const geometry::World world(scene);
    Collector seen(37, 29);
    const RenderResult result = render_scene(scene, world, settings(37, 29), nullptr, &seen);
    for (int n : seen.seen_) ASSERT_EQ(n, 1);
    EXPECT_EQ(seen.first_tiles, 5 * 4);  // 8-pixel tiles over 37 x 29
    EXPECT_EQ(seen.refinement_tiles, 0);
    const std::span<const float> film = result.film.rgb();
    ASSERT_EQ(film.size(), seen.rgb_.size());
    for (size_t k = 0; k < film.size(); ++k) ASSERT_EQ(film[k], seen.rgb_[k]) << "gamma " << gamma;
    // The same film as without an observer.
    const RenderResult plain = render_scene(scene, world, settings(37, 29));
    EXPECT_TRUE(std::equal(film.begin(), film.end(), plain.film.rgb().begin()));
  }
}

TEST(RenderObserver, AntialiasingSendsItsTilesAgainAndTheLastWordIsTheFilms) {
  const scene::Scene scene = ball_scene(1.0);
  const geometry::World world(scene);
  RenderSettings s = settings(40, 30);
  s.antialias = true;
  s.aa_threshold = 0.1;
  Collector seen(40, 30);
  const RenderResult result = render_scene(scene, world, s, nullptr, &seen);
  EXPECT_GT(seen.refinement_tiles, 0);
  const std::span<const float> film = result.film.rgb();
  for (size_t k = 0; k < film.size(); ++k) ASSERT_EQ(film[k], seen.rgb_[k]);
}

TEST(RenderObserver, APartialRenderReportsItsWindowOnly) {
  const scene::Scene scene = ball_scene(1.0);
  const geometry::World world(scene);
  RenderSettings s = settings(40, 30);
  s.antialias = true;  // its first pass also traces a ring around the window: not reported
  s.window = PixelWindow{5, 7, 31, 20};
  Collector seen(40, 30);
  render_scene(scene, world, s, nullptr, &seen);
  for (int j = 0; j < 30; ++j) {
    for (int i = 0; i < 40; ++i) {
      ASSERT_EQ(seen.seen_[size_t(j) * 40 + size_t(i)], s.window->contains(i, j) ? 1 : 0)
          << i << "," << j;
    }
  }
}

class Canceller : public RenderObserver {
 public:
  void tile_done(const FinishedTile&) override {
    if (++tiles >= 3) throw RenderCancelled("closed");
  }
  std::atomic<int> tiles{0};
};

TEST(RenderObserver, WhatItThrowsStopsTheRender) {
  const scene::Scene scene = ball_scene(1.0);
  const geometry::World world(scene);
  Canceller canceller;
  RenderSettings s = settings(400, 300);
  EXPECT_THROW(render_scene(scene, world, s, nullptr, &canceller), RenderCancelled);
  // TBB stops handing out tiles: far fewer than the 50 x 38 of the picture were done.
  EXPECT_LT(canceller.tiles.load(), 50 * 38);
}

}  // namespace
}  // namespace convray::render
