#include "sdl/pattern_items.hpp"

#include "sdl/item_parsers.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace convray::sdl::items {

namespace {

struct PatternKeyword {
  std::string_view word;
  scene::Pattern pattern;
};

constexpr PatternKeyword kPatterns[] = {
    {"checker", scene::Pattern::checker}, {"gradient", scene::Pattern::gradient},
    {"marble", scene::Pattern::marble},   {"wood", scene::Pattern::wood},
    {"granite", scene::Pattern::granite}, {"agate", scene::Pattern::agate},
    {"bozo", scene::Pattern::bozo},       {"radial", scene::Pattern::radial},
    {"onion", scene::Pattern::onion},     {"leopard", scene::Pattern::leopard},
    {"spotted", scene::Pattern::spotted}, {"ripples", scene::Pattern::ripples},
    {"waves", scene::Pattern::waves},     {"wrinkles", scene::Pattern::wrinkles},
    {"bumps", scene::Pattern::bumps},     {"dents", scene::Pattern::dents},
    {"planar", scene::Pattern::planar},   {"spherical", scene::Pattern::spherical},
    {"cylindrical", scene::Pattern::cylindrical}, {"boxed", scene::Pattern::boxed},
    {"spiral1", scene::Pattern::spiral1}, {"mandel", scene::Pattern::mandel},
    {"brick", scene::Pattern::brick},     {"hexagon", scene::Pattern::hexagon},
    {"quilted", scene::Pattern::quilted},
};

constexpr std::string_view kPatternNames[] = {
    "checker", "gradient", "marble",  "wood",    "granite", "agate",    "bozo",  "radial",
    "onion",   "leopard",  "spotted", "ripples", "waves",   "wrinkles", "bumps", "dents",
    "planar",  "spherical", "cylindrical", "boxed", "spiral1", "mandel",  "brick", "hexagon",
    "quilted"};

// POV-Ray patterns we know by name, so that they get "not supported yet" rather than
// "unexpected".
constexpr std::string_view kUnsupportedPatterns[] = {
    "crackle",      "cells",         "spiral2",
    "julia",        "bump_map",
    "object",     "density_file", "facets",
    "average",      "tiling",        "pavement",    "square",
    "triangular", "slope",        "aoi",          "image_pattern", "magnet",
    "normal_map", "slope_map",    "material_map", "texture_map",   "tiles",       "uv_mapping",
    "gradient_map"};

constexpr std::string_view kModifiers[] = {
    "turbulence",    "octaves",     "omega",        "lambda",     "frequency", "phase",
    "translate",     "rotate",      "scale",        "matrix",     "transform", "ramp_wave",
    "triangle_wave", "sine_wave",   "scallop_wave", "cubic_wave", "poly_wave", "noise_generator",
    "agate_turb",    "quick_color", "quick_colour", "brick_size", "mortar",    "warp",
    "control0",      "control1"};

}  // namespace

Keywords pattern_words() { return kPatternNames; }
Keywords pattern_modifier_words() { return kModifiers; }
Keywords unsupported_pattern_words() { return kUnsupportedPatterns; }

std::optional<scene::Pattern> parse_pattern_keyword(Parser& parser, scene::PatternSpace& space) {
  if (at_any_word(parser, kUnsupportedPatterns)) {
    parser.fail_unsupported_here("'" + parser.peek().text + "' is not supported yet by convray");
  }
  if (at_word(parser, "function")) {
    space.pattern = scene::Pattern::function;
    space.function = parser.parse_function_block();
    return space.pattern;
  }
  if (at_word(parser, "pigment_pattern")) {
    space.pattern = scene::Pattern::function;
    space.function = parser.parse_pigment_pattern();
    return space.pattern;
  }
  for (const PatternKeyword& keyword : kPatterns) {
    if (!at_word(parser, keyword.word)) continue;
    parser.next();
    space.pattern = keyword.pattern;
    if (keyword.pattern == scene::Pattern::gradient) {
      space.gradient_axis = vector_param(parser, "the gradient's axis");
      if (space.gradient_axis == Vec3(0.0)) {
        parser.fail_here("the gradient's axis must not be <0, 0, 0>");
      }
    }
    if (keyword.pattern == scene::Pattern::spiral1) {
      const SourceLoc loc = parser.peek().loc;
      space.arms = float_param(parser, "the number of spiral1's arms");
      if (!std::isfinite(space.arms)) parser.fail(loc, "spiral1's number of arms must be finite");
    }
    if (keyword.pattern == scene::Pattern::mandel) {
      const SourceLoc loc = parser.peek().loc;
      space.iterations = int_param(parser, "mandel's number of iterations");
      if (space.iterations < 1) {
        parser.fail(loc, "mandel needs at least 1 iteration, found " +
                             std::to_string(space.iterations));
      }
    }
    return keyword.pattern;
  }
  return std::nullopt;
}

