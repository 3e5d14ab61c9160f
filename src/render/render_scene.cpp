#include "render/render_scene.hpp"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "render/antialias.hpp"
#include "render/integrator.hpp"
#include "core/coherent_rays.hpp"
#include "core/progress.hpp"
#include "render/scene_camera.hpp"

namespace convray::render {

namespace {

// Runs `work(tile, stats)` on every tile of `area` (tiles of tile_size pixels from its corner)
// over TBB's threads, with per-thread statistics summed into `total` at the end (integer sums:
// order-independent). A pixel's value does not depend on its tile beyond the last bits of a
// root (each tile is a new run of coherent rays: core/coherent_rays.hpp), so any area may be
// tiled.
template <typename Work>
void for_each_tile(const PixelWindow& area, int tile_size, RenderStats& total, Work&& work) {
  if (area.empty()) return;
  const int tiles_x = (area.x1 - area.x0 + tile_size - 1) / tile_size;
  const int tiles_y = (area.y1 - area.y0 + tile_size - 1) / tile_size;
  tbb::enumerable_thread_specific<RenderStats> per_thread;
  const tbb::blocked_range2d<int> all_tiles(0, tiles_y, 1, 0, tiles_x, 1);
  tbb::parallel_for(all_tiles, [&](const tbb::blocked_range2d<int>& range) {
    RenderStats& stats = per_thread.local();
    for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty) {
      for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
        const int x0 = area.x0 + tx * tile_size, y0 = area.y0 + ty * tile_size;
        const PixelWindow tile{x0, y0, std::min(x0 + tile_size, area.x1),
                               std::min(y0 + tile_size, area.y1)};
        begin_coherent_rays();  // hints stay within the tile (core/coherent_rays.hpp)
        work(tile, stats);
      }
    }
  });
  for (const RenderStats& stats : per_thread) total += stats;
}

// The pixels to compute: the window (the whole picture when none is given).
PixelWindow window_of(const RenderSettings& s) {
  return s.window.value_or(PixelWindow{0, 0, s.width, s.height});
}

void check_settings(const RenderSettings& s) {
  if (s.width < 1 || s.height < 1) {
    throw std::invalid_argument("render_scene: the image needs at least one pixel");
  }
  if (s.tile_size < 1) throw std::invalid_argument("render_scene: tile_size must be positive");
  if (s.block_size < 1) throw std::invalid_argument("render_scene: block_size must be positive");
  if (s.antialias && (s.aa_depth < 1 || s.aa_depth > 9)) {
    throw std::invalid_argument("render_scene: the anti-aliasing depth must be 1 to 9");
  }
  if (!(s.ray_offset >= 0.0)) {
    throw std::invalid_argument("render_scene: ray_offset must not be negative");
  }
  const PixelWindow& w = window_of(s);
  if (!w.empty() && (w.x0 < 0 || w.y0 < 0 || w.x1 > s.width || w.y1 > s.height)) {
    throw std::invalid_argument("render_scene: the window reaches outside the picture");
  }
}

