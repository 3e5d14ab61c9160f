#include "scene/quick_scene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace convray::scene {

namespace {

double radians(double degrees) { return degrees * kPi / 180.0; }

}  // namespace

LookAtView frame_bounds(const Box3& bounds, int width, int height, double angle_degrees) {
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
  return LookAtView{center + distance * towards_camera, center, angle_degrees, width,
                           height};
}

Vec3 default_light_position(const Camera& camera, const Box3& bounds) {
  const Vec3 center = 0.5 * (bounds.lo + bounds.hi);
  const double radius = 0.5 * glm::length(bounds.extent());
  const Vec3 right = glm::normalize(camera.right);
  const Vec3 up = glm::normalize(camera.up);
  const Vec3 forward = glm::normalize(camera.direction);
  // Relative to the camera, whose distance already scales with the object.
  const double reach = std::max(radius, 0.25 * glm::length(camera.location - center));
  return camera.location + reach * (-2.0 * right + 3.0 * up - 1.0 * forward);
}

Vec3 quick_background() { return Vec3(0.015, 0.018, 0.025); }

TexturePtr quick_texture() {
  Texture texture;
  texture.pigment.color.rgb = Vec3(0.80, 0.60, 0.42);  // a warm clay
  texture.finish.ambient = Vec3(0.08);
  texture.finish.diffuse = 0.85;
  texture.finish.phong = 0.30;
  texture.finish.phong_size = 40.0;
  return std::make_shared<const Texture>(texture);
}

Scene quick_scene(scene::ConvolutionObject object, const Camera& camera, const Vec3& light,
                  std::shared_ptr<Object>* record_out) {
  Scene scene;
  scene.camera = camera;
  Light lamp;
  lamp.position = light;
  scene.lights.push_back(lamp);
  scene.background = Color{quick_background()};

  auto record = std::make_shared<Object>();
  Implicit implicit;
  implicit.object = std::move(object);
  record->shape = std::move(implicit);
  record->texture = quick_texture();
  record->loc = SourceLoc{"command line"};
  if (record_out) *record_out = record;
  scene.objects.push_back(std::move(record));
  return scene;
}

}  // namespace convray::scene
