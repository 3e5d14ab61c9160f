#pragma once
// Whether a texture lets light through anywhere: what lets a shadow ray stop at any crossing
// of a surface without finding where it is (geometry's any-hit shadow queries).
#include "scene/texture.hpp"

namespace convray::scene {

// True only when every colour the texture can give, at every point, has filter = transmit = 0:
// each layer's pigment (its colour, colour map, block colours, pigment map, recursively) and
// every texture a texture map can pick. A pattern without its own colour map uses the
// renderer's default map, and a block pattern listing fewer colours its default colours; all
// of those are opaque (render/pigment.cpp, tests/render/texture_opacity_test.cpp). Image maps
// can carry transparency and are never taken as opaque. Conservative: false means "maybe not".
bool always_opaque(const Texture& texture);
bool always_opaque(const Pigment& pigment);

}  // namespace convray::scene