// POV-Ray computes in the space of `assumed_gamma` and decodes at the end: a working value v
// is the linear value v^gamma (POV-Ray 3.7 with assumed_gamma 2.2 writes background
// <0.5,0.2,0.9> as the sRGB bytes of <0.5^2.2, ...>: 128, 48, 230; a diffuse value 0.5313
// comes out as 0.2487 = 0.5313^2.2). Scenes with assumed_gamma 1 are untouched.
//
// POV-Ray 3.7 renders scenes older than 3.7 without assumed_gamma with gamma correction off:
// a computed 0.3 is written as the byte 77, not as its sRGB encoding 149. The film holds
// linear light that the image writer encodes, so such a film is decoded here: the writer's
// encoding then gives back the computed value.
//
// One pixel at a time, for the film's end and for the tiles an observer sees on the way; the
// value is rounded to float between the two steps, as the film stores it.
Vec3 output_light(const scene::GlobalSettings& g, Vec3 c) {
  if (g.assumed_gamma != 1.0 && g.assumed_gamma > 0.0) {
    c = glm::pow(glm::max(c, Vec3(0.0)), Vec3(g.assumed_gamma));
    c = Vec3(float(c.x), float(c.y), float(c.z));
  }
  if (g.gamma_correction) return c;
  const auto decode = [](double v) {
    if (!(v > 0.0)) return 0.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  return Vec3(decode(c.x), decode(c.y), decode(c.z));
}

void finish_film(const scene::GlobalSettings& g, Film& film) {
  if (g.gamma_correction && (g.assumed_gamma == 1.0 || !(g.assumed_gamma > 0.0))) return;
  for (int j = 0; j < film.height(); ++j) {
    for (int i = 0; i < film.width(); ++i) film.set(i, j, output_light(g, film.at(i, j)));
  }
}

// Hands `observer` the pixels of `tile` inside the window, as the film will end them.
void report_tile(RenderObserver* observer, const scene::GlobalSettings& g, const Film& film,
                 const PixelWindow& tile, const PixelWindow& window, bool refinement) {
  if (!observer) return;
  const PixelWindow area = tile.intersection(window);
  if (area.empty()) return;
  std::vector<float> rgb;
  rgb.reserve(3 * area.pixels());
  for (int j = area.y0; j < area.y1; ++j) {
    for (int i = area.x0; i < area.x1; ++i) {
      const Vec3 c = output_light(g, film.at(i, j));
      rgb.insert(rgb.end(), {float(c.x), float(c.y), float(c.z)});
    }
  }
  observer->tile_done({area, rgb, refinement});
}

// The mean colour of pixel (i, j)'s supersamples and its first-pass `centre` sample.
Vec3 supersampled_pixel(const Integrator& integrator, const SceneCamera& camera, int i, int j,
                        const Vec3& centre, const AntialiasSettings& aa, RenderStats& stats) {
  const std::vector<Vec2> positions = supersample_positions(i, j, aa);
  Vec3 sum = centre;
  for (const Vec2& at : positions) {
    sum += integrator.trace_camera_ray(camera.ray_at_film(at.x, at.y), stats);
  }
  ++stats.supersampled_pixels;
  return sum / double(positions.size() + 1);
}

// The pixel whose ray colours the block of `block` pixels that holds pixel i, along an axis
// of `size` pixels: the block's middle one, or its last where the picture ends first.
int block_sample(int i, int block, int size) {
  const int first = i - i % block;
  return std::min(first + block / 2, std::min(first + block, size) - 1);
}

// A quick look at `tile`: one ray per block (traced again in each tile a block straddles,
// which gives the same colour: a pixel depends only on its own ray).
void render_blocks(const Integrator& integrator, const SceneCamera& camera,
                   const RenderSettings& settings, const PixelWindow& tile, Film& film,
                   RenderStats& stats) {
  const int b = settings.block_size;
  for (int j0 = tile.y0; j0 < tile.y1; j0 = std::min(j0 - j0 % b + b, tile.y1)) {
    const int j1 = std::min(j0 - j0 % b + b, tile.y1);
    const int sj = block_sample(j0, b, settings.height);
    for (int i0 = tile.x0; i0 < tile.x1; i0 = std::min(i0 - i0 % b + b, tile.x1)) {
      const int i1 = std::min(i0 - i0 % b + b, tile.x1);
      const int si = block_sample(i0, b, settings.width);
      const Vec3 c = integrator.trace_camera_ray(camera.primary_ray(si, sj), stats);
      for (int j = j0; j < j1; ++j) {
        for (int i = i0; i < i1; ++i) film.set(i, j, c);
      }
    }
  }
}

// The first pass: the centre of every pixel of `area`. Progress counts the window's pixels.
void render_centres(const Integrator& integrator, const SceneCamera& camera,
                    const RenderSettings& settings, const PixelWindow& area, Progress* progress,
                    RenderObserver* observer, const scene::GlobalSettings& g,
                    RenderResult& result) {
  Film& film = result.film;
  const PixelWindow window = window_of(settings);
  for_each_tile(area, settings.tile_size, result.stats,
                [&](const PixelWindow& tile, RenderStats& stats) {
                  if (settings.block_size > 1) {
                    render_blocks(integrator, camera, settings, tile, film, stats);
                  } else {
                    for (int j = tile.y0; j < tile.y1; ++j) {
                      for (int i = tile.x0; i < tile.x1; ++i) {
                        film.set(i, j,
                                 integrator.trace_camera_ray(camera.primary_ray(i, j), stats));
                      }
                    }
                  }
                  if (progress) progress->advance(tile.intersection(window).pixels());
                  report_tile(observer, g, film, tile, window, false);
                });
}

// The second pass: pixels of the window that differ from a neighbour get supersampled. The
// decisions read the first pass only (the window and the ring of neighbours around it), so
// they depend neither on the order in which tiles finish nor on the window's size.
void antialias(const Integrator& integrator, const SceneCamera& camera,
               const RenderSettings& settings, RenderObserver* observer,
               const scene::GlobalSettings& g, RenderResult& result) {
  const AntialiasSettings aa{settings.aa_threshold, settings.aa_gamma,      settings.aa_depth,
                             settings.jitter,       settings.jitter_amount, settings.seed};
  const Film& first = result.film;
  const std::vector<uint8_t> flags = pixels_to_supersample(first, aa.threshold, aa.gamma);
  Film refined = first;
  for_each_tile(window_of(settings), settings.tile_size, result.stats,
                [&](const PixelWindow& tile, RenderStats& stats) {
                  for (int j = tile.y0; j < tile.y1; ++j) {
                    for (int i = tile.x0; i < tile.x1; ++i) {
                      if (!flags[size_t(j) * size_t(settings.width) + size_t(i)]) continue;
                      const Vec3 mean =
                          supersampled_pixel(integrator, camera, i, j, first.at(i, j), aa, stats);
                      refined.set(i, j, mean);
                    }
                  }
                  report_tile(observer, g, refined, tile, tile, true);
                });
  result.film = std::move(refined);
}

// A partial render's picture: black outside the window, as POV-Ray 3.7 writes it (the ring of
// neighbours that anti-aliasing read is cleared too).
void clear_outside(const PixelWindow& window, Film& film) {
  for (int j = 0; j < film.height(); ++j) {
    for (int i = 0; i < film.width(); ++i) {
      if (!window.contains(i, j)) film.set(i, j, Vec3(0.0));
    }
  }
}

}  // namespace

