#pragma once
// A surface's field where a scene's transform places it: F_world(p) = F(M^-1 p), so
// grad F_world = M^-T grad F (the normal rule), and its support boxes placed with it. What
// `convray field` and `convray polygonize` ask of a declared object.
#include <vector>

#include "field/sample.hpp"
#include "implicit/surface.hpp"
#include "scene/transform.hpp"
#include "util/math.hpp"

namespace convray::implicit {

field::FieldSample placed_field(const Surface& surface, const scene::Transform& placed,
                                const Vec3& p);

// Each support box of `surface` (Surface::support_boxes) mapped into placed space.
std::vector<Box3> placed_support_boxes(const Surface& surface, const scene::Transform& placed);

}  // namespace convray::implicit
