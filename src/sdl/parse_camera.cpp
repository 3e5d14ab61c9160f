// camera { [CAMERA_ID] [perspective | orthographic | fisheye | panoramic | spherical |
//          cylinder N | ultra_wide_angle] location, look_at, right, up, direction, sky, angle, transforms }
//
// The wide projections keep their angle (spherical: two) for the renderer instead of
// lengthening the direction; without one they span 90 degrees (spherical: 360 and 180).
//
// POV-Ray 3.7 reads every camera item first and then builds the frame in a fixed order,
// whatever order the scene wrote them in:
//  1. angle: direction gets the length 0.5 |right| / tan(angle / 2), the distance at which
//     `right` spans the horizontal field of view. An orthographic camera then scales right
//     and up by |look_at - location| / |direction| (found by rendering with POV-Ray 3.7.0.10:
//     the point looked at appears as large as through the perspective camera; look_at
//     defaults to <0, 0, 1>). So does one given neither right nor up, without an angle.
//  2. look_at: direction, right and up are turned to look at the point, keeping their lengths
//     and the handedness of right relative to up and direction:
//       direction = unit(look_at - location), right = unit(sky x direction),
//       up = direction x right, each times its old length (right negated if it was on the
//       other side).
//  3. the transforms, applied to location (a point) and the three vectors (directions).
#include <cmath>
#include <glm/geometric.hpp>

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

