#pragma once
// Shadow rays: how much of a light's colour gets through the objects between a point and the
// light. An opaque surface stops it; a surface whose pigment has filter f and transmit t
// passes f * pigment + t of it per channel (checked against POV-Ray 3.7: an invisible
// `no_image` plane of colour <0.9,0.6,0.3> filter 0.4 transmit 0.2 between light and a white
// plane dims the light to <0.56, 0.44, 0.32>, as f * pigment + t says); every surface crossed
// counts, so a transparent solid dims twice (in and out). Shadow rays go straight: no
// refraction. Objects marked no_shadow are ignored (their crossings say so).
#include "geometry/world.hpp"
#include "render/render_stats.hpp"
#include "util/math.hpp"

namespace convray::render {

// The transmittance along `ray` over (tmin, tmax): 0 where an opaque surface blocks it.
// Objects that block light outright (geometry::Shape::blocks_light: opaque everywhere) are
// settled first by one any-hit query; the others are asked one crossing at a time, so that a
// shadow ray stops at the first opaque surface without finding the ones behind it; `step`
// (> 0) is how far past a transparent crossing the search resumes.
Vec3 shadow_transmittance(const geometry::World& world, const Ray& ray, double tmin,
                          double tmax, double step, RenderStats& stats);

// What one crossed surface lets through: f * pigment + t of its pigment at `point` (of its
// interior_texture's where a ray leaving the solid crosses it, when it has one).
Vec3 surface_transmittance(const geometry::SurfaceInfo& surface, const Vec3& point,
                           bool entering = true);

}  // namespace convray::render
