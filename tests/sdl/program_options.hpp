#pragma once
// The parse options the program (app/) gives every scene, for the parser's tests: the
// renderer's pigments, patterns and noise, which user functions read (scene/color_sources.hpp).
#include "render/function_sources.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl {

inline ParseOptions program_options() {
  ParseOptions options;
  options.color_sources = render::renderer_color_sources();
  return options;
}

}  // namespace convray::sdl
