#include "render/shadows.hpp"

#include <algorithm>
#include <array>

#include "render/interior_fade.hpp"
#include "render/pigment.hpp"
#include "render/texture_map.hpp"
#include "render/texture_space.hpp"

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

// The fading solids a shadow ray is inside, with where it entered them: leaving one dims the
// light by the depth crossed (interior_fade.hpp). A ray that leaves a solid it never entered
// started inside it, at the ray's start; one that leaves by another surface record of the
// same solid (a CSG's faces) closes the innermost entry.
class FadeTracker {
 public:
  explicit FadeTracker(double start) : start_(start) {}

  // The factor for crossing `surface` at t, going in or out.
  Vec3 cross(const geometry::SurfaceInfo& surface, bool entering, double t) {
    // POV-Ray 3.7 leaves light to shadows unfaded for fade_power 0 (which halves what rays
    // see through the solid): measured with povray on slabs.
    if (!fades(surface.interior) || surface.interior.fade_power == 0.0) return Vec3(1.0);
    if (entering) {
      if (size_ < kMaxDepth) entries_[size_++] = {&surface, t};
      return Vec3(1.0);
    }
    if (size_ == 0) return interior_fade(surface.interior, t - start_);
    size_t k = size_ - 1;
    for (size_t m = size_; m-- > 0;) {
      if (entries_[m].surface == &surface) {
        k = m;
        break;
      }
    }
    const Entry entry = entries_[k];
    for (size_t m = k + 1; m < size_; ++m) entries_[m - 1] = entries_[m];
    --size_;
    return interior_fade(entry.surface->interior, t - entry.t);
  }

 private:
  static constexpr size_t kMaxDepth = 8;
  struct Entry {
    const geometry::SurfaceInfo* surface = nullptr;
    double t = 0.0;
  };
  std::array<Entry, kMaxDepth> entries_{};
  size_t size_ = 0;
  double start_;
};

}  // namespace

Vec3 surface_transmittance(const geometry::SurfaceInfo& surface, const Vec3& point,
                           bool entering) {
  // Leaving the solid, light passes the inside of the surface: its interior_texture.
  if (!entering && surface.interior_texture) {
    return texture_transmittance(*surface.interior_texture, point);
  }
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
  FadeTracker fade(0.0);
  for (int layer = 0; layer < kMaxShadowLayers && tmin < tmax; ++layer) {
    const std::optional<geometry::Crossing> crossing = world.first_hit(
        ray, tmin, tmax, stats.trace, geometry::World::Objects::letting_light_through);
    if (!crossing) return passed;
    tmin = crossing->t + step;
    const geometry::SurfaceInfo* surface = crossing->surface;
    if (surface && surface->no_shadow) continue;
    if (!surface) return Vec3(0.0);
    const bool entering = glm::dot(ray.direction, crossing->normal) < 0.0;
    passed *= surface_transmittance(*surface, texture_point(*crossing, ray.at(crossing->t)),
                                    entering) *
              fade.cross(*surface, entering, crossing->t);
    if (std::max({passed.r, passed.g, passed.b}) <= 0.0) return Vec3(0.0);
  }
  return tmin < tmax ? Vec3(0.0) : passed;
}

}  // namespace convray::render
