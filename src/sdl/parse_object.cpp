// Which parser an object keyword goes to, and `object { ID | OBJECT  [modifiers] }`.
#include <iterator>

#include "scene/instance.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

using ShapeParser = scene::ObjectPtr (*)(Parser&);

struct ShapeKeyword {
  std::string_view word;
  ShapeParser parse;
};

scene::ObjectPtr parse_object_statement(Parser& parser);

constexpr ShapeKeyword kShapes[] = {
    {"sphere", parse_sphere},
    {"box", parse_box},
    {"plane", parse_plane},
    {"cylinder", parse_cylinder},
    {"cone", parse_cone},
    {"torus", parse_torus},
    {"disc", parse_disc},
    {"triangle", parse_triangle},
    {"smooth_triangle", parse_triangle},
    {"mesh", parse_mesh},
    {"mesh2", parse_mesh2},
    {"union", parse_csg},
    {"intersection", parse_csg},
    {"difference", parse_csg},
    {"merge", parse_csg},
    {"blob", parse_blob},
    {"convolution", parse_convolution},
    {"text", parse_text},
    {"prism", parse_prism},
    {"superellipsoid", parse_superellipsoid},
    {"lathe", parse_lathe},
    {"polygon", parse_polygon},
    {"sor", parse_sor},
    {"bicubic_patch", parse_bicubic_patch},
    {"height_field", parse_height_field},
    {"isosurface", parse_isosurface},
    {"poly", parse_polynomial},
    {"cubic", parse_polynomial},
    {"quartic", parse_polynomial},
    {"quadric", parse_polynomial},
    {"object", parse_object_statement},
};

constexpr std::string_view kObjectWords[] = {
    "sphere",       "box",        "plane",           "cylinder", "cone",        "torus",
    "disc",         "triangle",   "smooth_triangle", "mesh",     "mesh2",       "union",
    "intersection", "difference", "merge",           "blob",     "convolution", "object",
    "poly",         "cubic",      "quartic",         "quadric",  "text", "prism",
    "superellipsoid", "lathe", "isosurface"};

// The declared object named by the next token (consumed), or null when it names none.
scene::ObjectPtr declared_object(Parser& parser) {
  const Value* declared = parser.peek_declared();
  if (!declared) return nullptr;
  if (const auto* object = declared->get<scene::ObjectPtr>()) {
    scene::ObjectPtr result = *object;
    parser.next();
    return result;
  }
  if (declared->get<std::shared_ptr<Array>>()) {  // `object { Things[i] }`
    const SourceLoc loc = parser.peek().loc;
    const Value element = parser.parse_expression();
    if (const auto* object = element.get<scene::ObjectPtr>(); object && *object) return *object;
    parser.fail(loc, "expected an object in object { }, found " + type_name(element));
  }
  const std::string name = parser.peek().text;
  if (declared->get<std::shared_ptr<const scene::Light>>()) {
    parser.fail_here("'" + name + "' is a light_source: place it with light_source { " + name +
                     " }");
  }
  parser.fail_here("expected an object in object { }, found '" + name + "' (" +
                   type_name(*declared) + ")");
}

// What follows `object {`: a declared object or an object (unless `base` was read
// already), then modifiers.
scene::ObjectPtr parse_object_body(Parser& parser, Block& block, scene::ObjectPtr base = {}) {
  if (!base) base = declared_object(parser);
  if (!base) {
    if (!at_object(parser)) {
      parser.fail_here("expected a declared object or an object in object { }, found '" +
                       parser.peek().text + "'");
    }
    base = parse_object(parser);
  }
  // Without modifiers the declared record is shared as it is (a mesh is not copied); a
  // declared union moved by transforms is shared too, as an instance (scene/instance.hpp).
  if (!block.more()) return base;
  if (const auto* mesh = std::get_if<scene::TriangleMesh>(&base->shape)) {
    // The copy holds the mesh's lists again (TriangleMesh::counted): checked before it is made.
    parser.check_element_budget(mesh->counted.count(), block.loc());
  }
  scene::Object copy = scene::can_instance(*base)
                           ? scene::instance_of(base, scene::Transform{}, block.loc())
                           : *base;
  copy.loc = block.loc();
  ObjectBuilder builder(parser, std::move(copy));
  do {
    if (!builder.parse_modifier()) block.unexpected({}, modifier_words());
  } while (block.more());
  return builder.build();
}

scene::ObjectPtr parse_object_statement(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "object", loc);
  return parse_object_body(parser, block);
}

constexpr std::string_view kUnsupportedObjects[] = {
    "polynomial", "parametric",    "julia_fractal",
    "sphere_sweep",  "ovus",          "lemon"};

}  // namespace

Keywords object_words() { return kObjectWords; }

bool at_unsupported_object(Parser& parser) { return at_any_word(parser, kUnsupportedObjects); }

bool at_object(Parser& parser) {
  for (const ShapeKeyword& shape : kShapes) {
    if (at_word(parser, shape.word)) return true;
  }
  return at_unsupported_object(parser);
}

scene::ObjectPtr parse_object(Parser& parser) {
  for (const ShapeKeyword& shape : kShapes) {
    if (at_word(parser, shape.word)) return shape.parse(parser);
  }
  if (at_unsupported_object(parser)) {
    parser.fail_here("'" + parser.peek().text + "' objects are not supported yet by convray");
  }
  parser.fail_here("expected an object, found '" + parser.peek().text + "'");
}

void parse_top_level_object(Parser& parser, scene::Scene& scene) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "object", loc);
  const Value* declared = parser.peek_declared();
  Value named;  // a declared item, or an element of a declared array
  if (declared && (declared->get<std::shared_ptr<Array>>() ||
                   declared->get<std::shared_ptr<const scene::Light>>())) {
    named = parser.parse_expression();
  }
  if (const auto* light = named.get<std::shared_ptr<const scene::Light>>()) {
    scene.lights.push_back(parse_light_modifiers(parser, block, **light));
    return;
  }
  scene::ObjectPtr base;
  if (named.is_set()) {
    const auto* object = named.get<scene::ObjectPtr>();
    if (!object || !*object) {
      parser.fail(loc,
                  "expected an object or light_source in object { }, found " + type_name(named));
    }
    base = *object;
  }
  scene.objects.push_back(placed_object(parser, parse_object_body(parser, block, base), loc));
  add_csg_lights(*scene.objects.back(), scene);
}

scene::ObjectPtr parse_unsupported_object_as_empty(Parser& parser) {
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  skip_braced(parser, word, loc);
  warn_once(parser, loc,
            "'" + word +
                "' objects are not supported yet by convray: declaring one is accepted, "
                "placing it in the scene is an error");
  scene::Object empty;
  empty.shape = scene::Csg{scene::CsgOperation::union_, {}};
  empty.unsupported = scene::UnsupportedObject{word, loc};
  empty.loc = loc;
  return std::make_shared<const scene::Object>(std::move(empty));
}

}  // namespace convray::sdl::items
