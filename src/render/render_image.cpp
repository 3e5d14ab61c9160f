#include "render/render_image.hpp"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "render/progress.hpp"
#include "implicit/ray_box.hpp"

namespace convray::render {

namespace {

// Pixels [x0, x1) x [y0, y1) of the film.
struct Tile {
  int x0, y0, x1, y1;
  uint64_t pixels() const { return uint64_t(x1 - x0) * uint64_t(y1 - y0); }
};

// An offset that leaves the surface for sure yet stays far below any feature worth drawing.
double automatic_shadow_bias(const Box3& bounds) {
  return bounds.empty() ? 0.0 : 1e-9 * std::max(glm::length(bounds.extent()), 1e-300);
}

void render_tile(const Tile& tile, const Traceable& scene, const Box3& bounds, const Camera& camera,
                 const Lighting& lighting, Film& film, RenderStats& stats) {
  for (int j = tile.y0; j < tile.y1; ++j) {
    for (int i = tile.x0; i < tile.x1; ++i) {
      film.set(i, j, render_pixel(scene, bounds, camera, lighting, i, j, stats));
    }
  }
}

}  // namespace

Vec3 render_pixel(const Traceable& scene, const Box3& scene_bounds, const Camera& camera,
                  const Lighting& lighting, int i, int j, RenderStats& stats) {
  const Ray ray = camera.primary_ray(i, j);
  ++stats.camera_rays;
  double tmin = 0.0, tmax = std::numeric_limits<double>::infinity();
  if (!implicit::clip_to_box(ray, scene_bounds, tmin, tmax)) return lighting.background;
  ++stats.queries;
  const std::optional<SurfaceHit> hit = scene.first_hit(ray, tmin, tmax, stats.trace);
  if (!hit) return lighting.background;
  ++stats.hits;
  return shade(scene, scene_bounds, ray, *hit, lighting, stats);
}

RenderResult render_image(const Traceable& scene, const Camera& camera, const Lighting& lighting,
                          Progress* progress, int tile_size) {
  if (tile_size < 1) throw std::invalid_argument("render_image: tile_size must be positive");
  RenderResult result{Film(camera.width(), camera.height()), {}};
  Film& film = result.film;
  const Box3 bounds = scene.bounds();
  Lighting lit = lighting;
  if (lit.shadow_bias <= 0.0) lit.shadow_bias = automatic_shadow_bias(bounds);

  const int tiles_x = (film.width() + tile_size - 1) / tile_size;
  const int tiles_y = (film.height() + tile_size - 1) / tile_size;
  tbb::enumerable_thread_specific<RenderStats> per_thread;

  // Grain 1: a tile is already a worthwhile task; TBB splits the grid of tiles among threads.
  const tbb::blocked_range2d<int> all_tiles(0, tiles_y, 1, 0, tiles_x, 1);
  tbb::parallel_for(all_tiles, [&](const tbb::blocked_range2d<int>& range) {
    RenderStats& stats = per_thread.local();
    for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty) {
      for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
        const Tile tile{tx * tile_size, ty * tile_size,
                        std::min((tx + 1) * tile_size, film.width()),
                        std::min((ty + 1) * tile_size, film.height())};
        render_tile(tile, scene, bounds, camera, lit, film, stats);
        if (progress) progress->advance(tile.pixels());
      }
    }
  });

  for (const RenderStats& stats : per_thread) result.stats += stats;
  if (progress) progress->finish();
  return result;
}

}  // namespace convray::render
