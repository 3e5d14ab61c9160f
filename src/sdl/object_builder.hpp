#pragma once
// An object whose modifiers are being parsed: translate/rotate/scale/matrix/transform,
// texture/pigment/finish/normal, interior, material, inverse, no_shadow, hollow, bounded_by,
// clipped_by, and the flags that are accepted with a warning.
//
// Textures move with the transforms given after them (POV-Ray's rule): the object's texture is
// kept as a mutable copy that every later transform is appended to, and the textures inside
// the object (CSG children, mesh faces, components) get the transforms of this block when
// the object is built.
#include <functional>
#include <optional>

#include "scene/object.hpp"
#include "sdl/item_helpers.hpp"
#include "sdl/parser.hpp"

namespace convray::sdl::items {

// The object modifier keywords, for "did you mean".
Keywords modifier_words();

class ObjectBuilder {
 public:
  // `object` is the shape (or the copy of a declared object) the modifiers apply to.
  ObjectBuilder(Parser& parser, scene::Object object);

  scene::Object& object() { return object_; }

  // Parses one modifier if the next token starts one; false (nothing consumed) otherwise.
  bool parse_modifier();

  // Whether any modifier has been given, and where the first was: a shape's own items
  // (CSG children, blob components) must come before its modifiers, as in POV-Ray.
  bool modified() const { return first_modifier_.has_value(); }
  const SourceLoc& first_modifier_loc() const { return *first_modifier_; }
  // "the union's children must come before its modifiers (first: 'pigment' at 3:5)"
  [[noreturn]] void fail_after_modifiers(const std::string& what);

  // The finished record. Returns `unchanged` itself when no modifier was given (declared
  // objects are shared, not copied, by `object { ID }`).
  scene::ObjectPtr build(const scene::ObjectPtr& unchanged = nullptr);

 private:
  void flatten_instance();
  void apply_transform(const scene::Transform& transform);
  scene::Texture& texture_to_modify();
  void parse_texture_modifier();
  void parse_material();
  void parse_clip_or_bound(bool clip);
  std::vector<scene::ObjectPtr> parse_bounding_objects(const std::string& name);
  bool parse_flag(const std::string& word, const SourceLoc& loc);

  Parser& parser_;
  scene::Object object_;
  std::optional<scene::Texture> texture_;  // the object's texture, while it is modified
  bool texture_given_ = false;             // a `texture { }` in this block (for the warning)
  scene::Transform block_transform_;       // the transforms of this block, for inner textures
  std::optional<SourceLoc> first_modifier_;
  std::string first_modifier_word_;
};

// The loop a shape ends with: modifiers until the closing `}`. `own` parses the shape's own
// keywords that may appear among the modifiers (cylinder's `open`, torus' `sturm`); it
// returns false when the next token is not one of them. `own_words` feed "did you mean".
using OwnKeywordParser = std::function<bool(ObjectBuilder&)>;
scene::ObjectPtr parse_modifiers(Block& block, scene::Object object, Keywords own_words = {},
                                 const OwnKeywordParser& own = {});

}  // namespace convray::sdl::items
