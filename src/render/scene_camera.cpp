#include "render/scene_camera.hpp"

#include <cmath>
#include <stdexcept>

#include "render/wide_projections.hpp"

namespace convray::render {

SceneCamera::SceneCamera(const scene::Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
  if (width < 1 || height < 1) throw std::invalid_argument("the image needs at least one pixel");
  const double direction_length = glm::length(camera.direction);
  if (!(direction_length > 0.0) || !std::isfinite(direction_length)) {
    throw std::invalid_argument("the camera direction must be a non-zero finite vector");
  }
  const double spanned = glm::length(glm::cross(camera.right, camera.up));
  if (!(spanned > 0.0) || !std::isfinite(spanned)) {
    throw std::invalid_argument("the camera's right and up vectors must span a plane");
  }
}

Ray SceneCamera::ray_through(double x0, double y0) const {
  using Kind = scene::Camera::Kind;
  if (camera_.kind != Kind::perspective && camera_.kind != Kind::orthographic) {
    const std::optional<Ray> ray = wide_projection_ray(camera_, x0, y0);
    return ray ? *ray : Ray{camera_.location, Vec3(0.0)};
  }
  const Vec3 offset = x0 * camera_.right + y0 * camera_.up;
  if (camera_.kind == scene::Camera::Kind::orthographic) {
    return Ray{camera_.location + offset, glm::normalize(camera_.direction)};
  }
  return Ray{camera_.location, glm::normalize(camera_.direction + offset)};
}

Ray SceneCamera::ray_at_film(double x, double y) const {
  return ray_through(x / width_ - 0.5, 0.5 - y / height_);
}

}  // namespace convray::render
