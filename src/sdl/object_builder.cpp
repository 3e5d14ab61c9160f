#include "sdl/object_builder.hpp"

#include "scene/instance.hpp"
#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

namespace {

// clang-format off
constexpr std::string_view kModifierWords[] = {
    "translate", "rotate", "scale", "matrix", "transform", "texture", "pigment", "finish",
    "normal", "interior", "material", "inverse", "no_shadow", "hollow", "bounded_by",
    "clipped_by", "sturm", "double_illuminate", "no_image", "no_reflection", "no_radiosity",
    "photons", "radiosity", "interior_texture", "uv_mapping", "split_union",
    "cutaway_textures"};
// clang-format on

}  // namespace

Keywords modifier_words() { return kModifierWords; }

ObjectBuilder::ObjectBuilder(Parser& parser, scene::Object object)
    : parser_(parser), object_(std::move(object)) {
  if (object_.texture) texture_ = *object_.texture;
}

void ObjectBuilder::fail_after_modifiers(const std::string& what) {
  parser_.fail(parser_.peek().loc, what + " must come before the object's modifiers (first: '" +
                                       first_modifier_word_ + "' at " + first_modifier_->str() +
                                       ")");
}

bool ObjectBuilder::parse_modifier() {
  if (!at_any_word(parser_, modifier_words())) return false;
  const std::string word = parser_.peek().text;
  const SourceLoc loc = parser_.peek().loc;
  if (!first_modifier_) {
    first_modifier_ = loc;
    first_modifier_word_ = word;
  }
  if (object_.instance && !at_any_word(parser_, kTransformWords)) flatten_instance();
  if (auto transform = parse_transform_modifier(parser_)) {
    apply_transform(*transform);
  } else if (word == "texture") {
    parse_texture_modifier();
  } else if (word == "pigment") {
    scene::Texture& texture = texture_to_modify();
    texture.pigment = parse_pigment(parser_, texture.pigment);
  } else if (word == "finish") {
    scene::Texture& texture = texture_to_modify();
    texture.finish = parse_finish(parser_, texture.finish);
  } else if (word == "normal") {
    scene::Texture& texture = texture_to_modify();
    texture.normal = parse_normal(parser_, texture.normal);
  } else if (word == "interior") {
    object_.interior = parse_interior(parser_, object_.interior.value_or(scene::Interior{}));
  } else if (word == "material") {
    parse_material();
  } else if (word == "clipped_by" || word == "bounded_by") {
    parse_clip_or_bound(word == "clipped_by");
  } else if (word == "interior_texture") {
    // `interior_texture { pigment ... }`, placed by the transforms that follow, as the texture
    object_.interior_texture = std::make_shared<const scene::Texture>(
        parse_texture(parser_, parser_.defaults().texture));
  } else {
    parser_.next();
    return parse_flag(word, loc);
  }
  return true;
}

// A placement that gives more than transforms is the copy of the declared union: what it
// gives lies over the members' own textures and flags (scene/instance.hpp). The transforms
// read so far are in the copy's textures now.
void ObjectBuilder::flatten_instance() {
  object_ = scene::flattened(object_);
  texture_.reset();
  if (object_.texture) texture_ = *object_.texture;
  block_transform_ = scene::Transform{};
}

void ObjectBuilder::apply_transform(const scene::Transform& transform) {
  object_.transform = object_.transform.then(transform);
  if (texture_) move_texture(*texture_, transform);
  if (object_.interior_texture) {
    object_.interior_texture = moved_texture(object_.interior_texture, transform);
  }
  block_transform_ = block_transform_.then(transform);
}

scene::Texture& ObjectBuilder::texture_to_modify() {
  // POV-Ray: a pigment, finish or normal given to an object without a texture modifies a
  // copy of the default texture.
  if (!texture_) texture_ = parser_.defaults().texture;
  return *texture_;
}

void ObjectBuilder::parse_texture_modifier() {
  const scene::Texture texture = parse_texture(parser_, parser_.defaults().texture);
  if (texture_given_) {
    texture_ = scene::layered_on(*texture_, texture);
  } else {
    texture_ = texture;
  }
  texture_given_ = true;
}

void ObjectBuilder::parse_material() {
  ParsedMaterial material = items::parse_material(parser_);
  if (material.interior) object_.interior = material.interior;
  if (material.texture) {
    texture_ = std::move(material.texture);
    texture_given_ = true;
  }
}

