#pragma once
// POV-Ray 3.7's noise-based patterns, each matched to the povray binary's values
// (`function { pattern { ... } }` printed at random points; docs/noise.md):
//   bozo, spotted, bumps  noise(p)                    dents  noise(p)^3
//   granite   sum k = 0..5 of |turbulence_noise(4 2^k p) - 1/2| / 2^k
//   wrinkles  sum k = 0..9 of turbulence_noise(2^k p) / 2^(k+1)
//   agate     (1/2 + sin(2 pi (1.1 z + 1.3 agate_turb T(p))) / 2)^0.77, T the scalar
//             turbulence of 6 octaves, omega 1/2, lambda 2
//   marble    x + turbulence.x T(p) with the pattern's octaves, omega and lambda: marble's
//             turbulence is this scalar sum, not the warp other patterns get
//   wood      |(x + sin(2 pi a.x (x + D.x)), y + sin(2 pi a.y (y + D.y)))|, a the turbulence
//             amount and D the warp's displacement (render/noise.hpp); |(x, y)| without
//   marble and wood then wrap as fmod(v, 1.00001) (+1 below zero), as the binary does
// (noise, turbulence_noise and T as in render/noise.hpp, for the pattern's noise_generator).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The value of a noise-based pattern (bozo, spotted, bumps, dents, granite, wrinkles, agate)
// at a pattern-space point.
double noise_pattern_value(const scene::PatternSpace& space, const Vec3& q);

// Marble's value before its wave: x, plus its own scalar turbulence when it has one.
double marble_value(const scene::PatternSpace& space, const Vec3& q);

// Wood's value before its wave: the distance from the z axis, turbulence its own way.
double wood_value(const scene::PatternSpace& space, const Vec3& q);

// Whether the pattern takes its `turbulence` its own way (marble, wood) rather than as a warp.
bool has_own_turbulence(scene::Pattern pattern);

}  // namespace convray::render
