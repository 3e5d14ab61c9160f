// POV-Ray's blob: `threshold t`, components `sphere { c, r, [strength] s }`,
// `cylinder { a, b, r, [strength] s }` and the old `component s, r, <c>`, each sphere and
// cylinder with its own transforms and texture; then the object's modifiers.
#include "sdl/component_modifiers.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

using Kind = scene::Implicit::Kind;

void require_radius(Parser& parser, const SourceLoc& loc, const std::string& what, double r) {
  if (!(r > 0.0)) parser.fail(loc, what + " radius must be positive, found " + number_text(r));
}

// `, [strength] s` after a component's radius.
double parse_strength(Parser& parser) {
  parser.accept_comma();
  accept_word(parser, "strength");
  return float_param(parser, "strength");
}

// The texture and transforms after a component's parameters, up to its `}`.
void parse_component_modifiers(Block& block, ComponentModifiers& modifiers) {
  while (block.more()) {
    if (!modifiers.parse()) block.unexpected(kComponentModifierWords);
  }
}

void parse_blob_sphere(Parser& parser, scene::Implicit& implicit) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "blob sphere", loc);
  scene::BlobSphereComponent sphere;
  sphere.center = vector_param(parser, "center");
  parser.accept_comma();
  sphere.weight.radius = float_param(parser, "radius");
  sphere.weight.strength = parse_strength(parser);
  require_radius(parser, loc, "blob sphere", sphere.weight.radius);
  ComponentModifiers modifiers(parser, "blob sphere");
  parse_component_modifiers(block, modifiers);
  sphere.center = modifiers.transform().point(sphere.center);
  sphere.weight.radius *= modifiers.scale();
  add_component_texture(implicit, modifiers.texture());
  implicit.component_order.emplace_back(Kind::blob_sphere, implicit.object.blob_spheres.size());
  implicit.object.blob_spheres.push_back(sphere);
}

void parse_blob_cylinder(Parser& parser, scene::Implicit& implicit) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "blob cylinder", loc);
  scene::BlobCylinderComponent cylinder;
  cylinder.base = vector_param(parser, "base point");
  parser.accept_comma();
  cylinder.apex = vector_param(parser, "cap point");
  parser.accept_comma();
  cylinder.weight.radius = float_param(parser, "radius");
  cylinder.weight.strength = parse_strength(parser);
  require_radius(parser, loc, "blob cylinder", cylinder.weight.radius);
  if (cylinder.base == cylinder.apex) {
    parser.fail(loc, "blob cylinder: its two end points coincide");
  }
  ComponentModifiers modifiers(parser, "blob cylinder");
  parse_component_modifiers(block, modifiers);
  cylinder.base = modifiers.transform().point(cylinder.base);
  cylinder.apex = modifiers.transform().point(cylinder.apex);
  cylinder.weight.radius *= modifiers.scale();
  add_component_texture(implicit, modifiers.texture());
  implicit.component_order.emplace_back(Kind::blob_cylinder, implicit.object.blob_cylinders.size());
  implicit.object.blob_cylinders.push_back(cylinder);
}

// The old form: `component strength, radius, <center>`.
void parse_old_component(Parser& parser, scene::Implicit& implicit) {
  const SourceLoc loc = take_keyword(parser);
  scene::BlobSphereComponent sphere;
  sphere.weight.strength = float_param(parser, "strength");
  parser.accept_comma();
  sphere.weight.radius = float_param(parser, "radius");
  parser.accept_comma();
  sphere.center = vector_param(parser, "center");
  require_radius(parser, loc, "blob component", sphere.weight.radius);
  implicit.component_order.emplace_back(Kind::blob_sphere, implicit.object.blob_spheres.size());
  implicit.object.blob_spheres.push_back(sphere);
}

}  // namespace

scene::ObjectPtr parse_blob(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "blob", loc);
  scene::Object object;
  object.loc = loc;
  scene::Implicit blob;
  blob.is_blob = true;
  blob.object.threshold = 1.0;  // POV-Ray's default
  object.shape = std::move(blob);
  ObjectBuilder builder(parser, std::move(object));
  auto& implicit = std::get<scene::Implicit>(builder.object().shape);

  static constexpr std::string_view kOwn[] = {"threshold", "sphere",    "cylinder",
                                              "component", "hierarchy", "sturm"};
  while (block.more()) {
    const bool component =
        at_word(parser, "sphere") || at_word(parser, "cylinder") || at_word(parser, "component");
    if (component && builder.modified()) builder.fail_after_modifiers("the blob's components");
    if (at_word(parser, "sphere")) {
      parse_blob_sphere(parser, implicit);
    } else if (at_word(parser, "cylinder")) {
      parse_blob_cylinder(parser, implicit);
    } else if (at_word(parser, "component")) {
      parse_old_component(parser, implicit);
    } else if (at_word(parser, "threshold")) {
      const SourceLoc threshold_loc = take_keyword(parser);
      implicit.object.threshold = float_param(parser, "threshold");
      if (!(implicit.object.threshold > 0.0)) {
        parser.fail(threshold_loc, "blob threshold must be positive, found " +
                                       number_text(implicit.object.threshold));
      }
    } else if (accept_word(parser, "hierarchy")) {
      optional_bool(parser);  // a bounding hint; our bounds are always built
    } else if (!builder.parse_modifier()) {
      block.unexpected(kOwn, modifier_words());
    }
  }
  if (implicit.component_order.empty()) parser.fail(loc, "blob has no components");
  return builder.build();
}

}  // namespace convray::sdl::items
