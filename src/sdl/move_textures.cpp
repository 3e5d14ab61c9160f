// Warps in textures and pigments, and the map entries placed in their pattern's space. Moving
// textures by transforms is scene/moved_textures.hpp's.
#include <type_traits>

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

void append_warp(scene::PatternSpace& space, scene::Warp warp) {
  warp.inner = space.transform;
  space.transform = scene::Transform();
  space.warps.push_back(std::move(warp));
}

void warp_pigment(scene::Pigment& pigment, const scene::Warp& warp) {
  append_warp(pigment.space, warp);
  for (scene::PigmentMapEntry& entry : pigment.pigment_map) {
    scene::Pigment warped = *entry.pigment;
    warp_pigment(warped, warp);
    entry.pigment = std::make_shared<const scene::Pigment>(std::move(warped));
  }
}

void warp_texture(scene::Texture& texture, const scene::Warp& warp) {
  warp_pigment(texture.pigment, warp);
  append_warp(texture.normal.space, warp);
  if (texture.map) {
    auto map = std::make_shared<scene::TextureMap>(*texture.map);
    append_warp(map->space, warp);
    for (scene::TexturePtr& entry : map->textures) {
      scene::Texture warped = *entry;
      warp_texture(warped, warp);
      entry = std::make_shared<const scene::Texture>(std::move(warped));
    }
    texture.map = std::move(map);
  }
  if (texture.below) {
    scene::Texture warped = *texture.below;
    warp_texture(warped, warp);
    texture.below = std::make_shared<const scene::Texture>(std::move(warped));
  }
}

void place_in_space(scene::Pigment& pigment, const scene::PatternSpace& space) {
  for (const scene::Warp& warp : space.warps) {
    move_pigment(pigment, warp.inner);
    warp_pigment(pigment, warp);
  }
  move_pigment(pigment, space.transform);
}

void place_in_space(scene::Texture& texture, const scene::PatternSpace& space) {
  for (const scene::Warp& warp : space.warps) {
    move_texture(texture, warp.inner);
    warp_texture(texture, warp);
  }
  move_texture(texture, space.transform);
}

}  // namespace convray::sdl::items