double automatic_ray_offset(const scene::Scene& scene, const geometry::World& world) {
  const Box3 bounds = world.bounds();
  double size = glm::length(scene.camera.location);
  if (!bounds.empty()) {
    const double diagonal = glm::length(bounds.extent());
    if (std::isfinite(diagonal)) size = std::max(size, diagonal);
  }
  return 1e-7 * (size > 0.0 ? size : 1.0);
}

RenderResult render_scene(const scene::Scene& scene, const geometry::World& world,
                          const RenderSettings& settings, Progress* progress,
                          RenderObserver* observer) {
  check_settings(settings);
  const SceneCamera camera(scene.camera, settings.width, settings.height);
  IntegratorSettings integrator_settings;
  integrator_settings.ray_offset =
      settings.ray_offset > 0.0 ? settings.ray_offset : automatic_ray_offset(scene, world);
  integrator_settings.seed = settings.seed;
  const Integrator integrator(scene, world, integrator_settings);

  RenderResult result{Film(settings.width, settings.height), {}};
  // Anti-aliasing compares each pixel with its four neighbours, so a window's first pass also
  // covers the ring around it: its pixels then get exactly the full render's decisions.
  const PixelWindow window = window_of(settings);
  const bool antialiased = settings.antialias && settings.block_size == 1;
  const PixelWindow traced =
      antialiased ? window.grown(1, settings.width, settings.height) : window;
  render_centres(integrator, camera, settings, traced, progress, observer, scene.settings,
                 result);
  if (antialiased) antialias(integrator, camera, settings, observer, scene.settings, result);
  if (settings.window) clear_outside(window, result.film);
  finish_film(scene.settings, result.film);
  if (progress) progress->finish();
  return result;
}

}  // namespace convray::render
