#pragma once
// POV-Ray's warps (`warp { turbulence ... }`, `warp { repeat ... }`): where a world point
// lands in a pattern's space when the transforms and warps listed in the pattern are undone
// from the last listed to the first (scene::Warp).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The world point in the pattern's own space: its transforms inverted and its warps applied,
// in the order the scene lists them; the plain `turbulence` modifier is not applied here.
Vec3 pattern_point(const scene::PatternSpace& space, const Vec3& world_point);

// Every transform of the space composed, its warps left out (pattern space -> world): how a
// pattern-space direction is carried to world space for normals.
scene::Transform placement_without_warps(const scene::PatternSpace& space);

// One warp applied to a point of the space it sits in.
Vec3 apply_warp(const scene::Warp& warp, const Vec3& p);

}  // namespace convray::render
