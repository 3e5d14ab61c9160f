#include "render/wide_projections.hpp"

#include <cmath>

namespace convray::render {
namespace {

constexpr double kDegree = kPi / 180.0;

struct Frame {
  Vec3 r, u, d;               // unit right, up, direction
  double right_length, up_length;
};

Frame frame_of(const scene::Camera& camera) {
  return {glm::normalize(camera.right), glm::normalize(camera.up),
          glm::normalize(camera.direction), glm::length(camera.right), glm::length(camera.up)};
}

std::optional<Ray> fisheye(const scene::Camera& camera, double u, double v) {
  const Frame f = frame_of(camera);
  const double a = u * f.right_length, b = v * f.up_length;
  const double r = std::hypot(a, b);
  if (r > 0.5) return std::nullopt;
  const double theta = r * camera.angle * kDegree;
  Vec3 sideways(0.0);
  if (r > 0.0) sideways = (a * f.r + b * f.u) / r;
  return Ray{camera.location,
                       glm::normalize(std::sin(theta) * sideways + std::cos(theta) * f.d)};
}

Ray panoramic(const scene::Camera& camera, double u, double v) {
  const Vec3 direction = std::sin(kPi * u) * camera.right + std::tan(kPi * v) * camera.up +
                         std::cos(kPi * u) * camera.direction;
  return {camera.location, glm::normalize(direction)};
}

Ray spherical(const scene::Camera& camera, double u, double v) {
  const Frame f = frame_of(camera);
  const double longitude = u * camera.angle * kDegree;
  const double latitude = v * camera.vertical_angle * kDegree;
  const Vec3 direction = std::cos(latitude) * (std::sin(longitude) * f.r +
                                               std::cos(longitude) * f.d) +
                         std::sin(latitude) * f.u;
  return {camera.location, glm::normalize(direction)};
}

Ray cylinder(const scene::Camera& camera, double u, double v) {
  const Frame f = frame_of(camera);
  const double along_right = u * f.right_length, along_up = v * f.up_length;
  const double around_vertical = u * camera.angle * kDegree;
  const double around_horizontal = v * camera.angle * kDegree;
  const Vec3 vertical = std::sin(around_vertical) * f.r + std::cos(around_vertical) * f.d;
  const Vec3 horizontal = std::sin(around_horizontal) * f.u + std::cos(around_horizontal) * f.d;
  switch (camera.cylinder_type) {
    case 1:
      return {camera.location, glm::normalize(vertical + along_up * f.u)};
    case 2:
      return {camera.location, glm::normalize(horizontal + along_right * f.r)};
    case 3:
      return {camera.location + along_up * f.u, glm::normalize(vertical)};
    default:
      return {camera.location + along_right * f.r, glm::normalize(horizontal)};
  }
}

Ray ultra_wide_angle(const scene::Camera& camera, double u, double v) {
  const Frame f = frame_of(camera);
  const double a = u * camera.angle * kDegree;
  const double b = v * camera.angle * (f.up_length / f.right_length) * kDegree;
  const Vec3 direction =
      std::sin(a) * f.r + std::sin(b) * f.u + std::cos(a) * std::cos(b) * f.d;
  return {camera.location, glm::normalize(direction)};
}

}  // namespace

std::optional<Ray> wide_projection_ray(const scene::Camera& camera, double u,
                                                 double v) {
  switch (camera.kind) {
    case scene::Camera::Kind::fisheye:
      return fisheye(camera, u, v);
    case scene::Camera::Kind::panoramic:
      return panoramic(camera, u, v);
    case scene::Camera::Kind::spherical:
      return spherical(camera, u, v);
    case scene::Camera::Kind::cylinder:
      return cylinder(camera, u, v);
    case scene::Camera::Kind::ultra_wide_angle:
      return ultra_wide_angle(camera, u, v);
    default:
      return std::nullopt;
  }
}

}  // namespace convray::render
