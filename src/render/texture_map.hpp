#pragma once
// The plain textures a texture pattern (scene::TextureMap) is made of at a point, each with
// its weight: one block of a block pattern; one or two neighbouring entries of a
// texture_map, weighted as a colour map mixes colours; every entry of an average. Maps
// nested in maps multiply their weights. The integrator shades each texture and adds the
// colours by weight (POV-Ray mixes the shaded colours of a texture_map's textures, not
// their pigments).
#include <cstddef>

#include "render/patterns.hpp"
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// POV-Ray's default texture: what a block without a texture of its own shows.
inline const scene::Texture& default_block_texture() {
  static const scene::Texture kDefault = scene::default_texture();
  return kDefault;
}

// Calls visit(texture, weight) for each plain texture (one without a map) that makes up
// `texture` at `world_point`; the weights sum to `weight`.
template <class Visit>
void for_each_texture(const scene::Texture& texture, const Vec3& world_point, double weight,
                      Visit&& visit) {
  if (!texture.map) {
    visit(texture, weight);
    return;
  }
  const scene::TextureMap& map = *texture.map;
  const auto entry = [&](size_t k, double w) {
    if (!(w > 0.0)) return;
    if (k < map.textures.size() && map.textures[k]) {
      for_each_texture(*map.textures[k], world_point, w, visit);
    } else {
      visit(default_block_texture(), w);
    }
  };
  if (map.textures.empty()) return visit(default_block_texture(), weight);
  switch (map.kind) {
    case scene::TextureMap::Kind::blocks:
      return entry(size_t(int(pattern_value(map.space, world_point))), weight);
    case scene::TextureMap::Kind::average: {
      double total = 0.0;
      for (double w : map.values) total += w;
      if (!(total > 0.0)) return visit(default_block_texture(), weight);
      for (size_t k = 0; k < map.textures.size(); ++k) entry(k, weight * map.values[k] / total);
      return;
    }
    case scene::TextureMap::Kind::map:
      break;
  }
  // As lookup_color_map: below the first value the first texture, above the last the last,
  // between two entries both by distance; two entries at one value make a sharp step.
  const double value = pattern_value(map.space, world_point);
  const size_t last = map.textures.size() - 1;
  if (value <= map.values.front()) return entry(0, weight);
  if (value >= map.values[last]) return entry(last, weight);
  size_t high = 1;
  while (high < last && map.values[high] <= value) ++high;
  const double span = map.values[high] - map.values[high - 1];
  if (!(span > 0.0) || map.textures[high] == map.textures[high - 1]) {
    return entry(high, weight);
  }
  const double t = (value - map.values[high - 1]) / span;
  entry(high - 1, weight * (1.0 - t));
  entry(high, weight * t);
}

}  // namespace convray::render
