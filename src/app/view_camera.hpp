#pragma once
// `convray view`'s camera: POV-Ray's camera items that the mouse moves (location, look_at,
// sky, and the lengths of right, up and direction), kept as the scene language says them, so
// that the view is always the camera block that prints it: camera_of() parses
// camera_block()'s text with the scene parser, and a block pasted into the scene renders
// the same picture (docs/view.md).
#include <string>

#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::app {

struct ViewCamera {
  scene::Camera::Kind kind = scene::Camera::Kind::perspective;
  int cylinder_type = 1;                 // cylinder only
  double angle = 0, vertical_angle = 0;  // the wide projections' (scene::Camera's)
  Vec3 location{0.0, 0.0, -10.0}, look_at{0.0}, sky{0.0, 1.0, 0.0};
  double right_length = 4.0 / 3.0, up_length = 1.0, direction_length = 1.0;
  bool mirrored = false;  // right on the other side (a right-handed scene)
};

// The items that give `camera` (a parsed scene's camera record). Without a look_at in the
// scene, the view looks along the camera's direction at the distance of `bounds`' centre
// (or at the direction's length, for empty or infinite bounds).
ViewCamera view_of(const scene::Camera& camera, const Box3& bounds);

// `camera { ... }` in the scene language, numbers in their shortest exact decimal form, so
// that parsing it gives back these very items.
std::string camera_block(const ViewCamera& view);

// The camera record the block gives, by the scene parser. Throws InputError for a view the
// language refuses (looking along the sky).
scene::Camera camera_of(const ViewCamera& view);

// Turns the camera around look_at: `yaw` about the sky, `pitch` about the camera's right
// (radians; positive pitch looks from higher up); the view never reaches the sky's axis.
ViewCamera orbit(const ViewCamera& view, double yaw, double pitch);
// Moves the camera towards look_at (factor < 1) or away (> 1); an orthographic camera shows
// a smaller or larger area instead, which is what moving it would not do.
ViewCamera zoom(const ViewCamera& view, double factor);
// Moves the camera and look_at together across the view by (dx, dy) times the picture's
// width and height at look_at's distance (dx to the right, dy up).
ViewCamera pan(const ViewCamera& view, double dx, double dy);

// The shortest decimal text that reads back as `value` ("0.1", "1e-05", "-3").
std::string exact_number(double value);
// <x, y, z> in exact_number's digits: a vector the scene language reads back bit for bit.
std::string vector_text(const Vec3& v);

}  // namespace convray::app
