#pragma once
// What one component of a blob or convolution object may carry after its own parameters:
// transforms, applied to its skeleton (rotations, translations and uniform scales only: a
// uniform scale also scales the component's radius; anything else fails, since a kernel
// cannot be stretched one way), and a texture, moved by the transforms given after it.
#include <optional>
#include <string>

#include "scene/object.hpp"
#include "scene/texture.hpp"
#include "sdl/item_helpers.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::items {

extern const std::string_view kComponentModifierWords[9];

class ComponentModifiers {
 public:
  // `kind` names the component in messages: "blob sphere", "convolution segment".
  ComponentModifiers(Parser& parser, std::string kind);

  // Parses one modifier if the next token starts one; false (nothing consumed) otherwise.
  bool parse();

  const scene::Transform& transform() const { return transform_; }
  // The factor lengths are scaled by (radii scale with it).
  double scale() const { return transform_.uniform_scale(); }
  // The component's texture (with the transforms given after it), null when none was given.
  scene::TexturePtr texture() const;

 private:
  scene::Texture& texture_to_modify();

  Parser& parser_;
  std::string kind_;
  scene::Transform transform_;
  std::optional<scene::Texture> texture_;
};

// Records a component's texture under its index in listing order (Implicit::component_order
// before this component is appended).
void add_component_texture(scene::Implicit& implicit, const scene::TexturePtr& texture);

}  // namespace convray::sdl::items
