#include "render/variable_reflection.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace convray::render
