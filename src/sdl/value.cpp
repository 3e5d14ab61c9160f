#include "sdl/value.hpp"

namespace convray::sdl {

std::string type_name(const Value& value) {
  struct Namer {
    std::string operator()(std::monostate) const { return "an unset value"; }
    std::string operator()(double) const { return "a float"; }
    std::string operator()(const Vector& v) const { return v.color ? "a color" : "a vector"; }
    std::string operator()(const std::string&) const { return "a string"; }
    std::string operator()(const std::shared_ptr<Array>&) const { return "an array"; }
    std::string operator()(const scene::ObjectPtr&) const { return "an object"; }
    std::string operator()(const std::shared_ptr<const scene::Texture>&) const {
      return "a texture";
    }
    std::string operator()(const std::shared_ptr<const scene::Pigment>&) const {
      return "a pigment";
    }
    std::string operator()(const std::shared_ptr<const scene::Finish>&) const {
      return "a finish";
    }
    std::string operator()(const std::shared_ptr<const scene::Normal>&) const {
      return "a normal";
    }
    std::string operator()(const std::shared_ptr<const scene::Interior>&) const {
      return "an interior";
    }
    std::string operator()(const std::shared_ptr<const ColorMap>&) const { return "a color_map"; }
    std::string operator()(const std::shared_ptr<const scene::Transform>&) const {
      return "a transform";
    }
    std::string operator()(const std::shared_ptr<const scene::Camera>&) const {
      return "a camera";
    }
    std::string operator()(const std::shared_ptr<const scene::Light>&) const {
      return "a light_source";
    }
    std::string operator()(const std::shared_ptr<const scene::SkySphere>&) const {
      return "a sky_sphere";
    }
    std::string operator()(const std::shared_ptr<const UnsupportedItem>&) const {
      return "an item convray cannot render yet";
    }
  };
  return std::visit(Namer{}, value.data);
}

}  // namespace convray::sdl
