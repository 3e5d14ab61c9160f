#pragma once
// What a render did, counted per thread and summed: the rays the renderer cast, and the work
// the surface did for them (implicit::TraceStats). Integers only, so the sums, like the
// pixels, do not depend on how the work was split between threads.
#include <cstdint>

#include "implicit/trace_stats.hpp"

namespace convray::render {

struct RenderStats {
  uint64_t camera_rays = 0;  // one per pixel
  uint64_t shadow_rays = 0;  // one per lit hit (none where the surface faces away)
  uint64_t queries = 0;      // rays handed to the surface (those that meet its bounds)
  uint64_t hits = 0;         // camera rays that found the surface
  implicit::TraceStats trace;

  RenderStats& operator+=(const RenderStats& o) {
    camera_rays += o.camera_rays;
    shadow_rays += o.shadow_rays;
    queries += o.queries;
    hits += o.hits;
    trace += o.trace;
    return *this;
  }
};

}  // namespace convray::render
