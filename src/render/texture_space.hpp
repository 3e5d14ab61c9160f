#pragma once
// Where a surface's textures are evaluated. Textures are in the space their surface is placed
// in, except for the members of a shared union's placement (geometry/instance.hpp): theirs are
// in the union's own space, and the crossing names the placement. Evaluated through these, a
// placement's picture is its copy's, whose textures the parser moved by the placement.
#include "geometry/shape.hpp"
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The point at which the crossing's textures are evaluated (pigments, texture patterns).
Vec3 texture_point(const geometry::Crossing& crossing, const Vec3& world_point);

// The shading normal (render/normal_perturbation.hpp) of a texture in `texture_space` (null:
// placed where the surface is), at a world point, from a unit world normal.
Vec3 perturb_normal(const scene::Normal& perturbation, const scene::Transform* texture_space,
                    const Vec3& world_point, const Vec3& normal);

}  // namespace convray::render
