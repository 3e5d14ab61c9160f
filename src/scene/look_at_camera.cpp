#include "scene/look_at_camera.hpp"

#include <cmath>
#include <stdexcept>

namespace convray::scene {

namespace {

constexpr Vec3 kSky{0.0, 1.0, 0.0};

double radians(double degrees) { return degrees * kPi / 180.0; }

}  // namespace

Camera look_at_camera(const LookAtView& view) {
  if (view.width < 1 || view.height < 1)
    throw std::invalid_argument("the image must have at least one pixel");
  if (!(view.angle_degrees > 0.0 && view.angle_degrees < 180.0)) {
    throw std::invalid_argument("the camera angle must lie strictly between 0 and 180 degrees");
  }
  const Vec3 towards = view.look_at - view.location;
  const double view_length = glm::length(towards);
  if (!(view_length > 0.0) || !std::isfinite(view_length)) {
    throw std::invalid_argument("the camera location and look_at must be distinct finite points");
  }

  // POV-Ray's defaults: right = <W/H, 0, 0>, up = <0, 1, 0>; `angle` sets the direction's
  // length so that the right vector spans the horizontal field of view.
  const double right_length = double(view.width) / double(view.height);
  const double up_length = 1.0;
  const double direction_length =
      0.5 * right_length / std::tan(0.5 * radians(view.angle_degrees));

  // `look_at` turns the frame as POV-Ray does, keeping each vector's length. In left-handed
  // coordinates cross(sky, direction) points to the viewer's right.
  const Vec3 forward = towards / view_length;
  const Vec3 side = glm::cross(kSky, forward);
  if (glm::length(side) < 1e-12) {
    throw std::invalid_argument(
        "the view direction must not be vertical (parallel to the sky <0,1,0>)");
  }
  Camera camera;
  camera.kind = Camera::Kind::perspective;
  camera.location = view.location;
  camera.direction = forward * direction_length;
  camera.right = glm::normalize(side) * right_length;
  camera.up = glm::normalize(glm::cross(camera.direction, camera.right)) * up_length;
  return camera;
}

}  // namespace convray::scene
