#pragma once
// A convolution surface as something the renderer can draw, in two flavours: the fast path
// (ConvolutionSurface's own first_hit and occluded), and the slow exact reference tracer
// (`convray quick --reference`), so the two can be compared picture against picture.
// Neither owns the surface, which must outlive it.
#include "implicit/convolution_surface.hpp"
#include "render/traceable.hpp"

namespace convray::render {

class ConvolutionTraceable final : public Traceable {
 public:
  explicit ConvolutionTraceable(const implicit::ConvolutionSurface& surface) : surface_(surface) {}

  Box3 bounds() const override;
  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override;
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

 private:
  const implicit::ConvolutionSurface& surface_;
};

class ReferenceTraceable final : public Traceable {
 public:
  explicit ReferenceTraceable(const implicit::ConvolutionSurface& surface) : surface_(surface) {}

  Box3 bounds() const override;
  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override;
  // Any reference root in [tmin, tmax]: reference_roots finds them all, which costs the same
  // march as finding the first.
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

 private:
  const implicit::ConvolutionSurface& surface_;
};

}  // namespace convray::render
