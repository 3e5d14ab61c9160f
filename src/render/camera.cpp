#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace convray::render {

namespace {

constexpr Vec3 kSky{0.0, 1.0, 0.0};

double radians(double degrees) { return degrees * kPi / 180.0; }

}  // namespace

Camera::Camera(const CameraSpec& spec)
    : location_(spec.location), width_(spec.width), height_(spec.height) {
  if (width_ < 1 || height_ < 1)
    throw std::invalid_argument("the image must have at least one pixel");
  if (!(spec.angle_degrees > 0.0 && spec.angle_degrees < 180.0)) {
    throw std::invalid_argument("the camera angle must lie strictly between 0 and 180 degrees");
  }
  const Vec3 view = spec.look_at - spec.location;
  const double view_length = glm::length(view);
  if (!(view_length > 0.0) || !std::isfinite(view_length)) {
    throw std::invalid_argument("the camera location and look_at must be distinct finite points");
  }

  // POV-Ray's defaults: right = <W/H, 0, 0>, up = <0, 1, 0>; `angle` sets the direction's
  // length so that the right vector spans the horizontal field of view.
  const double right_length = double(width_) / double(height_);
  const double up_length = 1.0;
  const double direction_length = 0.5 * right_length / std::tan(0.5 * radians(spec.angle_degrees));

  // `look_at` turns the frame as POV-Ray does, keeping each vector's length. In left-handed
  // coordinates cross(sky, direction) points to the viewer's right.
  const Vec3 forward = view / view_length;
  const Vec3 side = glm::cross(kSky, forward);
  if (glm::length(side) < 1e-12) {
    throw std::invalid_argument(
        "the view direction must not be vertical (parallel to the sky <0,1,0>)");
  }
  direction_ = forward * direction_length;
  right_ = glm::normalize(side) * right_length;
  up_ = glm::normalize(glm::cross(direction_, right_)) * up_length;
}

Ray Camera::ray_through(double x0, double y0) const {
  return Ray{location_, glm::normalize(direction_ + x0 * right_ + y0 * up_)};
}

Ray Camera::primary_ray(int i, int j) const {
  const double x0 = (i + 0.5) / width_ - 0.5;
  const double y0 = 0.5 - (j + 0.5) / height_;
  return ray_through(x0, y0);
}

CameraSpec frame_bounds(const Box3& bounds, int width, int height, double angle_degrees) {
  const Vec3 center = 0.5 * (bounds.lo + bounds.hi);
  const double radius =
      std::max(0.5 * glm::length(bounds.extent()), 1e-9 * (1.0 + glm::length(center)));

  // The sphere of radius r at distance d fills a half-angle asin(r/d); it must fit in the
  // smaller of the half fields of view (vertical: tan = tan(horizontal) * H/W).
  const double half_horizontal = 0.5 * radians(angle_degrees);
  const double half_vertical =
      std::atan(std::tan(half_horizontal) * double(height) / double(width));
  const double distance = 1.05 * radius / std::sin(std::min(half_horizontal, half_vertical));

  const double elevation = radians(20.0);
  const Vec3 towards_camera{0.0, std::sin(elevation), -std::cos(elevation)};
  return CameraSpec{center + distance * towards_camera, center, angle_degrees, width, height};
}

Vec3 default_light_position(const Camera& camera, const Box3& bounds) {
  const Vec3 center = 0.5 * (bounds.lo + bounds.hi);
  const double radius = 0.5 * glm::length(bounds.extent());
  const Vec3 right = glm::normalize(camera.right());
  const Vec3 up = glm::normalize(camera.up());
  const Vec3 forward = glm::normalize(camera.direction());
  // Relative to the camera, whose distance already scales with the object.
  const double reach = std::max(radius, 0.25 * glm::length(camera.location() - center));
  return camera.location() + reach * (-2.0 * right + 3.0 * up - 1.0 * forward);
}

}  // namespace convray::render
