#pragma once
// POV-Ray 3.7's bumps for a pattern that has no normal of its own (gradient, marble, onion,
// granite, agate, hexagon, brick, function, pigment_pattern, ...): the pattern is sampled at
// the four corners of a small regular tetrahedron around the point, and the values, each
// times its corner's direction, tilt the normal. Measured with the povray binary (a plane
// lit by three coloured parallel lights, 16-bit linear output, the normal recovered per
// pixel; threshold functions `function { x > t }` located every corner to 1e-9):
//
//   corners  p + accuracy u_k in pattern space, with the unit directions
//            u = (0, 1, 0), (2√2/3, -1/3, 0), (-√2/3, -1/3, ±√(2/3))
//   vector   v = -(1 / (10 accuracy)) Σ value(p + accuracy u_k) u_k        (accuracy 0.02)
//   normal   the viewer-facing normal carried into pattern space (transpose of the
//            pattern's placement) and made unit, n_p + amount v, carried back (inverse
//            transpose) and made unit.
//
// A linear stretch of slope g therefore tilts by amount (2/15) g whatever the accuracy and
// the pattern's scale, and a pattern that jumps (a ramp wrapping from 1 to 0, the edges of
// hexagon and brick blocks) shows a crease as wide as the tetrahedron, as POV-Ray draws it.
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The shading normal at `world_point` for the unit, viewer-facing `normal`.
Vec3 sampled_pattern_normal(const scene::Normal& perturbation, const Vec3& world_point,
                            const Vec3& normal);

}  // namespace convray::render
