#pragma once
// The values a scene computes and declares: numbers, vectors and colours (POV-Ray's colours
// are five-component vectors), strings, arrays, and the scene items an identifier can name
// (objects, textures, pigments, ...). Copying a Value is cheap: items and arrays are shared.
#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "scene/color.hpp"
#include "scene/object.hpp"
#include "scene/scene.hpp"
#include "scene/texture.hpp"
#include "scene/transform.hpp"
#include "util/element_count.hpp"
#include "util/error.hpp"

namespace convray::sdl {

// A vector of 2 to 5 components; `color` marks one written as a colour (rgb..., or the result
// of colour arithmetic), whose components are r, g, b, filter, transmit.
struct Vector {
  std::array<double, 5> v{0.0, 0.0, 0.0, 0.0, 0.0};
  int size = 3;
  bool color = false;

  Vec3 xyz() const { return {v[0], v[1], v[2]}; }
  scene::Color as_color() const { return {Vec3(v[0], v[1], v[2]), v[3], v[4]}; }
};

// What a declared identifier holds when its item needs a feature convray cannot render yet
// (a texture with a crackle pigment, a sky_sphere with a pigment_map): declaring it is
// accepted, as long as it is never used, which fails with `feature` at `feature_at`.
struct UnsupportedItem {
  std::string feature;  // "'crackle' is not supported yet by convray"
  SourceLoc feature_at;
};

struct Value;
struct Array {
  std::vector<int> dimensions;  // #declare A = array[2][3]: {2, 3}
  std::vector<Value> elements;  // row-major; unset elements hold std::monostate
  ElementCount counted;         // the elements, in the parse's budget
};

using ColorMap = std::vector<scene::ColorMapEntry>;

// A string held in an array counts one element more per this many characters (about the
// memory of one array element).
inline constexpr std::size_t kStringBytesPerElement = 96;

struct Value {
  std::variant<std::monostate,                            // not (yet) set
               double, Vector, std::string, std::shared_ptr<Array>,
               scene::ObjectPtr,                          // sphere {...}, union {...}, ...
               std::shared_ptr<const scene::Texture>,
               std::shared_ptr<const scene::Pigment>,
               std::shared_ptr<const scene::Finish>,
               std::shared_ptr<const scene::Normal>,
               std::shared_ptr<const scene::Interior>,
               std::shared_ptr<const ColorMap>,
               std::shared_ptr<const scene::Transform>,
               std::shared_ptr<const scene::Camera>,
               std::shared_ptr<const scene::Light>,
               std::shared_ptr<const scene::SkySphere>,
               std::shared_ptr<const UnsupportedItem>>
      data;
  SourceLoc loc;  // where it was computed or declared, for messages

  template <class T>
  const T* get() const { return std::get_if<T>(&data); }
  bool is_set() const { return !std::holds_alternative<std::monostate>(data); }
};

// "float", "vector", "color", "string", "array", "object", "texture", ...: for messages such
// as "expected a float, found a texture".
std::string type_name(const Value& value);

}  // namespace convray::sdl
