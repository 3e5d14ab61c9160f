#pragma once
// How a transparent layer lets what lies below it through: colour = own * c + through * below,
// for a layer of colour c with filter f and transmit t. POV-Ray 3.7 has one rule for every
// layer; older scenes (the language version in effect when the parse ends below 3.7, or no
// #version, as for gamma) are drawn by the older versions' rules, which the 3.7 binary keeps
// for them. Measured on the binary (plain colours, 16-bit output, 3.0 to 3.7):
//   3.7, any layer:                   own 1 - f - t,          through f c + t
//   before 3.7, a sky_sphere's layer: own 1 - f - t,          through f + t (filter as transmit)
//   3.5 and 3.6, a texture's layer:   own 1 - f max(c) - t,   through f c + t
//   before 3.5, a texture layer over another layer of the same texture: own 1 - f - t,
//   through f + t; its bottom layer over the scene behind as 3.5 and 3.6.
#include "scene/color.hpp"
#include "util/math.hpp"

namespace convray::render {

enum class Layer {
  over_layer,  // a texture's layer over the next layer of the same layered texture
  over_scene,  // a texture's (bottom) layer over what the ray finds behind the surface
  sky,         // a sky_sphere pigment over the layers before it (the background last)
};

struct LayerBlend {
  double own;    // weight of the layer's own colour (lit, for a texture)
  Vec3 through;  // what passes from below
};

LayerBlend layer_blend(const scene::Color& c, Layer layer, double language_version);

}  // namespace convray::render
