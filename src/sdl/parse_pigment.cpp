// pigment { [P_ID] color C | PATTERN [colors] [color_map {...}] [pattern modifiers] } and
// color_map { [v color] ... } (also colour_map, and color_map { CM_ID }).
#include <algorithm>

#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

// A block pattern's colours: `checker [COLOR [, COLOR]]` or `checker pigment { A } [,]
// pigment { B }` (the pigments become a pigment_map with the blocks' numbers as values);
// hexagon takes three. Colours not given keep POV-Ray's defaults; after pigments, blocks not
// given are black (as the povray binary draws `checker pigment { A }` and `hexagon pigment
// { A } pigment { B }`).
void parse_block_colors(Parser& parser, scene::Pigment& pigment) {
  pigment.block_colors = scene::default_block_colors(pigment.space.pattern);
  const size_t count = pigment.block_colors.size();
  std::vector<scene::PigmentMapEntry> pigments;
  size_t given = 0;
  for (; given < count; ++given) {
    if (given > 0) parser.accept_comma();
    if (at_word(parser, "pigment")) {
      pigments.push_back(
          {double(given), std::make_shared<const scene::Pigment>(parse_pigment(parser, {}))});
      continue;
    }
    if (!at_color_start(parser)) break;
    pigment.block_colors[given] = color_param(parser);
  }
  if (pigments.empty()) return;
  for (size_t k = 0; k < count; ++k) {
    if (k < pigments.size() && pigments[k].value == double(k)) continue;
    scene::Pigment solid;
    solid.color = k < given ? pigment.block_colors[k] : scene::Color{};
    pigments.insert(pigments.begin() + std::ptrdiff_t(k),
                    {double(k), std::make_shared<const scene::Pigment>(solid)});
  }
  pigments.resize(count);
  pigment.pigment_map = std::move(pigments);
}

// One `[value color]` entry, or the old `[v1, v2 color c1 color c2]` pair.
void parse_map_entry(Parser& parser, ColorMap& map) {
  parser.expect("[", "color_map");
  const double value = float_param(parser, "the color_map entry's value");
  parser.accept_comma();
  if (parser.peek().kind == Token::Kind::number) {
    const double second = float_param(parser, "the color_map entry's second value");
    parser.accept_comma();
    const scene::Color first_color = color_param(parser);
    parser.accept_comma();
    map.push_back({value, first_color});
    map.push_back({second, color_param(parser)});
  } else {
    map.push_back({value, color_param(parser)});
  }
  parser.expect("]", "color_map entry");
}

// A declared pigment, or an element of a declared array that holds a pigment or a colour
// (`pigment { Colors[i] }`); nothing when the next token names neither.
std::optional<scene::Pigment> declared_pigment_or_color(Parser& parser) {
  const Value* declared = parser.peek_declared();
  if (!declared || !declared->get<std::shared_ptr<Array>>()) {
    return accept_declared<scene::Pigment>(parser, "a pigment");
  }
  const SourceLoc loc = parser.peek().loc;
  const Value element = parser.parse_expression();
  if (const auto* pigment = element.get<std::shared_ptr<const scene::Pigment>>()) {
    return **pigment;
  }
  const Vector* color = element.get<Vector>();
  if (!color) parser.fail(loc, "expected a pigment or colour, found " + type_name(element));
  scene::Pigment solid;
  solid.color = color->as_color();
  return solid;
}

}  // namespace

ColorMap parse_color_map(Parser& parser) {
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, word, loc);
  if (auto declared = accept_declared<ColorMap>(parser, "a color_map")) {
    parser.expect("}", word);
    return *declared;
  }
  ColorMap map;
  while (block.more()) {
    if (!parser.at("[")) {
      parser.fail_here("expected '[' to start a " + word + " entry, found '" + parser.peek().text +
                       "'");
    }
    parse_map_entry(parser, map);
  }
  if (map.empty()) parser.fail(loc, word + " has no entries");
  return ascending_equivalent(map);
}

