#pragma once
// What user functions read from the renderer (scene/function.hpp's ColorSource):
// `function { pigment { P } }`, the pigment's colour, and `function { pattern { P } }`, the
// pattern's value (turbulence, frequency, phase and wave applied) as a grey.
#include <memory>

#include "scene/color_sources.hpp"
#include "scene/function.hpp"
#include "scene/texture.hpp"

namespace convray::render {

std::shared_ptr<const scene::ColorSource> pigment_source(scene::Pigment pigment);
std::shared_ptr<const scene::ColorSource> pattern_source(scene::PatternSpace space);
// functions.inc's f_noise3d (internal(76)): the patterns' noise (render/noise.hpp), in [0, 1],
// as a grey.
std::shared_ptr<const scene::ColorSource> noise_source();

// The three above, for the parser (sdl::ParseOptions::color_sources).
std::shared_ptr<const scene::ColorSources> renderer_color_sources();

}  // namespace convray::render
