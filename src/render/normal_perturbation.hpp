#pragma once
// Bump mapping: `normal { bumps 0.5 }` and its kin tilt the shading normal.
//   - bumps, dents, wrinkles and quilted are POV-Ray's own normals: normalize(n + amount W(p)),
//     W made of its vector noise (or quilted's cubic), as the binary draws them;
//   - ripples and waves tilt against the pattern's slope, n' = normalize(n - k amount g_t),
//     g_t the tangential part of the gradient (as long as in pattern space), k = 1/2: about
//     POV-Ray's steepness (its own functions for them are not matched yet);
//   - every other pattern is sampled around the point as POV-Ray does
//     (render/sampled_normal.hpp).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The shading normal at `world_point` for the unit `normal`; `normal` itself when the texture
// has no normal pattern or a zero amount.
Vec3 perturb_normal(const scene::Normal& perturbation, const Vec3& world_point, const Vec3& normal);

// The gradient of the pattern's value in pattern space at a world point, by central
// differences (steps small against a pattern cell; jumps of fract-wrapped values unwrapped).
Vec3 pattern_space_gradient(const scene::PatternSpace& space, const Vec3& world_point);

}  // namespace convray::render
