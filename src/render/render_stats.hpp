#pragma once
// What a render did, counted per thread and summed: the rays the renderer cast, and the work
// the surface did for them (TraceStats). Integers only, so the sums, like the
// pixels, do not depend on how the work was split between threads.
#include <cstdint>

#include "core/trace_stats.hpp"

namespace convray::render {

struct RenderStats {
  uint64_t camera_rays = 0;          // one per pixel, plus the anti-aliasing samples
  uint64_t shadow_rays = 0;          // towards a light that can reach the point (one per area cell)
  uint64_t queries = 0;              // rays handed to the surface (those that meet its bounds)
  uint64_t hits = 0;                 // camera rays that found the surface
  uint64_t reflected_rays = 0;       // render_scene: secondary rays off mirrors (and total
  uint64_t refracted_rays = 0;       //   internal reflection), and through transparent surfaces
  uint64_t supersampled_pixels = 0;  // render_scene: pixels anti-aliasing sampled again
  TraceStats trace;

  RenderStats& operator+=(const RenderStats& o) {
    camera_rays += o.camera_rays;
    shadow_rays += o.shadow_rays;
    queries += o.queries;
    hits += o.hits;
    reflected_rays += o.reflected_rays;
    refracted_rays += o.refracted_rays;
    supersampled_pixels += o.supersampled_pixels;
    trace += o.trace;
    return *this;
  }
};

}  // namespace convray::render
