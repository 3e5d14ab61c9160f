#pragma once
// A declared union placed many times (scene/instance.hpp) is traced through one hierarchy of
// its members, built once in the union's own space and shared by every placement: each
// placement is a TransformedShape (geometry/transformed.hpp) in the scene's hierarchy that
// carries rays into that space and crossings back out. 1000 placements of a 1000-member union
// hold 1000 members, not 10^6.
//
// The members' textures stay in the union's own space: a crossing names the placement
// (Crossing::texture_space) and the renderer evaluates textures at the hit point carried back
// through it, which is where the copy's moved textures would have been evaluated.
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "geometry/shape.hpp"
#include "scene/object.hpp"
#include "scene/transform.hpp"

namespace convray::geometry {

// The members of one shared union: their hierarchy, and how many there are.
struct SharedUnion {
  std::shared_ptr<const Shape> shape;
  size_t members = 0;
};


// What the members of a shared union inherit from above it (nothing that depends on where it
// is placed: textures that look the same everywhere, an interior, flags): placements that
// inherit the same share one hierarchy.
struct InheritedState {
  scene::TexturePtr texture;  // null where no member wears it
  scene::TexturePtr interior_texture;
  std::optional<scene::Interior> interior;
  unsigned flags = 0;
  // Textures are the same record, or look the same everywhere (scene::same_everywhere).
  bool operator==(const InheritedState& other) const;
};

// The shared unions built while a World is built, one per declared union and inherited state.
class SharedUnions {
 public:
  // The one built for `declared` under `inherited`, or null.
  const SharedUnion* find(const scene::ObjectPtr& declared,
                          const InheritedState& inherited) const;
  // Keeps `shared` (and `declared`, whose address is the key) for the placements to come.
  std::shared_ptr<const Shape> add(const scene::ObjectPtr& declared,
                                   const InheritedState& inherited, SharedUnion shared);

  size_t unions() const { return unions_; }
  // The members built for all of them: each shared union's counted once.
  size_t members() const { return members_; }

 private:
  struct Entry {
    scene::ObjectPtr declared;
    InheritedState inherited;
    SharedUnion shared;
  };
  std::unordered_map<const scene::Object*, std::vector<Entry>> built_;
  size_t unions_ = 0;
  size_t members_ = 0;
};

}  // namespace convray::geometry
