#pragma once
// What pigments and normals share: the pattern keywords (`checker`, `gradient <axis>`,
// `bumps`, ...) and the pattern modifiers (turbulence, octaves, omega, lambda, frequency,
// phase, transforms).
#include <optional>

#include "scene/texture.hpp"
#include "sdl/item_helpers.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::items {

// For "did you mean".
Keywords pattern_words();
Keywords pattern_modifier_words();
// POV-Ray's patterns and maps that convray does not have yet (brick, image_map, ...).
Keywords unsupported_pattern_words();

// If the next token names a pattern, consumes it (and gradient's axis) and returns it; fails
// on POV-Ray patterns convray does not have yet (brick, hexagon, image_map, ...).
std::optional<scene::Pattern> parse_pattern_keyword(Parser& parser, scene::PatternSpace& space);

// Parses one pattern modifier into `space` if the next token is one.
bool parse_pattern_modifier(Parser& parser, scene::PatternSpace& space);

// `turbulence`, `octaves`, `omega` or `lambda` (already consumed as `word`) and its value.
void parse_turbulence_setting(Parser& parser, const std::string& word,
                              scene::Turbulence& turbulence);

// `warp { ... }` at the `warp` keyword (sdl/parse_warp.cpp); its `inner` is left for the caller.
scene::Warp parse_warp(Parser& parser);

// Whether the next token can start a colour (a colour keyword, `<`, a number, a declared
// colour or float).
bool at_color_start(Parser& parser);

}  // namespace convray::sdl::items
