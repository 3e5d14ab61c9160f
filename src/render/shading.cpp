#include "render/shading.hpp"

#include <cmath>

#include "implicit/ray_box.hpp"

namespace convray::render {

Vec3 phong(const Material& material, const PointLight& light, const Vec3& normal,
           const Vec3& to_light, const Vec3& to_viewer, double visible) {
  Vec3 color = material.color * material.ambient;
  const double n_dot_l = glm::dot(normal, to_light);
  if (visible <= 0.0 || n_dot_l <= 0.0) return color;
  const Vec3 mirrored = 2.0 * n_dot_l * normal - to_light;
  const double r_dot_v = std::max(glm::dot(mirrored, to_viewer), 0.0);
  const Vec3 lit = material.color * (material.diffuse * n_dot_l) +
                   Vec3(material.specular * std::pow(r_dot_v, material.shininess));
  return color + visible * light.color * lit;
}

Vec3 shade(const Traceable& scene, const Box3& scene_bounds, const Ray& ray, const SurfaceHit& hit,
           const Lighting& lighting, RenderStats& stats) {
  const Vec3 to_viewer = -ray.direction;
  const Vec3 normal = glm::dot(hit.normal, to_viewer) < 0.0 ? -hit.normal : hit.normal;
  Vec3 to_light = lighting.light.position - hit.point;
  const double light_distance = glm::length(to_light);
  if (!(light_distance > 0.0))
    return phong(lighting.material, lighting.light, normal, normal, to_viewer, 0.0);
  to_light /= light_distance;

  // No shadow ray where the surface faces away from the light: it is dark either way.
  double visible = glm::dot(normal, to_light) > 0.0 ? 1.0 : 0.0;
  if (visible > 0.0 && lighting.shadows) {
    ++stats.shadow_rays;
    // Leave the surface on the viewer's side of it, so the shadow ray does not find the
    // crossing it starts from.
    const Ray shadow{hit.point + lighting.shadow_bias * normal, to_light};
    double tmin = 0.0, tmax = light_distance - lighting.shadow_bias;
    if (implicit::clip_to_box(shadow, scene_bounds, tmin, tmax)) {
      ++stats.queries;
      if (scene.occluded(shadow, tmin, tmax, stats.trace)) visible = 0.0;
    }
  }
  return phong(lighting.material, lighting.light, normal, to_light, to_viewer, visible);
}

}  // namespace convray::render