namespace {

struct CameraItems {
  scene::Camera::Kind kind = scene::Camera::Kind::perspective;
  Vec3 location{0.0, 0.0, 0.0};
  Vec3 direction{0.0, 0.0, 1.0};
  Vec3 right{1.33, 0.0, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  Vec3 sky{0.0, 1.0, 0.0};
  Vec3 look_at{0.0, 0.0, 1.0};
  bool has_look_at = false;
  bool has_right_or_up = false;  // written in this camera (or the declared one it copies)
  int cylinder_type = 1;
  std::optional<double> angle;
  std::optional<double> vertical_angle;  // spherical's second angle
  SourceLoc angle_loc, look_at_loc;
  scene::Transform transform;
};

CameraItems items_of(const scene::Camera& camera) {
  CameraItems items;
  items.kind = camera.kind;
  items.cylinder_type = camera.cylinder_type;
  if (camera.angle > 0.0) items.angle = camera.angle;
  if (camera.vertical_angle > 0.0) items.vertical_angle = camera.vertical_angle;
  items.location = camera.location;
  items.direction = camera.direction;
  items.right = camera.right;
  items.up = camera.up;
  items.look_at = camera.location + camera.direction;
  items.sky = camera.sky;
  items.has_right_or_up = true;  // its frame is final already
  return items;
}

constexpr std::string_view kCameraWords[] = {
    "perspective", "orthographic", "fisheye",     "panoramic",  "spherical", "cylinder",
    "ultra_wide_angle",
    "location",    "look_at",      "right",       "up",         "direction", "sky",
    "angle",       "translate",    "rotate",      "scale",      "matrix",    "transform",
    "aperture",    "blur_samples", "focal_point", "confidence", "variance",  "normal"};

constexpr std::string_view kUnsupportedProjections[] = {"omnimax", "mesh_camera", "stereo"};

bool is_wide(scene::Camera::Kind kind) {
  return kind != scene::Camera::Kind::perspective && kind != scene::Camera::Kind::orthographic;
}

// The vector a camera keyword sets, or null.
Vec3* vector_item(CameraItems& items, const std::string& word) {
  if (word == "location") return &items.location;
  if (word == "direction") return &items.direction;
  if (word == "right") return &items.right;
  if (word == "up") return &items.up;
  if (word == "sky") return &items.sky;
  if (word == "look_at") return &items.look_at;
  return nullptr;
}

void parse_camera_item(Parser& parser, Block& block, CameraItems& items) {
  if (auto transform = parse_transform_modifier(parser)) {
    items.transform = items.transform.then(*transform);
    return;
  }
  if (at_any_word(parser, kUnsupportedProjections)) {
    parser.fail_unsupported_here("the " + parser.peek().text +
                     " camera is not supported yet: convray "
                     "has the perspective and orthographic cameras");
  }
  if (!at_any_word(parser, kCameraWords)) block.unexpected(kCameraWords);
  const std::string word = parser.peek().text;
  const SourceLoc loc = parser.peek().loc;
  if (word == "normal") {
    parse_normal(parser, scene::Normal{});
    warn_once(parser, loc, "a camera normal (ray perturbation) is ignored by convray");
    return;
  }
  parser.next();
  if (Vec3* vector = vector_item(items, word)) {
    *vector = vector_param(parser, word);
    if (word == "look_at") {
      items.has_look_at = true;
      items.look_at_loc = loc;
    }
    if (word == "right" || word == "up") items.has_right_or_up = true;
  } else if (word == "perspective" || word == "orthographic") {
    items.kind = word == "perspective" ? scene::Camera::Kind::perspective
                                       : scene::Camera::Kind::orthographic;
  } else if (word == "fisheye" || word == "panoramic" || word == "spherical" ||
             word == "ultra_wide_angle") {
    items.kind = word == "fisheye"     ? scene::Camera::Kind::fisheye
                 : word == "panoramic" ? scene::Camera::Kind::panoramic
                 : word == "spherical" ? scene::Camera::Kind::spherical
                                       : scene::Camera::Kind::ultra_wide_angle;
  } else if (word == "cylinder") {
    items.kind = scene::Camera::Kind::cylinder;
    const SourceLoc type_at = parser.peek().loc;
    items.cylinder_type = int_param(parser, "cylinder camera type");
    if (items.cylinder_type < 1 || items.cylinder_type > 4) {
      parser.fail(type_at, "the cylinder camera's type must be 1, 2, 3 or 4, found " +
                               std::to_string(items.cylinder_type));
    }
  } else if (word == "angle") {
    items.angle = float_param(parser, "angle");
    items.angle_loc = loc;
    if (parser.at(",")) {  // spherical: angle H, V
      parser.accept_comma();
      items.vertical_angle = float_param(parser, "vertical angle");
    }
  } else {  // focal blur
    if (word == "focal_point") {
      vector_param(parser, word);
    } else {
      float_param(parser, word);
    }
    warn_once(parser, loc, "focal blur ('" + word + "') is ignored by convray");
  }
}

// An orthographic camera given an angle, or neither right nor up, shows the area the
// perspective camera would show at the point looked at: right and up scaled by
// |look_at - location| / |direction| (POV-Ray's documented second mode; measured with
// POV-Ray 3.7.0.10 for both cases: textures/pigments/transmitfx.pov has neither).
void spans_perspective_area(CameraItems& items) {
  const double distance = glm::length(items.look_at - items.location);
  const double length = glm::length(items.direction);
  if (distance > 0.0 && length > 0.0) {
    items.right *= distance / length;
    items.up *= distance / length;
  }
}

void apply_angle(Parser& parser, CameraItems& items) {
  const double angle = *items.angle;
  if (!(angle > 0.0 && angle < 180.0)) {
    parser.fail(items.angle_loc,
                "camera angle must lie strictly between 0 and 180 degrees, "
                "found " +
                    number_text(angle));
  }
  if (items.direction == Vec3(0.0)) parser.fail(items.angle_loc, "camera direction is 0");
  const double length = 0.5 * glm::length(items.right) / std::tan(angle * kPi / 360.0);
  items.direction = glm::normalize(items.direction) * length;
  if (items.kind == scene::Camera::Kind::orthographic) spans_perspective_area(items);
}

// The wide projections' angles, checked; the defaults as POV-Ray's.
void set_wide_angles(Parser& parser, const CameraItems& items, scene::Camera& camera) {
  camera.cylinder_type = items.cylinder_type;
  const bool spherical = items.kind == scene::Camera::Kind::spherical;
  // Without an angle POV-Ray's fisheye, cylinder and ultra_wide_angle cameras span 90
  // degrees (seen in the directions of its rays), whatever right and direction say.
  camera.angle = items.angle.value_or(spherical ? 360.0 : 90.0);
  camera.vertical_angle = items.vertical_angle.value_or(spherical ? 0.5 * camera.angle : 0.0);
  if (!(camera.angle > 0.0 && camera.angle <= 360.0) || camera.vertical_angle < 0.0 ||
      camera.vertical_angle > 360.0) {
    parser.fail(items.angle_loc, "camera angle must lie in (0, 360] degrees, found " +
                                     number_text(camera.angle));
  }
}

void apply_look_at(Parser& parser, CameraItems& items) {
  const double direction_length = glm::length(items.direction);
  const double up_length = glm::length(items.up);
  const double right_length = glm::length(items.right);
  // Right-handed unless strictly left-handed: POV-Ray mirrors the picture also when up and
  // direction are parallel (`up z` with the default direction, as prism3.inc writes it) and
  // the product is zero.
  const double handedness = glm::dot(glm::cross(items.up, items.direction), items.right);
  const bool mirrored = !(handedness > 0.0);
  const Vec3 view = items.look_at - items.location;
  if (view == Vec3(0.0)) {
    parser.fail(items.look_at_loc, "camera look_at is the camera's location");
  }
  const Vec3 forward = glm::normalize(view);
  const Vec3 side = glm::cross(items.sky, forward);
  if (glm::length(side) >= 1e-12 * glm::length(items.sky)) {
    items.right = glm::normalize(side);
  } else {
    // POV-Ray's fallback (seen with POV-Ray 3.7.0.10 looking straight down): the right
    // vector as given, on the side the handedness puts it.
    parser.warn(items.look_at_loc,
                "camera looks along its sky vector: the right vector is "
                "kept as given (as POV-Ray does)");
    items.right = glm::normalize(items.right) * (mirrored ? -1.0 : 1.0);
  }
  const Vec3 up = glm::cross(forward, items.right);
  if (up == Vec3(0.0)) {
    parser.fail(items.look_at_loc,
                "camera looks along its right vector: give a sky (or "
                "right) that differs from the direction to look_at");
  }
  items.up = glm::normalize(up) * up_length;
  items.direction = forward * direction_length;
  items.right *= mirrored ? -right_length : right_length;
}

}  // namespace

scene::Camera parse_camera(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "camera", loc);
  CameraItems items;
  if (auto declared = accept_declared<scene::Camera>(parser, "a camera"))
    items = items_of(*declared);
  while (block.more()) parse_camera_item(parser, block, items);

  const bool wide = is_wide(items.kind);
  if (items.angle && !wide) {
    apply_angle(parser, items);
  } else if (items.kind == scene::Camera::Kind::orthographic && !items.has_right_or_up) {
    spans_perspective_area(items);
  }
  const Vec3 item_lengths(glm::length(items.right), glm::length(items.up),
                          glm::length(items.direction));
  if (items.has_look_at) apply_look_at(parser, items);
  for (const Vec3* v : {&items.direction, &items.right, &items.up}) {
    if (*v == Vec3(0.0)) parser.fail(loc, "camera direction, right and up must not be 0");
  }
  scene::Camera camera;
  camera.kind = items.kind;
  if (wide) set_wide_angles(parser, items, camera);
  camera.location = items.transform.point(items.location);
  camera.direction = items.transform.vector(items.direction);
  camera.right = items.transform.vector(items.right);
  camera.up = items.transform.vector(items.up);
  if (items.has_look_at) camera.look_at = items.transform.point(items.look_at);
  if (items.has_look_at && items.transform.is_identity()) camera.item_lengths = item_lengths;
  camera.sky = items.transform.vector(items.sky);
  return camera;
}

}  // namespace convray::sdl::items
