#include "render/variable_reflection.hpp"

#include <algorithm>
#include <cmath>

#include "render/finish.hpp"

namespace convray::render {

double fresnel_reflectance(double cos_incidence, double n_from, double n_to) {
  const double c = std::clamp(cos_incidence, 0.0, 1.0);
  const double eta = n_from / n_to;
  const double sin2_out = eta * eta * (1.0 - c * c);
  if (sin2_out >= 1.0) return 1.0;  // total internal reflection
  const double cos_out = std::sqrt(1.0 - sin2_out);
  const double s = (n_from * c - n_to * cos_out) / (n_from * c + n_to * cos_out);
  const double p = (n_from * cos_out - n_to * c) / (n_from * cos_out + n_to * c);
  return 0.5 * (s * s + p * p);
}

Vec3 reflection_at(const scene::Finish& finish, double cos_incidence, double n_from,
                   double n_to) {
  if (!finish.variable_reflection) return finish.reflection;
  const double c = std::clamp(cos_incidence, 0.0, 1.0);
  const double x = finish.fresnel ? fresnel_reflectance(c, n_from, n_to)
                                  : std::pow(1.0 - c, finish.reflection_falloff);
  return finish.reflection_min + (finish.reflection - finish.reflection_min) * x;
}

Vec3 metallic_reflection(const scene::Finish& finish, const Vec3& reflection, const Vec3& pigment,
                         double cos_incidence) {
  if (finish.reflection_metallic <= 0.0) return reflection;
  const double f = metallic_fresnel(cos_incidence);
  return reflection * (Vec3(1.0) + finish.reflection_metallic * (1.0 - f) * (pigment - Vec3(1.0)));
}

}  // namespace convray::render
