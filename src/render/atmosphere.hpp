#pragma once
// What lies between and beyond the objects: the background or sky_sphere that rays leaving
// the scene see, and fog along every ray.
//
// Fog, checked against POV-Ray 3.7 (ortho camera 10 units from a plane of colour P, fog
// distance 8, colour C with filter f, transmit t; 16-bit linear output):
//   k = max(exp(-depth / distance), t)
//   colour = k * (1 - f + f * C) * ray colour + (1 - k) * C
// (C = <0.2,0.4,0.9>, P = <0.7,0.5,0.3>: f = 0.5 gives red 0.26304, t = 0.5 gives 0.45,
// f = 0.3 t = 0.4 gives 0.3328: all matched to 1e-5). Rays that leave the scene have infinite
// depth: the fog colour (k = t) over the background.
// Ground fog (type 2): density 1 below `offset` (height h along `up`), 1 / (1 + u^2) above
// it with u = (h - offset) / altitude (measured: horizontal rays at u = 0.5, 1.5, 2.5 see
// densities 0.8, 0.3077, 0.1379), integrated exactly along the ray (atan); then the same
// blend with k = exp(-optical depth / distance). Fog turbulence is not applied.
// Several fogs: POV-Ray 3.7 does not fog one fog's colour with the next; it adds them:
//   colour = (k1 tint1)(k2 tint2)... * ray colour + (1 - k1) C1 + (1 - k2) C2 + ...
// (two constant fogs over a plane, with and without filter and transmit: agreement 1e-5).
//
// Sky sphere: each pigment is evaluated at the ray's direction (in the sky sphere's own
// space: its transform inverted); as in POV-Ray 3.7 the last pigment lies on top, earlier ones
// show through its filter and transmit, and the background through all of them (checked: a
// transparent striped pigment listed after an opaque gradient shows its stripes over it, and
// the picture matches POV-Ray's; tests/render/povray_compare_test.cpp).
#include <vector>

#include "core/ray.hpp"
#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::render {

// The colour seen along a direction that meets no object (before fog).
Vec3 sky_color(const scene::Scene& scene, const Vec3& direction);

// What one fog does over `depth` (infinite: the ray left the scene): the colour behind is
// multiplied by `through`, the fog adds `glow`.
struct FogLayer {
  Vec3 through{1.0};
  Vec3 glow{0.0};
};
FogLayer fog_layer(const scene::Fog& fog, const Ray& ray, double depth);

// `color` seen through one fog over `depth`.
Vec3 apply_fog(const scene::Fog& fog, const Ray& ray, double depth, const Vec3& color);

// Through all the scene's fogs, in order.
Vec3 apply_fogs(const std::vector<scene::Fog>& fogs, const Ray& ray, double depth,
                const Vec3& color);

// The optical depth (integral of the density) of ground fog along `ray` from 0 to `depth`.
double ground_fog_depth(const scene::Fog& fog, const Ray& ray, double depth);

}  // namespace convray::render
