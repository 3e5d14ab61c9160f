// The classic primitives: sphere, box, plane, cylinder, cone, torus, disc. Each reads its
// own parameters, checks them (degenerate shapes fail at the object's keyword) and ends with
// the object modifiers.
#include <cmath>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

scene::Object make_object(scene::Shape shape, const SourceLoc& loc) {
  scene::Object object;
  object.shape = std::move(shape);
  object.loc = loc;
  return object;
}

void require_positive(Parser& parser, const SourceLoc& loc, const std::string& what, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    parser.fail(loc, what + " must be positive, found " + number_text(value));
  }
}

void require_distinct(Parser& parser, const SourceLoc& loc, const std::string& shape, const Vec3& a,
                      const Vec3& b) {
  if (a == b) parser.fail(loc, shape + ": its two end points coincide");
}

}  // namespace

scene::ObjectPtr parse_sphere(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "sphere", loc);
  scene::Sphere sphere;
  sphere.center = vector_param(parser, "center");
  parser.accept_comma();
  sphere.radius = float_param(parser, "radius");
  require_positive(parser, loc, "sphere radius", sphere.radius);
  return parse_modifiers(block, make_object(sphere, loc));
}

scene::ObjectPtr parse_box(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "box", loc);
  scene::Box box;
  box.corner1 = vector_param(parser, "corner 1");
  parser.accept_comma();
  box.corner2 = vector_param(parser, "corner 2");
  return parse_modifiers(block, make_object(box, loc));
}

scene::ObjectPtr parse_plane(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "plane", loc);
  scene::Plane plane;
  plane.normal = vector_param(parser, "normal");
  parser.accept_comma();
  plane.distance = float_param(parser, "distance");
  if (plane.normal == Vec3(0.0)) parser.fail(loc, "plane normal must not be <0, 0, 0>");
  return parse_modifiers(block, make_object(plane, loc));
}

scene::ObjectPtr parse_cylinder(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "cylinder", loc);
  scene::Object object = make_object(scene::Cylinder{}, loc);
  auto& cylinder = std::get<scene::Cylinder>(object.shape);
  cylinder.base = vector_param(parser, "base point");
  parser.accept_comma();
  cylinder.cap = vector_param(parser, "cap point");
  parser.accept_comma();
  cylinder.radius = float_param(parser, "radius");
  require_positive(parser, loc, "cylinder radius", cylinder.radius);
  require_distinct(parser, loc, "cylinder", cylinder.base, cylinder.cap);
  static constexpr std::string_view kOwn[] = {"open"};
  return parse_modifiers(block, std::move(object), kOwn, [&parser](ObjectBuilder& builder) {
    if (!accept_word(parser, "open")) return false;
    std::get<scene::Cylinder>(builder.object().shape).open = optional_bool(parser);
    return true;
  });
}

scene::ObjectPtr parse_cone(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "cone", loc);
  scene::Object object = make_object(scene::Cone{}, loc);
  auto& cone = std::get<scene::Cone>(object.shape);
  cone.base = vector_param(parser, "base point");
  parser.accept_comma();
  cone.base_radius = float_param(parser, "base radius");
  parser.accept_comma();
  cone.cap = vector_param(parser, "cap point");
  parser.accept_comma();
  cone.cap_radius = float_param(parser, "cap radius");
  if (cone.base_radius < 0.0 || cone.cap_radius < 0.0) {
    parser.fail(loc, "cone radii must not be negative, found " + number_text(cone.base_radius) +
                         " and " + number_text(cone.cap_radius));
  }
  if (cone.base_radius == 0.0 && cone.cap_radius == 0.0) {
    parser.fail(loc, "cone: both radii are 0");
  }
  require_distinct(parser, loc, "cone", cone.base, cone.cap);
  static constexpr std::string_view kOwn[] = {"open"};
  return parse_modifiers(block, std::move(object), kOwn, [&parser](ObjectBuilder& builder) {
    if (!accept_word(parser, "open")) return false;
    std::get<scene::Cone>(builder.object().shape).open = optional_bool(parser);
    return true;
  });
}

scene::ObjectPtr parse_torus(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "torus", loc);
  scene::Torus torus;
  torus.major = float_param(parser, "major radius");
  parser.accept_comma();
  torus.minor = float_param(parser, "minor radius");
  require_positive(parser, loc, "torus major radius", torus.major);
  require_positive(parser, loc, "torus minor radius", torus.minor);
  return parse_modifiers(block, make_object(torus, loc));
}

scene::ObjectPtr parse_disc(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "disc", loc);
  scene::Disc disc;
  disc.center = vector_param(parser, "center");
  parser.accept_comma();
  disc.normal = vector_param(parser, "normal");
  parser.accept_comma();
  disc.radius = float_param(parser, "radius");
  parser.accept_comma();
  if (at_float_start(parser)) disc.hole_radius = float_param(parser, "hole radius");
  if (disc.normal == Vec3(0.0)) parser.fail(loc, "disc normal must not be <0, 0, 0>");
  require_positive(parser, loc, "disc radius", disc.radius);
  if (disc.hole_radius < 0.0 || disc.hole_radius >= disc.radius) {
    parser.fail(loc,
                "disc hole radius must lie in [0, radius), found " + number_text(disc.hole_radius));
  }
  return parse_modifiers(block, make_object(disc, loc));
}

}  // namespace convray::sdl::items
