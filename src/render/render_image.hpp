#pragma once
// Rendering a picture: one camera ray per pixel (through its centre), Phong shading with a
// hard shadow, tiles spread over TBB's threads.
//
// Deterministic: a pixel's colour depends only on its own rays, never on which thread traced
// it or in what order, and the statistics are integer sums; so one thread and sixteen give the
// same bytes.
#include "render/camera.hpp"
#include "render/film.hpp"
#include "render/render_result.hpp"
#include "render/render_stats.hpp"
#include "render/shading.hpp"
#include "render/traceable.hpp"

namespace convray::render {

class Progress;

// Renders `scene` seen by `camera`. `progress`, if given, hears of every pixel done and is
// finished at the end. Tiles are `tile_size` pixels square: big enough to amortise the
// scheduling, small enough that the last tiles do not leave cores idle.
RenderResult render_image(const Traceable& scene, const Camera& camera, const Lighting& lighting,
                          Progress* progress = nullptr, int tile_size = 16);

// The colour of pixel (i, j) alone, exactly as render_image computes it.
Vec3 render_pixel(const Traceable& scene, const Box3& scene_bounds, const Camera& camera,
                  const Lighting& lighting, int i, int j, RenderStats& stats);

}  // namespace convray::render
