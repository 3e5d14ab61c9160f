#pragma once
// The exact reference tracer, the slow twin of ConvolutionSurface's fast path: it marches the
// exact field with a step that its Lipschitz bound makes safe (no crossing can hide between
// samples unless the field only touches T), then bisects each bracket to rounding level.
#include <optional>
#include <vector>

#include "implicit/convolution_surface.hpp"

namespace convray::implicit {

void reference_roots(const ConvolutionSurface& surface, const Ray& ray, double tmin, double tmax,
                     std::vector<double>& out, TraceStats& stats);
std::optional<SurfaceHit> reference_first_hit(const ConvolutionSurface& surface, const Ray& ray,
                                              double tmin, double tmax, TraceStats& stats);

}  // namespace convray::implicit
