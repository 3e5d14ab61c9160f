#pragma once
// Scene records written in a line for the renderer's end-to-end tests: objects with a
// texture, textures that are only ambient (their pixels show a colour exactly), cameras.
#include <memory>
#include <optional>
#include <utility>

#include "scene/look_at_camera.hpp"
#include "scene/scene.hpp"

namespace convray::testing {

inline scene::Color rgb(double r, double g, double b, double filter = 0.0, double transmit = 0.0) {
  return scene::Color{Vec3(r, g, b), filter, transmit};
}

// A plain texture: a solid pigment and the given ambient and diffuse.
inline std::shared_ptr<scene::Texture> plain_texture(const scene::Color& color, double ambient,
                                                     double diffuse) {
  auto texture = std::make_shared<scene::Texture>();
  texture->pigment.color = color;
  texture->finish.ambient = Vec3(ambient);
  texture->finish.diffuse = diffuse;
  return texture;
}

// A texture that shows its colour whatever the light: ambient 1, diffuse 0.
inline std::shared_ptr<scene::Texture> glowing(const scene::Color& color) {
  return plain_texture(color, 1.0, 0.0);
}

inline scene::ObjectPtr object(scene::Shape shape, scene::TexturePtr texture,
                               std::optional<scene::Interior> interior = std::nullopt,
                               scene::Transform transform = {}) {
  auto o = std::make_shared<scene::Object>();
  o->shape = std::move(shape);
  o->texture = std::move(texture);
  o->interior = interior;
  o->transform = transform;
  o->loc = SourceLoc{"test.pov", 1, 1};
  return o;
}

inline scene::ObjectPtr sphere(const Vec3& center, double radius, scene::TexturePtr texture,
                               std::optional<scene::Interior> interior = std::nullopt) {
  return object(scene::Sphere{center, radius}, std::move(texture), interior);
}

// POV-Ray's plane { normal, distance }.
inline scene::ObjectPtr plane(const Vec3& normal, double distance, scene::TexturePtr texture,
                              std::optional<scene::Interior> interior = std::nullopt) {
  return object(scene::Plane{normal, distance}, std::move(texture), interior);
}

inline scene::ObjectPtr box(const Vec3& a, const Vec3& b, scene::TexturePtr texture,
                            std::optional<scene::Interior> interior = std::nullopt) {
  return object(scene::Box{a, b}, std::move(texture), interior);
}

inline scene::Light point_light(const Vec3& position, const Vec3& color = Vec3(1.0)) {
  scene::Light light;
  light.position = position;
  light.color.rgb = color;
  return light;
}

// The scene camera of POV-Ray's `camera { location L look_at A angle a }` with
// `right x*W/H` (scene::look_at_camera reproduces POV-Ray's frame).
inline scene::Camera look_at_camera(const Vec3& location, const Vec3& look_at, double angle,
                                    int width, int height) {
  return scene::look_at_camera({location, look_at, angle, width, height});
}

// An orthographic camera at `location` looking along +z, showing `width` x `height` units.
inline scene::Camera orthographic_camera(const Vec3& location, double width, double height) {
  scene::Camera record;
  record.kind = scene::Camera::Kind::orthographic;
  record.location = location;
  record.direction = Vec3(0, 0, 1);
  record.right = Vec3(width, 0, 0);
  record.up = Vec3(0, height, 0);
  return record;
}

}  // namespace convray::testing
