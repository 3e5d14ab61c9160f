// finish { [F_ID] ambient, diffuse, brilliance, phong, phong_size, specular, roughness,
//          reflection, metallic, emission, ... }
#include <algorithm>

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

namespace {

// The items of `reflection { ... }` after its values.
void parse_reflection_block(Parser& parser, Block& block, scene::Finish& finish) {
  static constexpr std::string_view kWords[] = {"fresnel", "falloff", "exponent", "metallic"};
  while (block.more()) {
    const SourceLoc item_loc = parser.peek().loc;
    if (accept_word(parser, "fresnel")) {
      finish.fresnel = optional_bool(parser);
    } else if (accept_word(parser, "falloff")) {
      finish.reflection_falloff = float_param(parser, "falloff");
    } else if (accept_word(parser, "exponent")) {
      float_param(parser, "exponent");
      warn_once(parser, item_loc, "reflection exponent is ignored");
    } else if (accept_word(parser, "metallic")) {
      finish.reflection_metallic = at_float_start(parser) ? float_param(parser, "metallic") : 1.0;
    } else {
      block.unexpected(kWords);
    }
  }
}

constexpr std::string_view kFinishWords[] = {
    "ambient",   "diffuse",    "brilliance", "phong",    "phong_size",      "specular",
    "roughness", "reflection", "metallic",   "emission", "conserve_energy", "reflection_exponent",
    "crand",     "irid",       "subsurface", "fresnel"};

// `diffuse`, `phong` and `specular` accept POV-Ray 3.7's `albedo` before their value.
double parse_coefficient(Parser& parser, const std::string& word) {
  if (at_word(parser, "albedo")) {
    warn_once(parser, take_keyword(parser),
              "albedo is ignored: the value after it is used as the plain " + word);
  }
  return float_param(parser, word);
}

// `reflection f`, `reflection rgb <...>`, `reflection min, max` or
// `reflection { [min,] max [fresnel] [falloff f] [exponent f] [metallic [f]] }`: a minimum
// or fresnel makes the reflection vary with the angle (render/variable_reflection.hpp).
void parse_reflection(Parser& parser, const SourceLoc& loc, scene::Finish& finish) {
  const bool block_form = parser.at("{");
  std::optional<Block> block;
  if (block_form) block.emplace(parser, "reflection", loc);
  Vec3 reflection = rgb_param(parser, "reflection");
  finish.variable_reflection = false;
  finish.fresnel = false;
  finish.reflection_metallic = 0.0;
  finish.reflection_falloff = 1.0;
  // The maximum follows the minimum after a comma, or in the block form without one
  // (`reflection { 0.0 1.0 fresnel on }`), as POV-Ray reads it.
  bool has_minimum = false;
  if (parser.accept(",") || (block_form && (at_float_start(parser) || parser.at("rgb")))) {
    finish.reflection_min = reflection;
    reflection = rgb_param(parser, "reflection");
    has_minimum = true;
  }
  finish.reflection = reflection;
  if (block_form) parse_reflection_block(parser, *block, finish);
  // Fresnel with one value varies from 0 (measured with povray); without fresnel one value
  // is a constant reflection.
  if (finish.fresnel && !has_minimum) finish.reflection_min = Vec3(0.0);
  finish.variable_reflection = has_minimum || finish.fresnel;
}

// The finish items convray parses but does not render.
void parse_ignored_finish_item(Parser& parser, const std::string& word, const SourceLoc& loc) {
  if (word == "irid" || word == "subsurface") {
    skip_braced(parser, word, loc);
  } else if (word == "fresnel") {
    optional_bool(parser);
  } else {
    float_param(parser, word);
  }
  warn_once(parser, loc, "'" + word + "' is ignored by convray");
}

}  // namespace

scene::Finish parse_finish(Parser& parser, const scene::Finish& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "finish", loc);
  scene::Finish finish = start;
  if (auto declared = accept_declared<scene::Finish>(parser, "a finish")) finish = *declared;
  while (block.more()) {
    if (!at_any_word(parser, kFinishWords)) block.unexpected(kFinishWords);
    const std::string word = parser.peek().text;
    const SourceLoc item_loc = take_keyword(parser);
    if (word == "ambient") {
      finish.ambient = rgb_param(parser, "ambient");
    } else if (word == "emission") {
      finish.emission = rgb_param(parser, "emission");
    } else if (word == "diffuse") {
      finish.diffuse = parse_coefficient(parser, word);
      if (parser.accept(",")) {
        float_param(parser, "diffuse's back-side value");
        warn_once(parser, item_loc, "diffuse's back-side illumination is ignored");
      }
    } else if (word == "phong") {
      finish.phong = parse_coefficient(parser, word);
    } else if (word == "specular") {
      finish.specular = parse_coefficient(parser, word);
    } else if (word == "brilliance") {
      finish.brilliance = float_param(parser, word);
    } else if (word == "phong_size") {
      finish.phong_size = float_param(parser, word);
    } else if (word == "roughness") {
      finish.roughness = float_param(parser, word);
      if (!(finish.roughness > 0.0)) {
        parser.fail(item_loc, "roughness must be positive, found " + number_text(finish.roughness));
      }
    } else if (word == "metallic") {
      finish.metallic = at_float_start(parser) ? float_param(parser, word) : 1.0;
    } else if (word == "reflection") {
      parse_reflection(parser, item_loc, finish);
    } else if (word == "conserve_energy") {
      finish.conserve_energy = optional_bool(parser);
    } else {
      parse_ignored_finish_item(parser, word, item_loc);
    }
  }
  return finish;
}

}  // namespace convray::sdl::items
