// Texture patterns: whole textures picked by a pattern (scene::TextureMap).
//   checker texture { A } [,] texture { B }      blocks
//   tiles { texture { A } ... tile2 texture { B } ... }   checker blocks
//   PATTERN [modifiers] texture_map { [v T] ... } a map: T is what a texture { } holds
//   average texture_map { [w T] ... }             every texture, weighted by w
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

using Kind = scene::TextureMap::Kind;

// The textures of one tile up to `tile2` or the end of the block, layered as on an object (a
// later one lies on top).
scene::TexturePtr parse_tile(Parser& parser, Block& block, const SourceLoc& loc) {
  std::optional<scene::Texture> layers;
  while (!at_word(parser, "tile2") && block.more()) {
    if (!at_word(parser, "texture")) {
      parser.fail_here("expected a texture { } in tiles, found '" + parser.peek().text + "'");
    }
    scene::Texture layer = parse_texture(parser, parser.defaults().texture);
    layers = layers ? scene::layered_on(*layers, std::move(layer)) : std::move(layer);
  }
  if (!layers) parser.fail(loc, "a tile of tiles { } holds no texture");
  return std::make_shared<const scene::Texture>(std::move(*layers));
}

// `tiles { texture { A } ... tile2 texture { B } ... }`: checker blocks of two textures, A
// in the blocks where checker puts its second (measured: tiles { A tile2 B } draws as
// checker texture { B } texture { A }); without tile2 the default texture.
void parse_tiles(Parser& parser, scene::TextureMap& map) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "tiles", loc);
  map.space.pattern = scene::Pattern::checker;
  const scene::TexturePtr first = parse_tile(parser, block, loc);
  const scene::TexturePtr second =
      accept_word(parser, "tile2") ? parse_tile(parser, block, loc) : nullptr;
  map.textures = {second, first};
}

// The textures of a map: entries in the pattern's space (the transforms written before the
// map move them too, as they move a pigment_map's pigments).
void parse_texture_map_entries(Parser& parser, scene::TextureMap& map) {
  Block block(parser, "texture_map", take_keyword(parser));
  map.values.clear();
  map.textures.clear();
  while (block.more()) {
    parser.expect("[", "texture_map");
    const SourceLoc loc = parser.peek().loc;
    // An average's weight may be left out: 1.
    const bool weighted = map.kind != Kind::average || at_float_start(parser);
    const double value = weighted ? float_param(parser, "the texture_map entry's value") : 1.0;
    parser.accept_comma();
    scene::Texture entry = parse_texture_body(parser, "]");
    parser.expect("]", "texture_map entry");
    if (map.kind == Kind::map && !map.values.empty() && value < map.values.back()) {
      // POV-Ray keeps the list as written; ours must ascend.
      parser.fail(loc, "texture_map entries must be in ascending order of value");
    }
    if (map.kind == Kind::average && !(value >= 0.0)) {
      parser.fail(loc, "an average's weight must not be negative, found " + number_text(value));
    }
    place_in_space(entry, map.space);
    map.values.push_back(value);
    map.textures.push_back(std::make_shared<const scene::Texture>(std::move(entry)));
  }
  if (map.textures.empty()) parser.fail(block.loc(), "texture_map has no entries");
}

// A block pattern followed by up to two textures (three for hexagon).
void parse_block_textures(Parser& parser, scene::TextureMap& map) {
  for (int k = 0; k < scene::block_count(map.space.pattern) && at_word(parser, "texture"); ++k) {
    map.textures.push_back(
        std::make_shared<const scene::Texture>(parse_texture(parser, parser.defaults().texture)));
    parser.accept_comma();
  }
}

// A new pattern of textures replaces whatever the texture had.
void start_map(scene::Texture& texture, scene::TextureMap map) {
  texture = scene::Texture{};
  texture.map = std::make_shared<const scene::TextureMap>(std::move(map));
}

}  // namespace

bool parse_texture_pattern(Parser& parser, scene::Texture& texture) {
  scene::TextureMap map;
  if (at_word(parser, "texture_map")) {
    if (!texture.map) parser.fail_here("a texture_map needs a pattern before it");
    map = *texture.map;
    parse_texture_map_entries(parser, map);
    texture.map = std::make_shared<const scene::TextureMap>(std::move(map));
    return true;
  }
  if (at_word(parser, "tiles")) {
    parse_tiles(parser, map);
  } else if (accept_word(parser, "average")) {
    map.kind = Kind::average;
  } else if (auto pattern = parse_pattern_keyword(parser, map.space)) {
    map.kind = scene::is_block_pattern(*pattern) ? Kind::blocks : Kind::map;
    if (map.kind == Kind::blocks) parse_block_textures(parser, map);
  } else {
    return false;
  }
  start_map(texture, std::move(map));
  return true;
}

void check_texture_pattern(Parser& parser, const scene::Texture& texture,
                           const SourceLoc& loc) {
  if (texture.map && texture.map->textures.empty()) {
    parser.fail(loc, "this texture's pattern picks no textures: give it a texture_map { "
                     "[value texture] ... }");
  }
}

}  // namespace convray::sdl::items
