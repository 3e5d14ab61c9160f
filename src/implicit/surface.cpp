#include "implicit/surface.hpp"

#include <algorithm>
#include <cmath>

#include "implicit/cauchy_surface.hpp"
#include "implicit/convolution_surface.hpp"
#include "util/unit_vector.hpp"

namespace convray::implicit {

std::unique_ptr<const Surface> make_surface(const scene::ConvolutionObject& object, SupportCache* cache,
                                            Tracer tracer) {
  switch (object.kernel.type) {
    case field::KernelType::cauchy:
      // One tracer only (its own reference twin, cauchy_reference_roots, is for the tests).
      return std::make_unique<const CauchySurface>(object);
    case field::KernelType::quartic:
      break;
  }
  return std::make_unique<const ConvolutionSurface>(object, cache, tracer);
}

SurfaceHit make_surface_hit(const Surface& surface, const Ray& ray, double t) {
  return surface_hit_from_gradient(ray, t, surface.field(ray.at(t)).gradient);
}

SurfaceHit surface_hit_from_gradient(const Ray& ray, double t, const Vec3& g) {
  SurfaceHit hit;
  hit.t = t;
  hit.point = ray.at(t);
  // Inside is F >= T, so the field falls outwards; a vanishing gradient (a touching point)
  // falls back to facing the ray. Gradients of extreme strengths (1e200, 1e-160) are scaled
  // before they are normalised (unit_or_zero).
  const Vec3 unit = unit_or_zero(g);
  hit.normal = unit == Vec3(0.0) ? -ray.direction : -unit;
  return hit;
}

}  // namespace convray::implicit
