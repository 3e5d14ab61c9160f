#pragma once
// POV-Ray's patterns: a number in [0, 1] (or a block index for checker) at every point of
// space, which a colour map turns into a pigment and a normal into bumps.
//
// Checked against POV-Ray 3.7 renders (orthographic camera on a plane, 16-bit linear output):
//   gradient  fract(p . axis / |axis|)                 (negative side too: no mirroring)
//   radial    fract(atan2(-z, x) / 2 pi): 0 along +x, 0.25 along -z, 0.5 along -x
//   onion     fract(|p|)
//   marble    triangle wave of x                         (0 at x = 0, 1 at x = 0.5)
//   wood      triangle wave of sqrt(x^2 + y^2)
//   leopard   ((sin x + sin y + sin z) / 3)^2
//   checker   floor(x) + floor(y) + floor(z) odd -> the second colour; POV-Ray adds a
//             tolerance between 1e-10 and 1e-9 before flooring (a plane at y = 0 gets the
//             colour of y = +0)
//   planar    max(0, 1 - |y|); spherical max(0, 1 - |p|); cylindrical max(0, 1 - |(x, z)|);
//   boxed     max(0, 1 - max(|x|, |y|, |z|))
//   spiral1 N r + N (atan2(y, x) / 2 pi + 1/4) + z, r = |(x, y)|; triangle wave by default
//   quilted   quilted_cubic(|v|) (|v.x| + |v.y| + |v.z|) 2 / (3 sqrt 3), v = fract(p) - 1/2
//   mandel N  escape time of z -> z^2 + (x + iy) from z = x + iy, over N; 1 inside the set
//   bozo, spotted, bumps, dents, granite, wrinkles, agate, marble and wood: POV-Ray's
//             noise and formulas, matched to the binary (render/noise_patterns.hpp)
// frequency and phase: v -> wave(v * frequency + phase) with wave = fract (triangle wave for
// marble, wood and spiral1): gradient x frequency 2 phase 0.3 gives 0.4 at x = 0.05.
// Not matched yet: ripples and waves (our own wave sources) and the bumps of normal patterns
// (render/normal_perturbation.hpp): alike in character, not pixel for pixel.
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The pattern's value at a world point (its space's transform inverted, turbulence applied,
// frequency and phase applied): in [0, 1]. For checker, 0 or 1 (the block index).
double pattern_value(const scene::PatternSpace& space, const Vec3& world_point);

// The same at a point already in pattern space.
double pattern_value_in_space(const scene::PatternSpace& space, const Vec3& pattern_point);

// The point moved by the pattern's plain `turbulence` modifier, as a warp innermost (marble
// and wood, whose turbulence is their own, stay where they are).
Vec3 turbulent_point(const scene::PatternSpace& space, const Vec3& pattern_point);

// The value at a point `turbulent_point` has already moved (frequency, phase and wave applied).
double pattern_value_after_turbulence(const scene::PatternSpace& space, const Vec3& q);

// The raw function of the pattern at a pattern-space point: no turbulence, frequency or phase.
double raw_pattern_value(const scene::PatternSpace& space, const Vec3& pattern_point);

// quilted's cubic Bezier t^3 + 3 t (1 - t)^2 control0 + 3 t^2 (1 - t) control1: its value
// and its normal are made of it (render/normal_perturbation.cpp).
double quilted_cubic(double t, double control0, double control1);

// The triangle wave of period 1: 0 at integers, 1 at half-integers, linear between.
double triangle_wave(double v);

// v = value * frequency + phase reshaped by the space's wave type (POV-Ray's ramp_wave,
// triangle_wave, sine_wave, scallop_wave, cubic_wave, poly_wave E): in [0, 1].
double shaped_by_wave(const scene::PatternSpace& space, double v);

// POV-Ray's checker block index (0 or 1) at a pattern-space point.
int checker_block(const Vec3& pattern_point);

}  // namespace convray::render