namespace {

std::vector<scene::PigmentMapEntry> parse_pigment_map(Parser& parser, bool average);

// One item of a pigment's body; false when the next token starts none.
bool parse_pigment_item(Parser& parser, scene::Pigment& pigment) {
  if (auto transform = parse_transform_modifier(parser)) {
    move_pigment(pigment, *transform);
  } else if (accept_word(parser, "average")) {
    // `average pigment_map { [w P] ... }`: the pigments mixed by their weights.
    pigment.space.pattern = scene::Pattern::average;
    pigment.color_map.clear();
    pigment.block_colors.clear();
    pigment.pigment_map.clear();
  } else if (at_word(parser, "image_map")) {
    pigment.image_map = parse_image_map(parser);
    pigment.space.pattern = scene::Pattern::image_map;
    pigment.color_map.clear();
    pigment.block_colors.clear();
    pigment.pigment_map.clear();
  } else if (auto pattern = parse_pattern_keyword(parser, pigment.space)) {
    // A new pattern replaces the colours of the one it is given over.
    pigment.color_map.clear();
    pigment.block_colors.clear();
    pigment.pigment_map.clear();
    if (scene::is_block_pattern(*pattern)) parse_block_colors(parser, pigment);
  } else if (at_word(parser, "color_map") || at_word(parser, "colour_map")) {
    pigment.color_map = parse_color_map(parser);
    pigment.pigment_map.clear();
  } else if (at_word(parser, "pigment_map")) {
    pigment.pigment_map =
        parse_pigment_map(parser, pigment.space.pattern == scene::Pattern::average);
    pigment.color_map.clear();
    // The entries live in the pattern's space: the transforms written before the map move
    // them too (those after it do, through move_pigment), as the povray binary draws them.
    for (scene::PigmentMapEntry& entry : pigment.pigment_map) {
      scene::Pigment moved = *entry.pigment;
      place_in_space(moved, pigment.space);
      entry.pigment = std::make_shared<const scene::Pigment>(std::move(moved));
    }
  } else if (at_word(parser, "warp")) {
    warp_pigment(pigment, parse_warp(parser));
  } else if (parse_pattern_modifier(parser, pigment.space)) {
    return true;
  } else if (at_color_start(parser)) {
    pigment.color = color_param(parser);
    pigment.space.pattern = scene::Pattern::solid;
    pigment.color_map.clear();
    pigment.block_colors.clear();
    pigment.pigment_map.clear();
  } else {
    return false;
  }
  return true;
}

// `pigment_map { [VALUE PIGMENT_BODY] ... }`: each entry is what a pigment { } holds (a
// colour, a declared pigment and its modifiers, a pattern ...). An average's values are
// weights: in any order, and 1 where left out.
std::vector<scene::PigmentMapEntry> parse_pigment_map(Parser& parser, bool average) {
  Block block(parser, "pigment_map", take_keyword(parser));
  std::vector<scene::PigmentMapEntry> map;
  while (block.more()) {
    parser.expect("[", "pigment_map");
    const SourceLoc loc = parser.peek().loc;
    const bool weighted = !average || at_float_start(parser);
    const double value = weighted ? float_param(parser, "the pigment_map entry's value") : 1.0;
    if (average && !(value >= 0.0)) {
      parser.fail(loc, "an average's weight must not be negative, found " + number_text(value));
    }
    parser.accept_comma();
    scene::Pigment entry;
    if (auto declared = declared_pigment_or_color(parser)) entry = *declared;
    while (!parser.at("]")) {
      if (!parse_pigment_item(parser, entry)) {
        parser.fail_here("unexpected '" + parser.peek().text + "' in a pigment_map entry");
      }
    }
    parser.expect("]", "pigment_map entry");
    if (!average && !map.empty() && value < map.back().value) {
      // Entries out of order: POV-Ray keeps the list as written; ours must ascend.
      parser.fail(block.loc(), "pigment_map entries must be in ascending order of value");
    }
    map.push_back({value, std::make_shared<const scene::Pigment>(std::move(entry))});
  }
  if (map.empty()) parser.fail(block.loc(), "pigment_map has no entries");
  return map;
}

}  // namespace

scene::Pigment parse_pigment(Parser& parser, const scene::Pigment& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "pigment", loc);
  scene::Pigment pigment = start;
  if (auto declared = declared_pigment_or_color(parser)) pigment = *declared;
  static constexpr std::string_view kMapWords[] = {"color_map", "colour_map", "pigment_map",
                                                   "color"};
  while (block.more()) {
    if (!parse_pigment_item(parser, pigment)) {
      block.unexpected(pattern_words(), kMapWords, pattern_modifier_words());
    }
  }
  if (pigment.space.pattern == scene::Pattern::average && pigment.pigment_map.empty()) {
    parser.fail(loc, "an average pigment needs a pigment_map { [weight pigment] ... }");
  }
  return pigment;
}

}  // namespace convray::sdl::items
