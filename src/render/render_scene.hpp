#pragma once
// Rendering a parsed scene: the camera's rays through every pixel, each traced by the Whitted
// integrator (integrator.hpp) against the World, optionally anti-aliased (antialias.hpp),
// tiles spread over TBB's threads.
//
// The film holds linear light. Scenes with global_settings { assumed_gamma g } other than 1
// are computed as POV-Ray 3.7 does, in g's space, and decoded (v -> v^g) at the end.
//
// Deterministic: a pixel depends only on its own rays (jitter is a hash of the seed and the
// pixel), statistics are integer sums; one thread and sixteen give the same bytes. So a
// partial render (RenderSettings::window) gives exactly the full render's pixels there.
#include <cstdint>
#include <optional>

#include "geometry/world.hpp"
#include "render/pixel_window.hpp"
#include "render/render_observer.hpp"
#include "render/render_result.hpp"
#include "scene/scene.hpp"

namespace convray {
class Progress;  // core/progress.hpp
}  // namespace convray

namespace convray::render {

struct RenderSettings {
  int width = 800, height = 600;
  bool antialias = false;     // POV-Ray's +A
  double aa_threshold = 0.3;  // +A0.3
  double aa_gamma = 2.5;      // POV-Ray's Antialias_Gamma: colours compared as c^(1/2.5)
  int aa_depth = 3;           // +R3: 3 x 3 samples in a supersampled pixel
  bool jitter = false;        // +J
  double jitter_amount = 1.0;
  uint64_t seed = 0;   // jittered samples and area lights: same seed, same picture
  int tile_size = 16;  // pixels per tile side
  // Secondary rays ignore crossings closer than this to their origin; 0: 1e-7 times the size
  // of the scene (its finite bounds' diagonal, or the camera's distance from the origin).
  double ray_offset = 0.0;
  // A partial render (POV-Ray's +SR/+ER/+SC/+EC): only these pixels are computed, every other
  // one stays black, as POV-Ray 3.7 writes them. Unset: the whole picture.
  std::optional<PixelWindow> window;
  // A quick look (`convray view`'s first picture): above 1, one camera ray per block of
  // block_size x block_size pixels (blocks from the picture's corner), through the centre of
  // the block's middle pixel (or of its last pixel in a block the picture's edge cuts short),
  // and that pixel's colour fills the block. Anti-aliasing is then not done.
  int block_size = 1;
};

// Renders `scene` whose objects `world` holds (built from the same scene). `progress`, if
// given, hears of every pixel of the first pass done (width * height units, or the window's
// pixels) and is finished at the end. `observer`, if given, is handed each finished tile (a
// preview window); what it throws (RenderCancelled) stops the render and leaves here. Throws
// std::invalid_argument for settings out of range or a degenerate camera.
RenderResult render_scene(const scene::Scene& scene, const geometry::World& world,
                          const RenderSettings& settings, Progress* progress = nullptr,
                          RenderObserver* observer = nullptr);

// The offset render_scene uses when RenderSettings::ray_offset is 0.
double automatic_ray_offset(const scene::Scene& scene, const geometry::World& world);

}  // namespace convray::render