void parse_turbulence_setting(Parser& parser, const std::string& word,
                              scene::Turbulence& turbulence) {
  if (word == "turbulence") {
    turbulence.amount = vector_param(parser, "turbulence");
  } else if (word == "octaves") {
    const SourceLoc loc = parser.peek().loc;
    turbulence.octaves = int_param(parser, "octaves");
    if (turbulence.octaves < 1 || turbulence.octaves > 10) {
      // POV-Ray's limits for octaves.
      parser.fail(loc, "octaves must lie in 1..10, found " + std::to_string(turbulence.octaves));
    }
  } else if (word == "omega") {
    turbulence.omega = float_param(parser, "omega");
  } else {
    turbulence.lambda = float_param(parser, "lambda");
  }
}

namespace {

// Generators 1 and 2 are POV-Ray's own noise (render/noise.hpp); 3, Perlin's improved noise,
// is not matched yet and is drawn with 2, which the warning says.
void parse_noise_generator(Parser& parser, const SourceLoc& loc, scene::PatternSpace& space) {
  const int generator = int_param(parser, "noise_generator");
  if (generator < 1 || generator > 3) {
    parser.fail(loc, "noise_generator must be 1, 2 or 3, found " + std::to_string(generator));
  }
  space.noise_generator = generator == 1 ? 1 : 2;
  if (generator == 3) {
    warn_once(parser, loc,
              "noise_generator 3 (Perlin's improved noise) is drawn with generator 2 by convray");
  }
}

}  // namespace

bool parse_pattern_modifier(Parser& parser, scene::PatternSpace& space) {
  if (auto transform = parse_transform_modifier(parser)) {
    space.transform = space.transform.then(*transform);
    return true;
  }
  if (!at_any_word(parser, kModifiers)) return false;
  if (at_word(parser, "warp")) {
    // The transforms so far go with the warp; those after it start afresh. (Pigments and
    // textures with maps warp their entries too: parse_pigment.cpp, parse_texture.cpp.)
    append_warp(space, parse_warp(parser));
    return true;
  }
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  if (word == "turbulence" || word == "octaves" || word == "omega" || word == "lambda") {
    parse_turbulence_setting(parser, word, space.turbulence);
  } else if (word == "frequency") {
    space.frequency = float_param(parser, "frequency");
  } else if (word == "phase") {
    space.phase = float_param(parser, "phase");
  } else if (word == "ramp_wave") {
    space.wave = scene::Wave::ramp;
  } else if (word == "triangle_wave") {
    space.wave = scene::Wave::triangle;
  } else if (word == "sine_wave") {
    space.wave = scene::Wave::sine;
  } else if (word == "scallop_wave") {
    space.wave = scene::Wave::scallop;
  } else if (word == "cubic_wave") {
    space.wave = scene::Wave::cubic;
  } else if (word == "poly_wave") {
    space.wave = scene::Wave::poly;
    space.wave_exponent = at_float_start(parser) ? float_param(parser, "poly_wave") : 1.0;
  } else if (word == "brick_size") {
    // POV-Ray takes these whatever the pattern; only brick uses them.
    space.brick_size = vector_param(parser, "brick_size");
    if (!(space.brick_size.x > 0.0 && space.brick_size.y > 0.0 && space.brick_size.z > 0.0)) {
      parser.fail(loc, "brick_size must be positive along every axis");
    }
  } else if (word == "control0") {
    space.control0 = float_param(parser, "control0");  // quilted's; others ignore it
  } else if (word == "control1") {
    space.control1 = float_param(parser, "control1");
  } else if (word == "mortar") {
    space.mortar = float_param(parser, "mortar");
  } else if (word == "quick_color" || word == "quick_colour") {
    color_param(parser);  // a preview colour: irrelevant to a full render
  } else if (word == "agate_turb") {
    space.agate_turb = float_param(parser, "agate_turb");
  } else {
    parse_noise_generator(parser, loc, space);
  }
  return true;
}

bool at_color_start(Parser& parser) {
  static constexpr std::string_view kColorWords[] = {
      "color",  "colour", "rgb",   "rgbf", "rgbt",   "rgbft",    "srgb", "srgbf", "srgbt",
      "srgbft", "red",    "green", "blue", "filter", "transmit", "gray", "grey"};
  if (at_any_word(parser, kColorWords)) return true;
  const Token& token = parser.peek();
  if (token.kind == Token::Kind::number) return true;
  if (token.kind == Token::Kind::symbol) return token.text == "<" || token.text == "(";
  if (const Value* declared = parser.peek_declared()) {
    return declared->get<Vector>() || declared->get<double>();
  }
  return false;
}

}  // namespace convray::sdl::items
