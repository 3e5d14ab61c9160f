#pragma once
// What user functions read of pigments, patterns and the patterns' noise
// (`function { pigment { P } }`, `function { pattern { P } }`, functions.inc's f_noise3d):
// only the renderer evaluates those, and the language does not link the renderer. The program
// (app/) hands the parser the renderer's (render/function_sources.hpp) in
// sdl::ParseOptions::color_sources, as it does for sdl::ObjectQueries; without one, such a
// function is unsupported where it is called.
#include <memory>

#include "scene/function.hpp"
#include "scene/texture.hpp"

namespace convray::scene {

class ColorSources {
 public:
  virtual ~ColorSources() = default;
  virtual std::shared_ptr<const ColorSource> pigment(Pigment pigment) const = 0;
  virtual std::shared_ptr<const ColorSource> pattern(PatternSpace space) const = 0;
  virtual std::shared_ptr<const ColorSource> noise() const = 0;
};

}  // namespace convray::scene
