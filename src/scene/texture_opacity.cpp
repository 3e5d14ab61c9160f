#include "scene/texture_opacity.hpp"

#include <algorithm>

namespace convray::scene {

bool always_opaque(const Pigment& pigment) {
  if (pigment.space.pattern == Pattern::image_map || pigment.image_map) return false;
  // A pigment map (or `average`) mixes whole pigments: opaque where each of them is.
  if (!pigment.pigment_map.empty()) {
    return std::all_of(pigment.pigment_map.begin(), pigment.pigment_map.end(),
                       [](const PigmentMapEntry& e) { return e.pigment && always_opaque(*e.pigment); });
  }
  const auto opaque = [](const Color& c) { return c.opaque(); };
  return pigment.color.opaque() &&
         std::all_of(pigment.block_colors.begin(), pigment.block_colors.end(), opaque) &&
         std::all_of(pigment.color_map.begin(), pigment.color_map.end(),
                     [&](const ColorMapEntry& e) { return opaque(e.color); });
}

bool always_opaque(const Texture& texture) {
  if (texture.map) {
    // Blocks pick one texture, maps and averages mix their colours: opaque mixes stay opaque.
    return std::all_of(texture.map->textures.begin(), texture.map->textures.end(),
                       [](const TexturePtr& t) { return t && always_opaque(*t); });
  }
  // The top layer's pigment decides: light reaches the layers below only through it.
  return always_opaque(texture.pigment);
}

}  // namespace convray::scene
