#pragma once
// POV-Ray 3.7's interior fade (`interior { fade_distance D fade_power P fade_color C }`): light
// that crosses d units inside the solid keeps the fraction
//   a + (1 - a) C,  a = 1 / (1 + (d / D)^P),  or a = exp(-d / D) when P >= 1000,
// per channel (measured with povray on slabs of several thicknesses, powers and colours, to
// the 16-bit level; fade_power 0 halves the light at any depth). D = 0: no fade. It applies to
// rays seen through the solid and to shadow rays, except that shadow rays are not faded with
// fade_power 0 (render/shadows.cpp).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

inline bool fades(const scene::Interior& interior) { return interior.fade_distance > 0.0; }

// The fraction of light kept after `distance` units inside `interior` (1 without fade).
Vec3 interior_fade(const scene::Interior& interior, double distance);

}  // namespace convray::render
