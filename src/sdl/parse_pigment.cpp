// pigment { [P_ID] color C | PATTERN [colors] [color_map {...}] [pattern modifiers] } and
// color_map { [v color] ... } (also colour_map, and color_map { CM_ID }).
#include <algorithm>

#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

// POV-Ray's checker colours when the scene gives none.
const scene::Color kCheckerDefaults[2] = {{Vec3(0.0, 0.0, 1.0)}, {Vec3(0.0, 1.0, 0.0)}};

void parse_checker_colors(Parser& parser, scene::Pigment& pigment) {
  pigment.block_colors = {kCheckerDefaults[0], kCheckerDefaults[1]};
  for (size_t k = 0; k < 2; ++k) {
    if (k > 0) parser.accept_comma();
    if (!at_color_start(parser)) break;
    pigment.block_colors[k] = color_param(parser);
  }
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

scene::Pigment parse_pigment(Parser& parser, const scene::Pigment& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "pigment", loc);
  scene::Pigment pigment = start;
  if (auto declared = declared_pigment_or_color(parser)) pigment = *declared;
  static constexpr std::string_view kMapWords[] = {"color_map", "colour_map", "color"};
  while (block.more()) {
    if (auto pattern = parse_pattern_keyword(parser, pigment.space)) {
      // A new pattern replaces the colours of the one it is given over.
      pigment.color_map.clear();
      pigment.block_colors.clear();
      if (*pattern == scene::Pattern::checker) parse_checker_colors(parser, pigment);
    } else if (at_word(parser, "color_map") || at_word(parser, "colour_map")) {
      pigment.color_map = parse_color_map(parser);
    } else if (parse_pattern_modifier(parser, pigment.space)) {
      continue;
    } else if (at_color_start(parser)) {
      pigment.color = color_param(parser);
      pigment.space.pattern = scene::Pattern::solid;
      pigment.color_map.clear();
      pigment.block_colors.clear();
    } else {
      block.unexpected(pattern_words(), kMapWords, pattern_modifier_words());
    }
  }
  return pigment;
}

}  // namespace convray::sdl::items
