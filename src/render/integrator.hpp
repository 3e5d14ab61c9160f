#pragma once
// The Whitted integrator: the colour seen along a ray, with POV-Ray 3.7's lighting model
// (finish.hpp), its lights (lights.hpp) and shadows (shadows.hpp), mirror reflection,
// refraction and transparency, fog and the sky.
//
// At a hit, with pigment colour P (filter f, transmit t) and the normal turned to the viewer:
//   colour = (1 - f - t) (ambient + sum of diffuse) + sum of highlights
//          + reflection * trace(mirrored ray)
//          + (f P + t) [(1 - reflection) with conserve_energy] * trace(transmitted ray)
// where reflection may vary with the angle (variable_reflection.hpp).
// (measured against POV-Ray 3.7: see finish.hpp). The transmitted ray bends by Snell's law
// when the ior changes (entering a solid: its interior's ior; leaving it: the ior of the solid
// around, 1 outside everything) and reflects when totally internally reflected.
//
// Recursion, as POV-Ray 3.7 does it (measured with stacks of mirrors and transparent planes):
// a camera ray has level 1; a secondary ray is traced only while its parent's level is below
// global max_trace_level; reflected and bent rays get the next level, a transmitted ray that
// does not bend (same ior on both sides) keeps its parent's level. A ray's weight is the
// product of the largest channel of every factor along its path; rays lighter than
// adc_bailout are not traced. Untraced rays contribute black.
#include <cstdint>

#include "geometry/world.hpp"
#include "render/medium_stack.hpp"
#include "render/render_stats.hpp"
#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::render {

struct IntegratorSettings {
  // Secondary rays (shadow, reflected, transmitted) ignore crossings closer than this to
  // their origin, so they do not find the surface they leave. Scene units; > 0.
  double ray_offset = 1e-6;
  uint64_t seed = 0;  // jittered area lights: their sample points hash this with the point
};

class Integrator {
 public:
  // Keeps references: the scene and world must outlive the integrator.
  Integrator(const scene::Scene& scene, const geometry::World& world,
             const IntegratorSettings& settings);

  // The colour seen along a camera ray (unit direction).
  Vec3 trace_camera_ray(const Ray& ray, RenderStats& stats) const;

 private:
  struct RayState {
    int level = 1;
    double weight = 1.0;
    MediumStack medium;
    // Camera rays and the rays they transmit skip no_image surfaces; once a ray has been
    // reflected, it and its descendants skip no_reflection ones.
    geometry::World::Viewer viewer = geometry::World::Viewer::camera;
    // Inside a solid that is not hollow (no fog along the ray); whether the camera is.
    bool in_solid = false;
    bool camera_in_solid = false;
  };
  // What shading needs to know about the hit point.
  struct HitPoint;

  Vec3 trace(const Ray& ray, const RayState& state, double tmin,
             RenderStats& stats) const;
  Vec3 shade(const Ray& ray, const geometry::Crossing& crossing, const RayState& state,
             RenderStats& stats) const;
  // `color` seen through the scene's fogs over `depth` along the ray (none inside a solid).
  Vec3 fogged(const Ray& ray, const RayState& state, double depth, const Vec3& color) const;
  // A texture at the hit: the plain textures its texture patterns pick there (texture_map.hpp),
  // each shaded as a layer, added by weight.
  Vec3 shade_texture(const scene::Texture& texture, const Vec3& outward, const HitPoint& hit,
                     const RayState& state, RenderStats& stats) const;
  // One layer of a (possibly layered) texture at the hit: its own light, and what shows
  // through its pigment: the layer below, or the light beyond the surface.
  Vec3 shade_layer(const scene::Texture& texture, const Vec3& outward, HitPoint& hit,
                   const RayState& state, RenderStats& stats) const;
  // Ambient, diffuse and highlights of all lights; `opacity` scales ambient and diffuse.
  Vec3 direct_light(const HitPoint& hit, double opacity, RenderStats& stats) const;
  // The fraction of light `index` that reaches the point (shadows, area lights).
  Vec3 light_visibility(size_t index, const Vec3& point, const Vec3& to_light, double distance,
                        RenderStats& stats) const;
  // The finish's reflection at the hit: constant, or varying with the angle (and the iors).
  Vec3 reflection_here(const HitPoint& hit, const RayState& state) const;
  Vec3 reflected_light(const HitPoint& hit, const Vec3& reflection, const RayState& state,
                       RenderStats& stats) const;
  Vec3 transmitted_light(const HitPoint& hit, const Vec3& factor, const RayState& state,
                         RenderStats& stats) const;
  // Whether a child ray of this weight factor may be traced from `state`; its weight.
  bool may_trace(const RayState& state, double factor, double& child_weight) const;

  const scene::Scene& scene_;
  const geometry::World& world_;
  IntegratorSettings settings_;
  // Whether the camera's location lies inside a solid that is not hollow (only asked with
  // fog): where every ray of a perspective camera starts, so asked once, not per ray.
  bool camera_location_in_solid_ = false;
  bool in_solid_seen_by_fog(const Vec3& origin) const;
};

}  // namespace convray::render
