#include "implicit/surface.hpp"

#include <algorithm>
#include <cmath>

#include "implicit/cauchy_surface.hpp"
#include "implicit/convolution_surface.hpp"

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
  // falls back to facing the ray. Gradients of extreme strengths (1e200, 1e-160) overflow or
  // underflow when squared: they are scaled by their largest component first.
  double length = glm::length(g);
  if (length > 1e-150 && length < 1e150) {
    hit.normal = -g / length;
    return hit;
  }
  const double largest = std::max({std::abs(g.x), std::abs(g.y), std::abs(g.z)});
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    hit.normal = -ray.direction;
    return hit;
  }
  const Vec3 scaled = g / largest;
  length = glm::length(scaled);
  hit.normal = -scaled / length;
  return hit;
}

}  // namespace convray::implicit
