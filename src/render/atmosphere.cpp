#include "render/atmosphere.hpp"

#include <algorithm>
#include <cmath>

#include "render/layer_blend.hpp"
#include "render/pigment.hpp"

namespace convray::render {

namespace {

// A colour seen through a layer of colour `front` (filter and transmit let `behind` through).
Vec3 through_layer(const scene::Color& front, const Vec3& behind, Layer layer,
                   double language_version) {
  const LayerBlend blend = layer_blend(front, layer, language_version);
  return blend.own * front.rgb + blend.through * behind;
}

// The integral of 1 / (1 + u^2) over s where u = u0 + g s goes from s = a to s = b (u >= 0
// there, g != 0): [atan(u) / g] from a to b; an infinite b reaches atan = pi/2.
double decaying_density_integral(double u0, double g, double a, double b) {
  const double at_a = std::atan(u0 + g * a);
  const double at_b = std::isinf(b) ? 0.5 * kPi : std::atan(u0 + g * b);
  return (at_b - at_a) / g;
}

}  // namespace

Vec3 sky_color(const scene::Scene& scene, const Vec3& direction) {
  const Vec3 background = scene.background.rgb;
  if (!scene.sky_sphere || scene.sky_sphere->pigments.empty()) return background;
  const scene::SkySphere& sky = *scene.sky_sphere;
  Vec3 on_sphere = sky.transform.inverse_vector(direction);
  const double length = glm::length(on_sphere);
  if (length > 0.0) on_sphere /= length;

  Vec3 color = background;
  for (const scene::Pigment& pigment : sky.pigments) {
    color = through_layer(evaluate_pigment(pigment, on_sphere), color, Layer::sky,
                          scene.settings.language_version);
  }
  return color;
}

double ground_fog_depth(const scene::Fog& fog, const Ray& ray, double depth) {
  const double up_length = glm::length(fog.up);
  const Vec3 up = up_length > 0.0 ? fog.up / up_length : Vec3(0.0, 1.0, 0.0);
  if (!(fog.altitude > 0.0)) return depth;  // no decay above the offset: constant density
  // u: height above the offset in altitudes, along the ray u = u0 + g s.
  const double u0 = (glm::dot(ray.origin, up) - fog.offset) / fog.altitude;
  const double g = glm::dot(ray.direction, up) / fog.altitude;
  if (g == 0.0) return depth * (u0 <= 0.0 ? 1.0 : 1.0 / (1.0 + u0 * u0));

  const double s_level = -u0 / g;  // where the ray crosses the offset height
  double below_from, below_to, above_from, above_to;
  if (g > 0.0) {  // rising: below the offset first
    below_from = 0.0;
    below_to = std::clamp(s_level, 0.0, depth);
    above_from = below_to;
    above_to = depth;
  } else {  // falling: above the offset first
    above_from = 0.0;
    above_to = std::clamp(s_level, 0.0, depth);
    below_from = above_to;
    below_to = depth;
  }
  double optical = 0.0;
  if (below_to > below_from) optical += below_to - below_from;
  if (above_to > above_from) optical += decaying_density_integral(u0, g, above_from, above_to);
  return optical;
}

FogLayer fog_layer(const scene::Fog& fog, const Ray& ray, double depth) {
  if (!(fog.distance > 0.0)) return FogLayer{};
  const double optical =
      fog.kind == scene::Fog::Kind::ground ? ground_fog_depth(fog, ray, depth) : depth;
  const double k = std::max(std::exp(-optical / fog.distance), fog.color.transmit);
  const Vec3& c = fog.color.rgb;
  const Vec3 tint = Vec3(1.0 - fog.color.filter) + fog.color.filter * c;
  return FogLayer{k * tint, (1.0 - k) * c};
}

Vec3 apply_fog(const scene::Fog& fog, const Ray& ray, double depth, const Vec3& color) {
  const FogLayer layer = fog_layer(fog, ray, depth);
  return layer.through * color + layer.glow;
}

Vec3 apply_fogs(const std::vector<scene::Fog>& fogs, const Ray& ray, double depth,
                const Vec3& color) {
  Vec3 through(1.0), glow(0.0);
  for (const scene::Fog& fog : fogs) {
    const FogLayer layer = fog_layer(fog, ray, depth);
    through *= layer.through;
    glow += layer.glow;
  }
  return through * color + glow;
}

}  // namespace convray::render
