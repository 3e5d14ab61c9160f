#include "scene/moved_textures.hpp"

#include <unordered_map>

namespace convray::scene {

namespace {

bool pigment_depends_on_position(const Pigment& pigment) {
  // A solid pigment is its colour wherever it is asked (render/pigment.cpp).
  return pigment.space.pattern != Pattern::solid;
}

bool normal_depends_on_position(const Normal& normal) {
  return normal.space.pattern != Pattern::solid && normal.amount != 0.0;
}

}  // namespace

bool depends_on_position(const Texture& texture) {
  if (texture.map) return true;
  if (pigment_depends_on_position(texture.pigment)) return true;
  if (normal_depends_on_position(texture.normal)) return true;
  return texture.below && depends_on_position(*texture.below);
}

bool same_everywhere(const Texture& a, const Texture& b) {
  if (depends_on_position(a) || depends_on_position(b)) return false;
  const Color& ca = a.pigment.color;
  const Color& cb = b.pigment.color;
  if (ca.rgb != cb.rgb || ca.filter != cb.filter || ca.transmit != cb.transmit) return false;
  if (!(a.finish == b.finish)) return false;
  if (!a.below || !b.below) return !a.below && !b.below;
  return same_everywhere(*a.below, *b.below);
}

void move_pigment(Pigment& pigment, const Transform& transform) {
  pigment.space.transform = pigment.space.transform.then(transform);
  // The pigments of a pigment_map move with the pigment they are in.
  for (PigmentMapEntry& entry : pigment.pigment_map) {
    Pigment moved = *entry.pigment;
    move_pigment(moved, transform);
    entry.pigment = std::make_shared<const Pigment>(std::move(moved));
  }
}

void move_texture(Texture& texture, const Transform& transform) {
  move_pigment(texture.pigment, transform);
  texture.normal.space.transform = texture.normal.space.transform.then(transform);
  if (texture.map) {
    // The pattern and the textures it picks move together.
    auto map = std::make_shared<TextureMap>(*texture.map);
    map->space.transform = map->space.transform.then(transform);
    for (TexturePtr& entry : map->textures) entry = moved_texture(entry, transform);
    texture.map = std::move(map);
  }
  if (texture.below) texture.below = moved_texture(texture.below, transform);
}

TexturePtr moved_texture(const TexturePtr& texture, const Transform& transform) {
  if (!texture || !depends_on_position(*texture)) return texture;
  Texture copy = *texture;
  move_texture(copy, transform);
  return std::make_shared<const Texture>(std::move(copy));
}

namespace {

// The moves of one move_inner_textures call: a texture shared by many children (a declared
// texture) is moved once and the moved copy shared as the original was.
class TextureMover {
 public:
  explicit TextureMover(const Transform& transform) : transform_(transform) {}

  TexturePtr moved(const TexturePtr& texture) {
    if (!texture || !depends_on_position(*texture)) return texture;
    auto [place, fresh] = moved_.try_emplace(texture.get());
    if (fresh) place->second = moved_texture(texture, transform_);
    return place->second;
  }
  void move_inside(Object& object);

 private:
  bool moves(const Object& object) const;
  bool moves_inside(const Object& object) const;

  const Transform& transform_;
  std::unordered_map<const Texture*, TexturePtr> moved_;
};

bool moves_texture(const TexturePtr& texture) {
  return texture && depends_on_position(*texture);
}

bool TextureMover::moves(const Object& object) const {
  return moves_texture(object.texture) || moves_texture(object.interior_texture) ||
         moves_inside(object);
}

bool TextureMover::moves_inside(const Object& object) const {
  if (object.instance) return false;  // its textures are in its own space
  if (const auto* csg = std::get_if<Csg>(&object.shape)) {
    for (const ObjectPtr& child : csg->children) {
      if (child && moves(*child)) return true;
    }
    return false;
  }
  if (const auto* mesh = std::get_if<TriangleMesh>(&object.shape)) {
    for (const TexturePtr& texture : mesh->textures) {
      if (moves_texture(texture)) return true;
    }
    return false;
  }
  if (const auto* implicit = std::get_if<Implicit>(&object.shape)) {
    for (const ComponentTexture& component : implicit->component_textures) {
      if (moves_texture(component.texture)) return true;
    }
  }
  return false;
}

void TextureMover::move_inside(Object& object) {
  if (object.instance) return;
  if (auto* csg = std::get_if<Csg>(&object.shape)) {
    for (ObjectPtr& child : csg->children) {
      if (!child || !moves(*child)) continue;  // shared as it is: nothing in it moves
      auto copy = std::make_shared<Object>(*child);
      copy->texture = moved(copy->texture);
      copy->interior_texture = moved(copy->interior_texture);
      move_inside(*copy);
      child = std::move(copy);
    }
  } else if (auto* mesh = std::get_if<TriangleMesh>(&object.shape)) {
    for (TexturePtr& texture : mesh->textures) texture = moved(texture);
  } else if (auto* implicit = std::get_if<Implicit>(&object.shape)) {
    for (ComponentTexture& component : implicit->component_textures) {
      component.texture = moved(component.texture);
    }
  }
}

}  // namespace

void move_inner_textures(Object& object, const Transform& transform) {
  if (transform.is_identity()) return;
  TextureMover(transform).move_inside(object);
}

}  // namespace convray::scene
