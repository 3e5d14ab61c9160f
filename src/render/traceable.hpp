#pragma once
// What the renderer needs of a thing it draws: its bounds, the first surface crossing along a
// ray, and whether any crossing blocks a shadow ray. Convolution surfaces (fast or reference
// tracer) and the analytic shapes of the tests implement it.
#include <optional>

#include "implicit/ray.hpp"
#include "implicit/trace_stats.hpp"
#include "util/math.hpp"

namespace convray::render {

using implicit::Ray;
using implicit::SurfaceHit;
using implicit::TraceStats;

class Traceable {
 public:
  virtual ~Traceable() = default;
  virtual Box3 bounds() const = 0;
  virtual std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                              TraceStats& stats) const = 0;
  virtual bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const = 0;
};

}  // namespace convray::render
