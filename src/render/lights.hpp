#pragma once
// How each kind of light reaches a point, before shadows. Checked against POV-Ray 3.7 renders
// (a white diffuse plane under the light; see tests/render/lights_test.cpp for the values):
//
//   point      the light's colour, from its position
//   spotlight  colour * cos(a)^tightness * s, a the angle between the spot axis
//              (point_at - position) and the direction to the point; s = 1 within `radius`
//              degrees, 0 beyond `falloff`, between them the smoothstep t^2 (3 - 2t) of
//              t = (cos a - cos falloff) / (cos radius - cos falloff); agreement 1e-5 for
//              radius/falloff/tightness 10/25/0, 10/25/10, 30/30/5, 20/35/1
//   parallel   the colour from direction position - point_at everywhere; its shadow rays
//              go on to infinity; no fading
//   fading     fade_distance > 0 and fade_power > 0: colour * 2 / (1 + (d / fade_distance)^
//              fade_power), d the distance to the light (agreement 1e-5)
//
// Area lights change shadows only: the diffuse and highlight directions are the centre's
// (checked: a plane under a 3 x 3 area light is lit exactly as by a point light at its
// centre), the visibility is averaged over the grid of lights (area_light_points,
// area_light.hpp).
#include <optional>
#include <vector>

#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::render {

struct LightArrival {
  Vec3 to_light{0.0, 1.0, 0.0};  // unit, from the point towards the light
  double distance = 0.0;         // to the light's centre; infinite for parallel lights
  Vec3 color{0.0};               // the light's colour after cone and fading
};

// How `light` reaches `point`; nullopt where it does not at all (outside a spotlight's cone,
// a black light, the point at the light itself).
std::optional<LightArrival> light_arrival(const scene::Light& light, const Vec3& point);

// The spotlight factor for the unit direction from the light to the point.
double spotlight_factor(const scene::Light& light, const Vec3& light_to_point);

// The fading factor at distance d (1 without fading).
double fade_factor(const scene::Light& light, double distance);

// The positions of an area light's size1 x size2 lights as seen from `point`: a grid
// spanning axis1 and axis2 centred on the light's position (corners included when a size
// exceeds 1). `jitter`: each moves within its cell, by hash of `jitter_seed` and the cell,
// so the same seed gives the same points. `orient`: the axes are turned to face `point`,
// keeping their lengths. `circular`: the square grid is mapped onto the disc (ellipse)
// that the axes span.
std::vector<Vec3> area_light_points(const scene::Light& light, const Vec3& point,
                                    uint64_t jitter_seed);

}  // namespace convray::render
