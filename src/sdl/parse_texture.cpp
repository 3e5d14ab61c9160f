// texture { [T_ID] pigment {} finish {} normal {} [transforms] } (or a texture pattern:
// parse_texture_map.cpp) and interior { [I_ID] ior f ... }.
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

// One item of a texture's body; false when the next token starts none.
bool parse_texture_item(Parser& parser, scene::Texture& texture) {
  if (texture.map && (at_word(parser, "pigment") || at_word(parser, "finish") ||
                      at_word(parser, "normal"))) {
    parser.fail_here("a texture made of a texture pattern (texture { checker texture {...} "
                     "texture {...} }, texture_map) takes no " + parser.peek().text +
                     " of its own");
  }
  if (at_word(parser, "pigment")) {
    texture.pigment = parse_pigment(parser, texture.pigment);
  } else if (at_word(parser, "finish")) {
    texture.finish = parse_finish(parser, texture.finish);
  } else if (at_word(parser, "normal")) {
    texture.normal = parse_normal(parser, texture.normal);
  } else if (auto transform = parse_transform_modifier(parser)) {
    move_texture(texture, *transform);
  } else if (texture.map && at_word(parser, "warp")) {
    warp_texture(texture, parse_warp(parser));
  } else if (texture.map && at_any_word(parser, pattern_modifier_words())) {
    // Turbulence and the like bend the texture pattern.
    scene::TextureMap bent = *texture.map;
    parse_pattern_modifier(parser, bent.space);
    texture.map = std::make_shared<const scene::TextureMap>(std::move(bent));
  } else if (!parse_texture_pattern(parser, texture)) {
    return false;
  }
  return true;
}

}  // namespace

scene::Texture parse_texture(Parser& parser, const scene::Texture& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "texture", loc);
  scene::Texture texture = start;
  if (auto declared = accept_declared<scene::Texture>(parser, "a texture")) texture = *declared;
  static constexpr std::string_view kWords[] = {"pigment", "finish",  "normal",      "translate",
                                                "rotate",  "scale",   "matrix",      "transform",
                                                "average", "tiles",   "texture_map"};
  while (block.more()) {
    if (!parse_texture_item(parser, texture)) block.unexpected(kWords, pattern_words());
  }
  check_texture_pattern(parser, texture, loc);
  return texture;
}

scene::Texture parse_texture_body(Parser& parser, const std::string& closing) {
  const SourceLoc loc = parser.peek().loc;
  scene::Texture texture = parser.defaults().texture;
  if (auto declared = accept_declared<scene::Texture>(parser, "a texture")) texture = *declared;
  while (!parser.at(closing)) {
    if (!parse_texture_item(parser, texture)) {
      parser.fail_here("unexpected '" + parser.peek().text + "' in a texture");
    }
  }
  check_texture_pattern(parser, texture, loc);
  return texture;
}

ParsedMaterial parse_material(Parser& parser) {
  static constexpr std::string_view kWords[] = {"texture", "interior", "translate", "rotate",
                                                "scale",   "matrix",   "transform"};
  Block block(parser, "material", take_keyword(parser));
  ParsedMaterial material;
  material.texture = accept_declared<scene::Texture>(parser, "a texture");
  while (block.more()) {
    if (at_word(parser, "texture")) {
      material.texture = parse_texture(parser, parser.defaults().texture);
    } else if (at_word(parser, "interior")) {
      material.interior = parse_interior(parser, material.interior.value_or(scene::Interior{}));
    } else if (auto transform = parse_transform_modifier(parser)) {
      if (material.texture) move_texture(*material.texture, *transform);
    } else {
      block.unexpected(kWords);
    }
  }
  return material;
}

scene::Interior parse_interior(Parser& parser, const scene::Interior& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "interior", loc);
  scene::Interior interior = start;
  if (auto declared = accept_declared<scene::Interior>(parser, "an interior")) interior = *declared;
  static constexpr std::string_view kWords[] = {
      "ior",           "caustics",   "dispersion", "dispersion_samples",
      "fade_distance", "fade_power", "fade_color", "fade_colour",
      "media"};
  while (block.more()) {
    if (!at_any_word(parser, kWords)) block.unexpected(kWords);
    const std::string word = parser.peek().text;
    const SourceLoc item_loc = take_keyword(parser);
    if (word == "ior") {
      interior.ior = float_param(parser, "ior");
      if (!(interior.ior > 0.0)) {
        parser.fail(item_loc, "ior must be positive, found " + number_text(interior.ior));
      }
      continue;
    }
    if (word == "fade_distance") {
      interior.fade_distance = float_param(parser, word);
      continue;
    }
    if (word == "fade_power") {
      interior.fade_power = float_param(parser, word);
      continue;
    }
    if (word == "fade_color" || word == "fade_colour") {
      interior.fade_color = color_param(parser).rgb;
      continue;
    }
    if (word == "media") {
      skip_braced(parser, word, item_loc);
    } else {
      float_param(parser, word);
    }
    warn_once(parser, item_loc, "'" + word + "' is ignored by convray");
  }
  return interior;
}

}  // namespace convray::sdl::items
