#pragma once
// The scene `convray quick` renders: one convolution object in a warm clay finish, one point
// light with shadows, a dark background, and a perspective camera that either frames the
// object's bounds or looks where the options say. Quick pictures go through the same
// renderer as scene files (render/render_scene.hpp); this file only chooses the records.
#include <memory>

#include "scene/convolution_object.hpp"
#include "scene/look_at_camera.hpp"
#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::scene {

// A view that shows all of `bounds` (assumed non-empty): it looks at the box's centre from
// the -z side and somewhat above (about 20 degrees), far enough that the box's bounding sphere
// fits in both the horizontal and the vertical field of view with a 5% margin.
LookAtView frame_bounds(const Box3& bounds, int width, int height, double angle_degrees);

// A light above, to the left of and behind the camera, a few bounding radii away from the
// box's centre, so that shadows fall visibly down and to the right of the object.
Vec3 default_light_position(const Camera& camera, const Box3& bounds);

// The finish of quick's pictures: ambient 0.08, diffuse 0.85, phong 0.3 with phong_size 40.
TexturePtr quick_texture();
// What a camera ray that misses everything shows: a dark blue-grey, so black shadows read.
Vec3 quick_background();

// The whole scene: `object` (in world space) seen by `camera`, lit by a white point light at
// `light`, shadows on, assumed_gamma 1. `record` (optional) receives the object's record, for
// a caller that changes it (command_quick.cpp lends its mesh triangles to the surface).
Scene quick_scene(scene::ConvolutionObject object, const Camera& camera, const Vec3& light,
                  std::shared_ptr<Object>* record = nullptr);

}  // namespace convray::scene
