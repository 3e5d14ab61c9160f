#pragma once
// Bump mapping: `normal { bumps 0.5 }` and its kin tilt the shading normal against the slope
// of the pattern's value. The tilt is the pattern's gradient g with its component along the
// normal removed:
//   n' = normalize(n - k * amount * (g - (g . n) n)),
// g pointing along the world-space gradient but as long as the gradient in pattern space, so
// that scaling a normal pattern changes the size of its bumps, not their steepness, and
// k = 2/15 as measured on POV-Ray 3.7 for patterns used as normals (gradient, onion,
// marble, ...: exact for linear stretches). bumps, dents and wrinkles are POV-Ray's own:
// normalize(n + amount W(p)), W made of its vector noise, as the binary draws them. For
// ripples and waves k = 1/2 gives about POV-Ray's steepness; their pictures are alike, not
// equal. Where a wrapped pattern jumps from 1 to 0 we take the slope
// across the jump (POV-Ray draws a thin crease there).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The shading normal at `world_point` for the unit `normal`; `normal` itself when the texture
// has no normal pattern or a zero amount.
Vec3 perturb_normal(const scene::Normal& perturbation, const Vec3& world_point, const Vec3& normal);

// The gradient of the pattern's value in pattern space at a world point, by central
// differences (steps small against a pattern cell; jumps of fract-wrapped values unwrapped).
Vec3 pattern_space_gradient(const scene::PatternSpace& space, const Vec3& world_point);

// The gradient of the pattern's value in world space.
Vec3 pattern_gradient(const scene::PatternSpace& space, const Vec3& world_point);

}  // namespace convray::render
