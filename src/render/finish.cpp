#include "render/finish.hpp"

#include <algorithm>
#include <cmath>

namespace convray::render {

Vec3 ambient_term(const scene::Finish& finish, const Vec3& ambient_light, const Vec3& pigment) {
  return finish.ambient * ambient_light * pigment;
}

double diffuse_factor(const scene::Finish& finish, double n_dot_l) {
  if (!(n_dot_l > 0.0) || finish.diffuse == 0.0) return 0.0;
  const double shaped = finish.brilliance == 1.0 ? n_dot_l : std::pow(n_dot_l, finish.brilliance);
  return finish.diffuse * shaped;
}

double phong_factor(const scene::Finish& finish, const Vec3& mirrored_view, const Vec3& to_light) {
  if (finish.phong == 0.0) return 0.0;
  const double r_dot_l = glm::dot(mirrored_view, to_light);
  if (!(r_dot_l > 0.0)) return 0.0;
  return finish.phong * std::pow(r_dot_l, finish.phong_size);
}

double specular_factor(const scene::Finish& finish, const Vec3& normal, const Vec3& to_light,
                       const Vec3& to_viewer) {
  if (finish.specular == 0.0 || !(finish.roughness > 0.0)) return 0.0;
  const Vec3 half = to_light + to_viewer;
  const double length = glm::length(half);
  if (!(length > 0.0)) return 0.0;
  const double n_dot_h = glm::dot(normal, half) / length;
  if (!(n_dot_h > 0.0)) return 0.0;
  return finish.specular * std::pow(n_dot_h, 1.0 / finish.roughness);
}

double metallic_fresnel(double cos_incidence) {
  const double x = std::abs(std::acos(std::clamp(cos_incidence, -1.0, 1.0))) / (0.5 * kPi);
  const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
  return std::clamp(f, 0.0, 1.0);
}

Vec3 highlight_color(const scene::Finish& finish, const Vec3& light, const Vec3& pigment,
                     double n_dot_l) {
  if (finish.metallic <= 0.0) return light;
  const double f = metallic_fresnel(n_dot_l);
  return light * (Vec3(1.0) + finish.metallic * (1.0 - f) * (pigment - Vec3(1.0)));
}

LightContribution light_contribution(const scene::Finish& finish, const Vec3& pigment,
                                     const Vec3& normal, const Vec3& view, const Vec3& to_light,
                                     const Vec3& light) {
  LightContribution result;
  const double n_dot_l = glm::dot(normal, to_light);
  if (!(n_dot_l > 0.0)) return result;  // the light is behind the surface
  result.diffuse = diffuse_factor(finish, n_dot_l) * light * pigment;

  const Vec3 mirrored_view = view - 2.0 * glm::dot(view, normal) * normal;
  const double highlight = phong_factor(finish, mirrored_view, to_light) +
                           specular_factor(finish, normal, to_light, -view);
  if (highlight > 0.0) {
    result.highlight = highlight * highlight_color(finish, light, pigment, n_dot_l);
  }
  return result;
}

}  // namespace convray::render
