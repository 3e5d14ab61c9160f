#pragma once
// How much a surface reflects at a given angle: POV-Ray 3.7's variable reflection and its
// conserve_energy, as measured with povray (tests/app/povray_reflection_test.cpp):
//
//   reflection { MIN, MAX }              R = MIN + (MAX - MIN) (1 - cos)^falloff
//   reflection { MIN, MAX fresnel on }   R = MIN + (MAX - MIN) F(cos, n)
//   reflection { MAX fresnel on }        the same with MIN = 0
//   reflection MAX                       R = MAX at every angle
//
// `metallic m` in the block tints it by the pigment P as metallic highlights are:
// R (1 + m (1 - f(cos)) (P - 1)), f finish.hpp's metallic_fresnel (measured with povray; a
// finish's own `metallic` tints highlights only).
//
// cos is the cosine of the angle between the view ray and the normal, F the unpolarised
// Fresnel reflectance of a dielectric for n = ior beyond / ior before (1 on total internal
// reflection). With conserve_energy the filter and transmit light is multiplied by 1 - R,
// channel by channel, whether R varies or not (ambient and diffuse keep the pigment's own
// filter and transmit).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The unpolarised Fresnel reflectance for a ray meeting the surface at cos_incidence (> 0)
// from a medium of ior n_from into one of ior n_to.
double fresnel_reflectance(double cos_incidence, double n_from, double n_to);

// The reflection colour of `finish` at cos_incidence; the iors are only read with fresnel.
Vec3 reflection_at(const scene::Finish& finish, double cos_incidence, double n_from,
                   double n_to);

// `reflection` tinted by `pigment` for the finish's reflection metallic at cos_incidence.
Vec3 metallic_reflection(const scene::Finish& finish, const Vec3& reflection, const Vec3& pigment,
                         double cos_incidence);

}  // namespace convray::render
