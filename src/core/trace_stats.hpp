#pragma once
// Counters of the work done while tracing, kept per thread and summed at the end, so that
// `--stats` can say where the time goes without slowing the tracer down.
#include <cstdint>

namespace convray {

struct TraceStats {
  uint64_t rays = 0;               // surface queries (camera and shadow rays)
  uint64_t primitives = 0;         // support intervals gathered (primitives crossed)
  uint64_t fits = 0;               // degree-6 fits built, or window-march steps taken
                                   // (spheres: entered)
  uint64_t subdivisions = 0;       // fits split because their error bound was too large, or
                                   // windows halved by the march's two-sided test
  uint64_t field_evaluations = 0;  // exact per-primitive field evaluations (or sphere terms)
  uint64_t roots = 0;              // roots found and polished on the exact field
  uint64_t fallbacks = 0;          // rays where the fast path handed over to exact tracing
  uint64_t shadows_settled = 0;    // shadow rays found blocked by a ball known to lie inside
                                   // the surface, without a search (implicit/inside_balls.hpp)

  TraceStats& operator+=(const TraceStats& o) {
    rays += o.rays;
    primitives += o.primitives;
    fits += o.fits;
    subdivisions += o.subdivisions;
    field_evaluations += o.field_evaluations;
    roots += o.roots;
    fallbacks += o.fallbacks;
    shadows_settled += o.shadows_settled;
    return *this;
  }
};

}  // namespace convray