std::vector<scene::ObjectPtr> ObjectBuilder::parse_bounding_objects(const std::string& name) {
  Block block(parser_, name, take_keyword(parser_));
  std::vector<scene::ObjectPtr> objects;
  const std::string other = name == "clipped_by" ? "bounded_by" : "clipped_by";
  if (accept_word(parser_, other)) {
    // `clipped_by { bounded_by }` and `bounded_by { clipped_by }`: the other list, already
    // in the object's own space.
    if (other == "bounded_by" && object_.bounded_by) objects.push_back(object_.bounded_by);
    if (other == "clipped_by") objects = object_.clipped_by;
    if (objects.empty()) {
      parser_.fail(block.loc(), name + " { " + other + " } needs an earlier " + other);
    }
    parser_.expect("}", name);
    return objects;
  }
  // The objects are written in the space the object is in now; they are stored in its own
  // space (like a CSG's children), so that later transforms move them with it.
  const scene::Transform to_own_space = object_.transform.inverse();
  while (block.more()) {
    if (!at_object(parser_)) block.unexpected({}, {});
    scene::ObjectPtr bound = parse_object(parser_);
    if (!object_.transform.is_identity()) {
      auto placed = std::make_shared<scene::Object>(*bound);
      placed->transform = placed->transform.then(to_own_space);
      bound = std::move(placed);
    }
    objects.push_back(std::move(bound));
  }
  if (objects.empty()) parser_.fail(block.loc(), name + " needs at least one object");
  return objects;
}

void ObjectBuilder::parse_clip_or_bound(bool clip) {
  const SourceLoc loc = parser_.peek().loc;
  std::vector<scene::ObjectPtr> objects =
      parse_bounding_objects(clip ? "clipped_by" : "bounded_by");
  if (clip) {
    object_.clipped_by.insert(object_.clipped_by.end(), objects.begin(), objects.end());
    return;
  }
  // POV-Ray 3.7 also cuts a poly, cubic, quartic or quadric where it leaves its bound (not
  // a sphere or a torus; measured with povray, and not as clipped_by would: hyptorus.pov).
  if (std::holds_alternative<scene::Polynomial>(object_.shape)) {
    warn_once(parser_, loc,
              "bounded_by on a poly, cubic, quartic or quadric: POV-Ray also cuts away parts of "
              "the surface outside the bound, convray only skips rays that miss the bound");
  }
  if (objects.size() == 1) {
    object_.bounded_by = objects.front();
    return;
  }
  // Several bounding objects bound by their intersection.
  scene::Object bound;
  bound.shape = scene::Csg{scene::CsgOperation::intersection, std::move(objects)};
  bound.loc = loc;
  object_.bounded_by = std::make_shared<const scene::Object>(std::move(bound));
}

bool ObjectBuilder::parse_flag(const std::string& word, const SourceLoc& loc) {
  if (word == "inverse") {
    object_.inverse = !object_.inverse;
  } else if (word == "no_shadow") {
    object_.no_shadow = true;
  } else if (word == "no_image") {
    object_.no_image = optional_bool(parser_);
  } else if (word == "no_reflection") {
    object_.no_reflection = optional_bool(parser_);
  } else if (word == "double_illuminate") {
    object_.double_illuminate = optional_bool(parser_);
  } else if (word == "hollow") {
    object_.hollow = optional_bool(parser_);
  } else if (word == "split_union") {
    object_.split_union = optional_bool(parser_);
  } else if (word == "sturm") {
    optional_bool(parser_);  // our roots are exact without it
  } else if (word == "photons" || word == "radiosity") {
    skip_braced(parser_, word, loc);
    warn_once(parser_, loc,
              "'" + word + "' settings are ignored: convray does not render " +
                  (word == "photons" ? "photons" : "radiosity"));
  } else {
    optional_bool(parser_);
    warn_once(parser_, loc, "'" + word + "' is ignored by convray");
  }
  return true;
}

scene::ObjectPtr ObjectBuilder::build(const scene::ObjectPtr& unchanged) {
  if (!first_modifier_ && unchanged) return unchanged;
  if (texture_) object_.texture = std::make_shared<const scene::Texture>(*texture_);
  if (!block_transform_.is_identity()) move_inner_textures(object_, block_transform_);
  return std::make_shared<const scene::Object>(std::move(object_));
}

scene::ObjectPtr parse_modifiers(Block& block, scene::Object object, Keywords own_words,
                                 const OwnKeywordParser& own) {
  ObjectBuilder builder(block.parser(), std::move(object));
  while (block.more()) {
    if (own && own(builder)) continue;
    if (builder.parse_modifier()) continue;
    block.unexpected(own_words, modifier_words());
  }
  return builder.build();
}

}  // namespace convray::sdl::items
