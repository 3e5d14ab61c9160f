#include "geometry/instance.hpp"

#include "core/box.hpp"
#include "scene/moved_textures.hpp"

namespace convray::geometry {

namespace {

bool same_texture(const scene::TexturePtr& a, const scene::TexturePtr& b) {
  if (a == b) return true;
  return a && b && scene::same_everywhere(*a, *b);
}

}  // namespace

bool InheritedState::operator==(const InheritedState& other) const {
  return same_texture(texture, other.texture) &&
         same_texture(interior_texture, other.interior_texture) && interior == other.interior &&
         flags == other.flags;
}

const SharedUnion* SharedUnions::find(const scene::ObjectPtr& declared,
                                      const InheritedState& inherited) const {
  const auto found = built_.find(declared.get());
  if (found == built_.end()) return nullptr;
  for (const Entry& entry : found->second) {
    if (entry.inherited == inherited) return &entry.shared;
  }
  return nullptr;
}

std::shared_ptr<const Shape> SharedUnions::add(const scene::ObjectPtr& declared,
                                               const InheritedState& inherited,
                                               SharedUnion shared) {
  ++unions_;
  members_ += shared.members;
  std::shared_ptr<const Shape> shape = shared.shape;
  built_[declared.get()].push_back(Entry{declared, inherited, std::move(shared)});
  return shape;
}

}  // namespace convray::geometry
