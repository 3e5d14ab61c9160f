// Textures are evaluated in world space (scene/texture.hpp), so every transform applied to an
// object after a texture was given must be appended to that texture's pattern transforms,
// including the textures of everything inside the object.
#include <type_traits>

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

void move_pigment(scene::Pigment& pigment, const scene::Transform& transform) {
  pigment.space.transform = pigment.space.transform.then(transform);
  // The pigments of a pigment_map move with the pigment they are in.
  for (scene::PigmentMapEntry& entry : pigment.pigment_map) {
    scene::Pigment moved = *entry.pigment;
    move_pigment(moved, transform);
    entry.pigment = std::make_shared<const scene::Pigment>(std::move(moved));
  }
}

void move_texture(scene::Texture& texture, const scene::Transform& transform) {
  move_pigment(texture.pigment, transform);
  texture.normal.space.transform = texture.normal.space.transform.then(transform);
  if (texture.map) {
    // The pattern and the textures it picks move together.
    auto map = std::make_shared<scene::TextureMap>(*texture.map);
    map->space.transform = map->space.transform.then(transform);
    for (scene::TexturePtr& entry : map->textures) entry = moved_texture(entry, transform);
    texture.map = std::move(map);
  }
  if (texture.below) texture.below = moved_texture(texture.below, transform);
}

scene::TexturePtr moved_texture(const scene::TexturePtr& texture,
                                const scene::Transform& transform) {
  if (!texture) return texture;
  scene::Texture copy = *texture;
  move_texture(copy, transform);
  return std::make_shared<const scene::Texture>(std::move(copy));
}

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

namespace {

bool has_inner_textures(const scene::Object& object);

bool has_textures(const scene::Object& object) {
  return object.texture || object.interior_texture || has_inner_textures(object);
}

bool has_inner_textures(const scene::Object& object) {
  if (const auto* csg = std::get_if<scene::Csg>(&object.shape)) {
    for (const scene::ObjectPtr& child : csg->children) {
      if (has_textures(*child)) return true;
    }
    return false;
  }
  if (const auto* mesh = std::get_if<scene::TriangleMesh>(&object.shape)) {
    return !mesh->textures.empty();
  }
  if (const auto* implicit = std::get_if<scene::Implicit>(&object.shape)) {
    return !implicit->component_textures.empty();
  }
  return false;
}

}  // namespace

void move_inner_textures(scene::Object& object, const scene::Transform& transform) {
  if (auto* csg = std::get_if<scene::Csg>(&object.shape)) {
    for (scene::ObjectPtr& child : csg->children) {
      if (!has_textures(*child)) continue;  // shared as it is: nothing in it moves
      auto copy = std::make_shared<scene::Object>(*child);
      copy->texture = moved_texture(copy->texture, transform);
      copy->interior_texture = moved_texture(copy->interior_texture, transform);
      move_inner_textures(*copy, transform);
      child = std::move(copy);
    }
  } else if (auto* mesh = std::get_if<scene::TriangleMesh>(&object.shape)) {
    for (scene::TexturePtr& texture : mesh->textures) texture = moved_texture(texture, transform);
  } else if (auto* implicit = std::get_if<scene::Implicit>(&object.shape)) {
    for (scene::ComponentTexture& component : implicit->component_textures) {
      component.texture = moved_texture(component.texture, transform);
    }
  }
}

}  // namespace convray::sdl::items
