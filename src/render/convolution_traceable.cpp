#include "render/convolution_traceable.hpp"

#include <vector>

#include "implicit/reference_tracer.hpp"

namespace convray::render {

Box3 ConvolutionTraceable::bounds() const { return surface_.bounds(); }

std::optional<SurfaceHit> ConvolutionTraceable::first_hit(const Ray& ray, double tmin, double tmax,
                                                          TraceStats& stats) const {
  return surface_.first_hit(ray, tmin, tmax, stats);
}

bool ConvolutionTraceable::occluded(const Ray& ray, double tmin, double tmax,
                                    TraceStats& stats) const {
  return surface_.occluded(ray, tmin, tmax, stats);
}

Box3 ReferenceTraceable::bounds() const { return surface_.bounds(); }

std::optional<SurfaceHit> ReferenceTraceable::first_hit(const Ray& ray, double tmin, double tmax,
                                                        TraceStats& stats) const {
  return implicit::reference_first_hit(surface_, ray, tmin, tmax, stats);
}

bool ReferenceTraceable::occluded(const Ray& ray, double tmin, double tmax,
                                  TraceStats& stats) const {
  std::vector<double> roots;
  implicit::reference_roots(surface_, ray, tmin, tmax, roots, stats);
  // The contract asks for [tmin, tmax]; filter anyway, so a root just outside never shadows.
  for (const double t : roots) {
    if (t >= tmin && t <= tmax) return true;
  }
  return false;
}

}  // namespace convray::render
