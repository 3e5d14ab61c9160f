// texture { [T_ID] pigment {} finish {} normal {} [transforms] } and
// interior { [I_ID] ior f ... }.
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

// `checker texture { A } [,] texture { B }`: the texture becomes those blocks.
void parse_texture_blocks(Parser& parser, scene::Texture& texture) {
  auto blocks = std::make_shared<scene::TextureBlocks>();
  parse_pattern_keyword(parser, blocks->space);
  for (int k = 0; k < 2 && at_word(parser, "texture"); ++k) {
    blocks->textures.push_back(
        std::make_shared<const scene::Texture>(parse_texture(parser, parser.defaults().texture)));
    parser.accept_comma();
  }
  texture = scene::Texture{};
  texture.blocks = std::move(blocks);
}

}  // namespace

scene::Texture parse_texture(Parser& parser, const scene::Texture& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "texture", loc);
  scene::Texture texture = start;
  if (auto declared = accept_declared<scene::Texture>(parser, "a texture")) texture = *declared;
  static constexpr std::string_view kWords[] = {"pigment", "finish", "normal", "translate",
                                                "rotate",  "scale",  "matrix", "transform"};
  while (block.more()) {
    if (texture.blocks && (at_word(parser, "pigment") || at_word(parser, "finish") ||
                           at_word(parser, "normal"))) {
      parser.fail_here("a texture made of blocks (texture { checker texture {...} texture "
                       "{...} }) takes no " + parser.peek().text + " of its own");
    }
    if (at_word(parser, "checker")) {
      parse_texture_blocks(parser, texture);
    } else if (at_word(parser, "pigment")) {
      texture.pigment = parse_pigment(parser, texture.pigment);
    } else if (at_word(parser, "finish")) {
      texture.finish = parse_finish(parser, texture.finish);
    } else if (at_word(parser, "normal")) {
      texture.normal = parse_normal(parser, texture.normal);
    } else if (auto transform = parse_transform_modifier(parser)) {
      move_texture(texture, *transform);
    } else if (texture.blocks && at_any_word(parser, pattern_modifier_words())) {
      // Turbulence and the like bend the blocks' pattern.
      scene::TextureBlocks bent = *texture.blocks;
      parse_pattern_modifier(parser, bent.space);
      texture.blocks = std::make_shared<const scene::TextureBlocks>(std::move(bent));
    } else if (at_any_word(parser, pattern_words()) ||
               at_any_word(parser, unsupported_pattern_words())) {
      parser.fail_unsupported_here("texture patterns and maps ('" + parser.peek().text +
                       "' in a texture) are not supported yet by convray");
    } else {
      block.unexpected(kWords);
    }
  }
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
    if (word == "media") {
      skip_braced(parser, word, item_loc);
    } else if (word == "fade_color" || word == "fade_colour") {
      color_param(parser);
    } else {
      float_param(parser, word);
    }
    warn_once(parser, item_loc, "'" + word + "' is ignored by convray");
  }
  return interior;
}

}  // namespace convray::sdl::items
