#include "render/shadows.hpp"

#include <algorithm>

#include "render/pigment.hpp"
#include "render/texture_map.hpp"

namespace convray::render {

namespace {

// A ray through more transparent surfaces than this is taken as blocked: far beyond any
// sensible scene, it only guards against a surface found again and again.
constexpr int kMaxShadowLayers = 256;

}  // namespace

namespace {

// Light passes a layered texture through every layer; the textures a texture pattern picks
// pass it by their weights.
Vec3 texture_transmittance(const scene::Texture& texture, const Vec3& point) {
  Vec3 passed(0.0);
  for_each_texture(texture, point, 1.0, [&](const scene::Texture& layer, double weight) {
    const scene::Color color = evaluate_pigment(layer.pigment, point);
    if (color.opaque()) return;
    Vec3 through = color.filter * color.rgb + Vec3(color.transmit);
    if (layer.below) through *= texture_transmittance(*layer.below, point);
    passed += weight * through;
  });
  return passed;
}

}  // namespace

Vec3 surface_transmittance(const geometry::SurfaceInfo& surface, const Vec3& point) {
  if (!surface.texture) return Vec3(0.0);
  return texture_transmittance(*surface.texture, point);
}

Vec3 shadow_transmittance(const geometry::World& world, const Ray& ray, double tmin,
                          double tmax, double step, RenderStats& stats) {
  ++stats.shadow_rays;
  // Any crossing of an object that blocks light outright (opaque everywhere) ends the ray
  // dark, wherever it lies: one any-hit query settles all of them, with no root refined.
  // Only the objects that may let light through are then followed crossing by crossing.
  if (world.blocked(ray, tmin, tmax, stats.trace)) return Vec3(0.0);
  Vec3 passed(1.0);
  for (int layer = 0; layer < kMaxShadowLayers && tmin < tmax; ++layer) {
    const std::optional<geometry::Crossing> crossing = world.first_hit(
        ray, tmin, tmax, stats.trace, geometry::World::Objects::letting_light_through);
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
