#include "render/integrator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "render/area_light.hpp"
#include "render/atmosphere.hpp"
#include "render/finish.hpp"
#include "render/interior_fade.hpp"
#include "render/layer_blend.hpp"
#include "render/lights.hpp"
#include "render/normal_perturbation.hpp"
#include "render/pigment.hpp"
#include "render/sample_hash.hpp"
#include "render/shadows.hpp"
#include "render/variable_reflection.hpp"
#include "render/texture_map.hpp"
#include "render/texture_space.hpp"

namespace convray::render {

using geometry::Crossing;
using geometry::SurfaceInfo;

namespace {

double max_channel(const Vec3& v) { return std::max({v.r, v.g, v.b}); }

// Shades surfaces that came without any (never after World's build; kept for safety).
const scene::Texture& fallback_texture() {
  static const scene::Texture texture = scene::default_texture();
  return texture;
}

Vec3 mirrored(const Vec3& direction, const Vec3& normal) {
  return direction - 2.0 * glm::dot(direction, normal) * normal;
}

// The mirror direction on a bumped surface as POV-Ray 3.7 draws it (measured on the binary: a
// mirror sphere with quilted bumps over a checker is identical, without either rule it is
// 19 dB off): where the bumped normal faces away from the incoming ray, the surface's own
// normal mirrors it; a mirrored ray that would go into the surface is mirrored again about
// the surface's own plane. `raw`: the unbumped normal, facing the viewer.
Vec3 bumped_reflection(const Vec3& direction, const Vec3& bumped, const Vec3& raw) {
  Vec3 out = mirrored(direction, glm::dot(direction, bumped) > 0.0 ? raw : bumped);
  const double into = glm::dot(out, raw);
  if (into < 0.0) out -= 2.0 * into * raw;
  return out;
}

// Snell's law for a unit direction through a unit normal facing against it, with
// eta = n_from / n_to; false on total internal reflection.
bool refracted(const Vec3& direction, const Vec3& normal, double eta, Vec3& out) {
  const double cos_in = -glm::dot(direction, normal);
  const double k = 1.0 - eta * eta * (1.0 - cos_in * cos_in);
  if (k < 0.0) return false;
  out = glm::normalize(eta * direction + (eta * cos_in - std::sqrt(k)) * normal);
  return true;
}

// A reproducible seed for the jittered sample points of an area light seen from `point`.
uint64_t area_jitter_seed(uint64_t seed, size_t light, const Vec3& point) {
  return hash_values(std::bit_cast<uint64_t>(point.x), std::bit_cast<uint64_t>(point.y),
                     std::bit_cast<uint64_t>(point.z), hash_values(seed, light));
}

}  // namespace

struct Integrator::HitPoint {
  Vec3 point;
  // Where the textures are evaluated: `point`, or for a placement of a shared union (whose
  // members' textures are in the union's space, geometry/instance.hpp) `point` carried back
  // through the placement, `texture_space`.
  Vec3 texture_point;
  const scene::Transform* texture_space = nullptr;
  Vec3 view;             // the incoming ray's direction
  Vec3 normal;           // shading normal, unit, facing the viewer
  Vec3 raw_normal;       // the surface's own normal (before bumps), unit, facing the viewer
  bool entering = true;  // the ray crosses into the solid (it met the outside of the surface)
  const SurfaceInfo* surface = nullptr;
  const scene::Finish* finish = nullptr;
  scene::Color pigment;
};

Integrator::Integrator(const scene::Scene& scene, const geometry::World& world,
                       const IntegratorSettings& settings)
    : scene_(scene),
      world_(world),
      settings_(settings),
      camera_location_in_solid_(in_solid_seen_by_fog(scene.camera.location)) {}

// POV-Ray 3.7 draws no fog along rays inside a solid that is not hollow (a camera under a
// plain `plane { y, 100 }` sees no fog; measured with povray): where the camera is, then the
// solids the rays enter. Without fog it does not matter, and is not asked.
bool Integrator::in_solid_seen_by_fog(const Vec3& origin) const {
  return !scene_.fogs.empty() && world_.has_solids() && world_.inside_solid(origin);
}

Vec3 Integrator::trace_camera_ray(const Ray& ray, RenderStats& stats) const {
  ++stats.camera_rays;
  // A camera with no ray there (outside a fisheye's circle): black, as in POV-Ray.
  if (ray.direction == Vec3(0.0)) return Vec3(0.0);
  RayState state;
  state.camera_in_solid = ray.origin == scene_.camera.location ? camera_location_in_solid_
                                                               : in_solid_seen_by_fog(ray.origin);
  state.in_solid = state.camera_in_solid;
  return trace(ray, state, 0.0, stats);
}

Vec3 Integrator::trace(const Ray& ray, const RayState& state, double tmin,
                       RenderStats& stats) const {
  ++stats.queries;
  const std::optional<Crossing> crossing = world_.first_hit(
      ray, tmin, kInfinity, stats.trace, geometry::World::Objects::all, state.viewer);
  if (!crossing) return fogged(ray, state, kInfinity, sky_color(scene_, ray.direction));
  if (state.level == 1) ++stats.hits;
  // A ray leaving a solid whose interior fades brings back light dimmed by the distance it
  // went inside (from where it started: the surface where it entered).
  const SurfaceInfo* left = crossing->surface;
  const Vec3 fade = left && fades(left->interior) && glm::dot(ray.direction, crossing->normal) > 0.0
                        ? interior_fade(left->interior, crossing->t)
                        : Vec3(1.0);
  const Vec3 color = fade * shade(ray, *crossing, state, stats);
  return fogged(ray, state, crossing->t, color);
}

Vec3 Integrator::fogged(const Ray& ray, const RayState& state, double depth,
                        const Vec3& color) const {
  if (scene_.fogs.empty() || state.in_solid) return color;
  return apply_fogs(scene_.fogs, ray, depth, color);
}

Vec3 Integrator::shade(const Ray& ray, const Crossing& crossing, const RayState& state,
                       RenderStats& stats) const {
  HitPoint hit;
  hit.point = ray.at(crossing.t);
  hit.view = ray.direction;
  hit.surface = crossing.surface;
  hit.texture_space = crossing.texture_space;
  hit.texture_point = texture_point(crossing, hit.point);
  hit.entering = glm::dot(ray.direction, crossing.normal) < 0.0;
  // Seen from within the solid, a surface wears its interior_texture when it has one.
  const SurfaceInfo* surface = crossing.surface;
  // A plain pointer: the conditional with nullptr made a temporary copy of the shared_ptr,
  // whose count both render threads then raised and lowered for every shaded point (the
  // same texture's count, one cache line between two cores: an eighth of the floor's time).
  const scene::Texture* worn =
      surface && !hit.entering && surface->interior_texture ? surface->interior_texture.get()
      : surface                                              ? surface->texture.get()
                                                             : nullptr;
  const scene::Texture& texture = worn ? *worn : fallback_texture();
  return shade_texture(texture, crossing.normal, hit, state, stats);
}

Vec3 Integrator::shade_texture(const scene::Texture& texture, const Vec3& outward,
                               const HitPoint& hit, const RayState& state,
                               RenderStats& stats) const {
  Vec3 color(0.0);
  const Vec3& at = hit.texture_point;
  for_each_texture(texture, at, 1.0, [&](const scene::Texture& plain, double weight) {
    HitPoint own = hit;
    color += weight * shade_layer(plain, outward, own, state, stats);
  });
  return color;
}

Vec3 Integrator::shade_layer(const scene::Texture& texture, const Vec3& outward, HitPoint& hit,
                             const RayState& state, RenderStats& stats) const {
  hit.finish = &texture.finish;
  hit.pigment = evaluate_pigment(texture.pigment, hit.texture_point);
  // The normal turns to face the viewer (the inside of a solid seen from within is lit like an
  // outside), then bumps tilt it: POV-Ray 3.7 bumps the side that is seen, so the inside of a
  // bumped surface is not the outside's bumps turned over (measured: interior_texture.pov).
  hit.raw_normal = hit.entering ? outward : -outward;
  hit.normal = perturb_normal(texture.normal, hit.texture_space, hit.point, hit.raw_normal);

  const scene::Color pigment = hit.pigment;
  const LayerBlend blend =
      layer_blend(pigment, texture.below ? Layer::over_layer : Layer::over_scene,
                  scene_.settings.language_version);
  Vec3 color = direct_light(hit, blend.own, stats);
  const Vec3 reflection = reflection_here(hit, state);
  if (reflection != Vec3(0.0)) color += reflected_light(hit, reflection, state, stats);
  if (!pigment.opaque()) {
    Vec3 factor = blend.through;
    if (texture.finish.conserve_energy) factor *= Vec3(1.0) - reflection;
    if (texture.below) {
      color += factor * shade_texture(*texture.below, outward, hit, state, stats);
    } else {
      color += factor * transmitted_light(hit, factor, state, stats);
    }
  }
  return color;
}

Vec3 Integrator::direct_light(const HitPoint& hit, double opacity, RenderStats& stats) const {
  const scene::Finish& finish = *hit.finish;
  Vec3 diffuse = ambient_term(finish, scene_.settings.ambient_light, hit.pigment.rgb);
  Vec3 highlights(0.0);
  const bool double_illuminated = hit.surface && hit.surface->double_illuminate;
  for (size_t index = 0; index < scene_.lights.size(); ++index) {
    const std::optional<LightArrival> arrival = light_arrival(scene_.lights[index], hit.point);
    if (!arrival) continue;
    // A light behind the surface adds nothing (no shadow ray needed), unless the surface is
    // double_illuminate: then it lights the far side as if that side faced the viewer.
    Vec3 normal = hit.normal;
    if (!(glm::dot(normal, arrival->to_light) > 0.0)) {
      if (!double_illuminated || !(glm::dot(normal, arrival->to_light) < 0.0)) continue;
      normal = -normal;
    }
    const Vec3 visible =
        light_visibility(index, hit.point, arrival->to_light, arrival->distance, stats);
    if (visible == Vec3(0.0)) continue;
    const LightContribution lit = light_contribution(finish, hit.pigment.rgb, normal, hit.view,
                                                     arrival->to_light, arrival->color * visible);
    diffuse += lit.diffuse;
    // POV-Ray 3.7: a shadowless light (a fill light) makes no phong or specular highlight.
    if (!scene_.lights[index].shadowless) highlights += lit.highlight;
  }
  return opacity * diffuse + highlights;
}

Vec3 Integrator::light_visibility(size_t index, const Vec3& point, const Vec3& to_light,
                                  double distance, RenderStats& stats) const {
  const scene::Light& light = scene_.lights[index];
  if (light.shadowless) return Vec3(1.0);
  const double offset = settings_.ray_offset;
  if (!light.area || light.kind == scene::Light::Kind::parallel) {
    return shadow_transmittance(world_, Ray{point, to_light}, offset, distance - offset, offset,
                                stats);
  }
  // An area light: POV-Ray's adaptive average over its grid of lights (area_light.hpp).
  const scene::AreaLight& area = *light.area;
  const std::vector<Vec3> lights =
      area_light_points(light, point, area_jitter_seed(settings_.seed, index, point));
  const int size1 = std::max(area.size1, 1), size2 = std::max(area.size2, 1);
  return area_light_visibility(size1, size2, area.adaptive, [&](int i, int j) {
    const Vec3 toward = lights[size_t(j) * size_t(size1) + size_t(i)] - point;
    const double length = glm::length(toward);
    if (!(length > offset)) return Vec3(1.0);
    return shadow_transmittance(world_, Ray{point, toward / length}, offset, length - offset,
                                offset, stats);
  });
}

bool Integrator::may_trace(const RayState& state, double factor, double& child_weight) const {
  if (state.level >= scene_.settings.max_trace_level) return false;
  // A negative factor (`transmit -1`: POV-Ray subtracts what is behind) weighs by its size.
  child_weight = state.weight * std::abs(factor);
  return child_weight >= scene_.settings.adc_bailout && child_weight > 0.0;
}

Vec3 Integrator::reflection_here(const HitPoint& hit, const RayState& state) const {
  const scene::Finish& finish = *hit.finish;
  if (!finish.variable_reflection && finish.reflection_metallic <= 0.0) return finish.reflection;
  const double cos_incidence = -glm::dot(hit.view, hit.normal);
  double ior_from = 1.0, ior_to = 1.0;
  if (finish.fresnel) {
    // Fresnel's law between the medium the ray is in and the one beyond the surface.
    ior_from = state.medium.ior();
    ior_to = hit.entering ? (hit.surface ? hit.surface->interior.ior : 1.0)
                          : state.medium.left(hit.surface).ior();
  }
  const Vec3 reflection = reflection_at(finish, cos_incidence, ior_from, ior_to);
  return metallic_reflection(finish, reflection, hit.pigment.rgb, cos_incidence);
}

Vec3 Integrator::reflected_light(const HitPoint& hit, const Vec3& reflection,
                                 const RayState& state, RenderStats& stats) const {
  double weight = 0.0;
  // POV-Ray weighs a reflected ray by the reflection at this angle with fresnel, by the
  // largest one without (measured under adc_bailout 0.1: `reflection { 0, 0.2 }` is traced
  // at every angle, `reflection { 0, 1 fresnel on }` only where it reaches 0.1).
  const Vec3& weighed = hit.finish->fresnel ? reflection : hit.finish->reflection;
  if (!may_trace(state, max_channel(weighed), weight)) return Vec3(0.0);
  ++stats.reflected_rays;
  RayState child = state;  // reflected: in the same medium
  child.level = state.level + 1;
  child.weight = weight;
  child.viewer = geometry::World::Viewer::reflection;
  const Ray ray{hit.point, bumped_reflection(hit.view, hit.normal, hit.raw_normal)};
  return reflection * trace(ray, child, settings_.ray_offset, stats);
}

Vec3 Integrator::transmitted_light(const HitPoint& hit, const Vec3& factor, const RayState& state,
                                   RenderStats& stats) const {
  double weight = 0.0;
  if (!may_trace(state, max_channel(factor), weight)) return Vec3(0.0);
  const double ior_from = state.medium.ior();
  const MediumStack beyond =
      hit.entering
          ? state.medium.entered(hit.surface, hit.surface ? hit.surface->interior.ior : 1.0)
          : state.medium.left(hit.surface);
  const double ior_to = beyond.ior();

  RayState child{state.level, weight, beyond, state.viewer};
  const SurfaceInfo* inside = beyond.innermost();
  child.camera_in_solid = state.camera_in_solid;
  child.in_solid = inside ? !inside->hollow : state.camera_in_solid;
  Vec3 direction = hit.view;
  if (ior_from != ior_to) {
    child.level = state.level + 1;  // a bent ray is a new level; a straight one is not
    if (!refracted(hit.view, hit.normal, ior_from / ior_to, direction)) {
      // Total internal reflection: the light stays in the medium it came from.
      direction = mirrored(hit.view, hit.normal);
      child.medium = state.medium;
      child.in_solid = state.in_solid;
      child.viewer = geometry::World::Viewer::reflection;
      ++stats.reflected_rays;
      return trace(Ray{hit.point, direction}, child, settings_.ray_offset, stats);
    }
  }
  ++stats.refracted_rays;
  return trace(Ray{hit.point, direction}, child, settings_.ray_offset, stats);
}

}  // namespace convray::render
