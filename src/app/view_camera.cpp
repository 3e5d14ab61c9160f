#include "app/view_camera.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "sdl/parser.hpp"

namespace convray::app {

namespace {

using Kind = scene::Camera::Kind;

// Rodrigues' rotation of v by `angle` about the unit `axis`.
Vec3 rotated(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

std::string kind_text(const ViewCamera& v) {
  switch (v.kind) {
    case Kind::perspective: return "perspective";
    case Kind::orthographic: return "orthographic";
    case Kind::fisheye: return "fisheye";
    case Kind::panoramic: return "panoramic";
    case Kind::spherical: return "spherical";
    case Kind::cylinder: return "cylinder " + std::to_string(v.cylinder_type);
    case Kind::ultra_wide_angle: return "ultra_wide_angle";
  }
  return "perspective";
}

bool wide(Kind kind) { return kind != Kind::perspective && kind != Kind::orthographic; }

// The camera's unit right vector as the parser's look_at makes it.
Vec3 right_axis(const ViewCamera& v) {
  const Vec3 side = glm::cross(v.sky, v.look_at - v.location);
  const double length = glm::length(side);
  return length > 0.0 ? side / length : Vec3(1.0, 0.0, 0.0);
}

}  // namespace

std::string exact_number(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : "0";
}

std::string vector_text(const Vec3& v) {
  return "<" + exact_number(v.x) + ", " + exact_number(v.y) + ", " + exact_number(v.z) + ">";
}

ViewCamera view_of(const scene::Camera& camera, const Box3& bounds) {
  ViewCamera v;
  v.kind = camera.kind;
  v.cylinder_type = camera.cylinder_type;
  v.angle = camera.angle;
  v.vertical_angle = camera.vertical_angle;
  v.location = camera.location;
  v.sky = camera.sky;
  v.right_length = glm::length(camera.right);
  v.up_length = glm::length(camera.up);
  v.direction_length = glm::length(camera.direction);
  v.mirrored = !(glm::dot(glm::cross(camera.up, camera.direction), camera.right) > 0.0);
  if (camera.item_lengths.x > 0.0) {  // as written: exact (the final vectors' may be a bit off)
    v.right_length = camera.item_lengths.x;
    v.up_length = camera.item_lengths.y;
    v.direction_length = camera.item_lengths.z;
  }
  if (camera.look_at && *camera.look_at != camera.location) {
    v.look_at = *camera.look_at;
  } else {
    double distance = v.direction_length;
    const Vec3 centre = bounds.empty() ? Vec3(0.0) : 0.5 * (bounds.lo + bounds.hi);
    if (!bounds.empty() && std::isfinite(glm::length(centre - camera.location))) {
      distance = std::max(glm::length(centre - camera.location), 1e-9);
    }
    v.look_at = camera.location + glm::normalize(camera.direction) * distance;
  }
  return v;
}

std::string camera_block(const ViewCamera& v) {
  std::string block = "camera {\n  " + kind_text(v) + "\n";
  block += "  location " + vector_text(v.location) + "\n";
  block += "  right " + vector_text({v.mirrored ? -v.right_length : v.right_length, 0, 0}) + "\n";
  block += "  up " + vector_text({0, v.up_length, 0}) + "\n";
  block += "  direction " + vector_text({0, 0, v.direction_length}) + "\n";
  if (wide(v.kind)) {
    block += "  angle " + exact_number(v.angle);
    if (v.kind == Kind::spherical) block += ", " + exact_number(v.vertical_angle);
    block += "\n";
  }
  block += "  sky " + vector_text(v.sky) + "\n";
  block += "  look_at " + vector_text(v.look_at) + "\n}\n";
  return block;
}

scene::Camera camera_of(const ViewCamera& view) {
  sdl::ParseOptions options;
  options.system_include_paths.clear();
  return sdl::parse_string(camera_block(view), "view camera", options).scene.camera;
}

ViewCamera orbit(const ViewCamera& view, double yaw, double pitch) {
  ViewCamera v = view;
  const Vec3 sky = glm::normalize(v.sky);
  Vec3 offset = v.location - v.look_at;
  offset = rotated(offset, sky, yaw);
  // Keep the view at least a degree away from the sky's axis, where look_at is undefined.
  const double elevation = std::asin(std::clamp(glm::dot(glm::normalize(offset), sky), -1.0, 1.0));
  const double limit = 0.5 * kPi - kPi / 180.0;
  const double wanted = std::clamp(elevation + pitch, -limit, limit);
  Vec3 level = offset - sky * glm::dot(offset, sky);
  if (glm::length(level) < 1e-12 * glm::length(offset)) {  // a scene looking along its sky
    level = glm::cross(sky, std::abs(sky.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 0, 1));
  }
  offset = glm::length(offset) *
           (std::cos(wanted) * glm::normalize(level) + std::sin(wanted) * sky);
  v.location = v.look_at + offset;
  return v;
}

ViewCamera zoom(const ViewCamera& view, double factor) {
  ViewCamera v = view;
  if (v.kind == Kind::orthographic) {
    v.right_length *= factor;
    v.up_length *= factor;
    return v;
  }
  const Vec3 offset = v.location - v.look_at;
  const double distance = glm::length(offset);
  const double wanted = std::max(distance * factor, 1e-9 * std::max(1.0, distance));
  v.location = v.look_at + offset * (wanted / distance);
  return v;
}

ViewCamera pan(const ViewCamera& view, double dx, double dy) {
  ViewCamera v = view;
  const Vec3 forward = glm::normalize(v.look_at - v.location);
  const Vec3 right = right_axis(v);
  const Vec3 up = glm::normalize(glm::cross(forward, right));
  const double distance = glm::length(v.look_at - v.location);
  // The picture's size at look_at: right and up span it at the direction's distance.
  const double scale = v.kind == Kind::orthographic ? 1.0 : distance / v.direction_length;
  const Vec3 move = right * (dx * v.right_length * scale * (v.mirrored ? -1.0 : 1.0)) +
                    up * (dy * v.up_length * scale);
  v.location += move;
  v.look_at += move;
  return v;
}

}  // namespace convray::app
