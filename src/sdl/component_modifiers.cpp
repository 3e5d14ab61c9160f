#include "sdl/component_modifiers.hpp"

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

const std::string_view kComponentModifierWords[9] = {"translate", "rotate",    "scale",
                                                     "matrix",    "transform", "texture",
                                                     "pigment",   "finish",    "normal"};

ComponentModifiers::ComponentModifiers(Parser& parser, std::string kind)
    : parser_(parser), kind_(std::move(kind)) {}

bool ComponentModifiers::parse() {
  SourceLoc loc;
  if (auto transform = parse_transform_modifier(parser_, &loc)) {
    if (!transform->is_similarity(1e-9)) {
      parser_.fail(loc, "non-uniform scale (or shear) of a " + kind_ +
                            " is not supported yet: a component may only be moved, turned "
                            "and scaled uniformly (scale the whole object instead)");
    }
    transform_ = transform_.then(*transform);
    if (texture_) move_texture(*texture_, *transform);
    return true;
  }
  if (at_word(parser_, "texture")) {
    texture_ = parse_texture(parser_, parser_.defaults().texture);
  } else if (at_word(parser_, "pigment")) {
    texture_to_modify().pigment = parse_pigment(parser_, texture_to_modify().pigment);
  } else if (at_word(parser_, "finish")) {
    texture_to_modify().finish = parse_finish(parser_, texture_to_modify().finish);
  } else if (at_word(parser_, "normal")) {
    texture_to_modify().normal = parse_normal(parser_, texture_to_modify().normal);
  } else {
    return false;
  }
  return true;
}

scene::Texture& ComponentModifiers::texture_to_modify() {
  if (!texture_) texture_ = parser_.defaults().texture;
  return *texture_;
}

scene::TexturePtr ComponentModifiers::texture() const {
  if (!texture_) return nullptr;
  return std::make_shared<const scene::Texture>(*texture_);
}

void add_component_texture(scene::Implicit& implicit, const scene::TexturePtr& texture) {
  if (!texture) return;
  implicit.component_textures.push_back({implicit.component_order.size(), texture});
}

}  // namespace convray::sdl::items
