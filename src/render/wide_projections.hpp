#pragma once
// POV-Ray's wide camera projections, as the povray binary traces them (each formula was
// fitted to the directions POV-Ray 3.7 gives its camera rays, read back through a sky_sphere
// whose colour is the ray's direction; tests/app/povray_cameras_test.cpp compares pictures).
// With image-plane coordinates u = x0, v = y0 in [-0.5, 0.5] and the camera's final right R,
// up U and direction D (hats: unit vectors), angles in degrees:
//   fisheye    a = u |R|, b = v |U|, r = hypot(a, b), theta = r angle: along
//              sin(theta) (a R^ + b U^) / r + cos(theta) D^; no ray where r > 1/2
//   panoramic  sin(pi u) R + tan(pi v) U + cos(pi u) D
//   spherical  longitude u angle, latitude v vertical_angle, about D^ towards R^ and U^
//   cylinder 1 sin(u angle) R^ + v |U| U^ + cos(u angle) D^        (vertical, fixed eye)
//   cylinder 2 u |R| R^ + sin(v angle) U^ + cos(v angle) D^        (horizontal, fixed eye)
//   cylinder 3 as 1 without the U^ term, from location + v |U| U^  (eye along the axis)
//   cylinder 4 as 2 without the R^ term, from location + u |R| R^
//   ultra_wide_angle  with a = u angle, b = v angle |U| / |R|:
//              sin(a) R^ + sin(b) U^ + cos(a) cos(b) D^
#include <optional>

#include "core/ray.hpp"
#include "scene/scene.hpp"

namespace convray::render {

// The ray of a wide projection through (u, v); nullopt where the projection has none (the
// corners outside a fisheye's circle, which POV-Ray leaves black).
std::optional<Ray> wide_projection_ray(const scene::Camera& camera, double u, double v);

}  // namespace convray::render
