// The entry points of the item parsers (items.hpp): which parser each keyword goes to.
#include "sdl/items.hpp"

#include "sdl/item_parsers.hpp"

namespace convray::sdl {

namespace {

template <class T>
void set_item(Value& out, T item) {
  out.data = std::shared_ptr<const T>(std::make_shared<const T>(std::move(item)));
}

constexpr std::string_view kStatementWords[] = {
    "camera",       "light_source", "background",      "fog",      "sky_sphere", "global_settings",
    "sphere",       "box",          "plane",           "cylinder", "cone",       "torus",
    "disc",         "triangle",     "smooth_triangle", "mesh",     "mesh2",      "union",
    "intersection", "difference",   "merge",           "object",   "blob",       "convolution",
    "rainbow",      "media"};

[[noreturn]] void fail_unknown_statement(Parser& parser) {
  const Token token = parser.peek();
  if (token.kind == Token::Kind::identifier || token.kind == Token::Kind::keyword) {
    if (const Value* declared = parser.peek_declared()) {
      if (declared->get<scene::ObjectPtr>()) {
        parser.fail(token.loc, "'" + token.text + "' is an object: place it with object { " +
                                   token.text + " }");
      }
      if (declared->get<std::shared_ptr<const scene::Light>>()) {
        parser.fail(token.loc, "'" + token.text +
                                   "' is a light_source: place it with light_source { " +
                                   token.text + " }");
      }
      parser.fail(token.loc, "unexpected '" + token.text + "' (" + type_name(*declared) +
                                 ") at the top level of the scene");
    }
    const std::string suggestion = items::closest_word(token.text, kStatementWords);
    parser.fail(token.loc, "unexpected '" + token.text + "' at the top level of the scene" +
                               (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)"));
  }
  parser.fail(token.loc, "unexpected '" + token.text + "' at the top level of the scene");
}

// Items the scene language has and Value (value.hpp) has no place for yet.
constexpr std::string_view kUndeclarable[] = {"fog", "rainbow", "media",
                                              "background"};

// A declared material is held as its texture until Value can hold a material.
scene::Texture parse_declared_material(Parser& parser) {
  const SourceLoc loc = parser.peek().loc;
  items::ParsedMaterial material = items::parse_material(parser);
  if (material.interior) {
    items::warn_once(parser, loc,
                     "a declared material keeps only its texture: its interior is dropped "
                     "(declaring materials is not fully supported yet)");
  }
  return material.texture.value_or(parser.defaults().texture);
}

// `default { ... }` written without its `#`, as scenes for older POV-Ray versions do.
void parse_old_default(Parser& parser) {
  items::Block block(parser, "default", items::take_keyword(parser));
  static constexpr std::string_view kWords[] = {"texture", "pigment", "finish", "normal"};
  scene::Texture& defaults = parser.defaults().texture;
  while (block.more()) {
    if (items::at_word(parser, "texture")) {
      defaults = items::parse_texture(parser, defaults);
    } else if (items::at_word(parser, "pigment")) {
      defaults.pigment = items::parse_pigment(parser, defaults.pigment);
    } else if (items::at_word(parser, "finish")) {
      defaults.finish = items::parse_finish(parser, defaults.finish);
    } else if (items::at_word(parser, "normal")) {
      defaults.normal = items::parse_normal(parser, defaults.normal);
    } else {
      block.unexpected(kWords);
    }
  }
}

}  // namespace

bool parse_item(Parser& parser, Value& out) {
  using namespace items;
  out.loc = parser.peek().loc;
  const scene::Texture& defaults = parser.defaults().texture;
  if (at_unsupported_object(parser)) {
    out.data = parse_unsupported_object_as_empty(parser);
  } else if (at_object(parser)) {
    out.data = parse_object(parser);
  } else if (at_word(parser, "texture")) {
    // Not followed by a look for further layers (`texture { A } texture { B }`): looking
    // past the item would run a following #declare before this one is stored (the parser
    // core carries out directives as it reads); parse_statement takes the layers instead.
    set_item(out, parse_texture(parser, defaults));
  } else if (at_word(parser, "material")) {
    set_item(out, parse_declared_material(parser));
  } else if (at_word(parser, "sky_sphere")) {
    set_item(out, parse_sky_sphere(parser));
  } else if (at_any_word(parser, kUndeclarable)) {
    parser.fail_here("a " + parser.peek().text +
                     " cannot be declared yet: write it where "
                     "it is used");
  } else if (at_word(parser, "pigment")) {
    set_item(out, parse_pigment(parser, defaults.pigment));
  } else if (at_word(parser, "finish")) {
    set_item(out, parse_finish(parser, defaults.finish));
  } else if (at_word(parser, "normal")) {
    set_item(out, parse_normal(parser, defaults.normal));
  } else if (at_word(parser, "interior")) {
    set_item(out, parse_interior(parser, scene::Interior{}));
  } else if (at_word(parser, "color_map") || at_word(parser, "colour_map")) {
    set_item(out, parse_color_map(parser));
  } else if (at_word(parser, "transform")) {
    set_item(out, parse_transform_block(parser));
  } else if (at_word(parser, "camera")) {
    set_item(out, parse_camera(parser));
  } else if (at_word(parser, "light_source")) {
    set_item(out, parse_light(parser));
  } else {
    return false;
  }
  return true;
}

scene::ObjectPtr items::with_default_texture(Parser& parser, scene::ObjectPtr object) {
  if (object->texture) return object;
  auto textured = std::make_shared<scene::Object>(*object);
  textured->texture = std::make_shared<const scene::Texture>(parser.defaults().texture);
  return textured;
}

const scene::UnsupportedObject* find_unsupported(const scene::Object& object) {
  if (object.unsupported) return &*object.unsupported;
  const auto in = [](const scene::ObjectPtr& child) {
    return child ? find_unsupported(*child) : nullptr;
  };
  if (const auto* csg = std::get_if<scene::Csg>(&object.shape)) {
    for (const scene::ObjectPtr& child : csg->children) {
      if (const auto* found = in(child)) return found;
    }
  }
  for (const scene::ObjectPtr& clip : object.clipped_by) {
    if (const auto* found = in(clip)) return found;
  }
  return in(object.bounded_by);
}

scene::ObjectPtr items::placed_object(Parser& parser, scene::ObjectPtr object,
                                      const SourceLoc& at) {
  if (const scene::UnsupportedObject* unsupported = find_unsupported(*object)) {
    parser.fail(at, "'" + unsupported->kind +
                        "' objects are not supported yet by convray: this object uses the one "
                        "declared at " +
                        unsupported->declared_at.str());
  }
  return with_default_texture(parser, std::move(object));
}

void parse_statement(Parser& parser, scene::Scene& scene) {
  using namespace items;
  if (at_word(parser, "object")) {
    parse_top_level_object(parser, scene);
  } else if (at_object(parser)) {
    const SourceLoc loc = parser.peek().loc;
    scene.objects.push_back(placed_object(parser, parse_object(parser), loc));
    add_csg_lights(*scene.objects.back(), scene);
  } else if (at_word(parser, "camera")) {
    scene.camera = parse_camera(parser);
  } else if (at_word(parser, "light_source")) {
    scene.lights.push_back(parse_light(parser));
  } else if (at_word(parser, "background")) {
    scene.background = parse_background(parser);
  } else if (at_word(parser, "fog")) {
    scene.fogs.push_back(parse_fog(parser));
  } else if (at_word(parser, "sky_sphere")) {
    scene.sky_sphere = parse_sky_sphere(parser);
  } else if (at_word(parser, "global_settings")) {
    parse_global_settings(parser, scene.settings);
  } else if (at_word(parser, "default")) {
    parse_old_default(parser);
  } else if (at_word(parser, "texture")) {
    // Only a further layer of a texture declared just before can be here.
    if (!parser.texture_declared_just_before()) {
      parser.fail_here("a texture at the top level must follow a declared texture, as its "
                       "next layer (#declare T = texture { ... } texture { ... })");
    }
    std::optional<scene::Texture> layer;
    const std::optional<UnsupportedItem> unsupported = parser.parse_or_skip_unsupported(
        [&] { layer = parse_texture(parser, parser.defaults().texture); });
    parser.add_declared_texture_layer(layer, unsupported);
  } else if (at_word(parser, "rainbow") || at_word(parser, "media")) {
    const std::string word = parser.peek().text;
    const SourceLoc loc = take_keyword(parser);
    skip_braced(parser, word, loc);
    items::warn_once(parser, loc, "'" + word + "' is ignored by convray");
  } else {
    fail_unknown_statement(parser);
  }
}

}  // namespace convray::sdl
