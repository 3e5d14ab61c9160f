#include "render/shadows.hpp"

#include <algorithm>

#include "render/pigment.hpp"

namespace convray::render {

namespace {

// A ray through more transparent surfaces than this is taken as blocked: far beyond any
// sensible scene, it only guards against a surface found again and again.
constexpr int kMaxShadowLayers = 256;

}  // namespace

Vec3 surface_transmittance(const geometry::SurfaceInfo& surface, const Vec3& point) {
  if (!surface.texture) return Vec3(0.0);
  // Light passes a layered texture through every layer.
  Vec3 passed(1.0);
  for (const scene::Texture* layer = &texture_at(*surface.texture, point); layer != nullptr;
       layer = layer->below ? &texture_at(*layer->below, point) : nullptr) {
    const scene::Color color = evaluate_pigment(layer->pigment, point);
    if (color.opaque()) return Vec3(0.0);
    passed *= color.filter * color.rgb + Vec3(color.transmit);
  }
  return passed;
}

Vec3 shadow_transmittance(const geometry::World& world, const geometry::Ray& ray, double tmin,
                          double tmax, double step, RenderStats& stats) {
  ++stats.shadow_rays;
  Vec3 passed(1.0);
  for (int layer = 0; layer < kMaxShadowLayers && tmin < tmax; ++layer) {
    const std::optional<geometry::Crossing> crossing =
        world.first_hit(ray, tmin, tmax, stats.trace);
    if (!crossing) return passed;
    tmin = crossing->t + step;
    const geometry::SurfaceInfo* surface = crossing->surface;
    if (surface && surface->no_shadow) continue;
    if (!surface) return Vec3(0.0);
    passed *= surface_transmittance(*surface, ray.at(crossing->t));
    if (std::max({passed.r, passed.g, passed.b}) <= 0.0) return Vec3(0.0);
  }
  return tmin < tmax ? Vec3(0.0) : passed;
}

}  // namespace convray::render
