#pragma once
// POV-Ray's perspective camera given by a location, a point to look at and a horizontal
// angle, with POV-Ray's defaults for the rest: sky <0,1,0>, `right` of length width/height,
// `up` of length 1, in left-handed coordinates taken as given (x right, y up, z into the
// screen; no axis is flipped). What `convray quick` asks for, as the scene's camera record.
#include "scene/scene.hpp"
#include "util/math.hpp"

namespace convray::scene {

struct LookAtView {
  Vec3 location{0.0, 0.0, -10.0};
  Vec3 look_at{0.0};
  double angle_degrees = 40.0;  // horizontal field of view, 0 < angle < 180
  int width = 800, height = 600;
};

// The camera record: direction towards look_at with the length at which `right` spans the
// angle, right = unit(sky x direction) * W/H, up = unit(direction x right). Throws
// std::invalid_argument when the frame is degenerate: location == look_at, a view straight
// along the sky vector, an angle outside (0, 180), or an empty image.
Camera look_at_camera(const LookAtView& view);

}  // namespace convray::scene
