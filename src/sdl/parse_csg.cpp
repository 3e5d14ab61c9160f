// union, intersection, difference, merge: children (and light_sources, placed with the CSG)
// in order, then the modifiers (POV-Ray refuses children after the first modifier, and so do
// we).
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

// The lights of `object`'s CSGs, `to_world` being where its parent's space lies.
void collect_csg_lights(const scene::Object& object, const scene::Transform& to_world,
                        std::vector<scene::Light>& lights) {
  const auto* csg = std::get_if<scene::Csg>(&object.shape);
  if (!csg) return;
  const scene::Transform here = object.transform.then(to_world);
  for (const auto& light : csg->lights) lights.push_back(placed_light(*light, here));
  for (const scene::ObjectPtr& child : csg->children) collect_csg_lights(*child, here, lights);
}

scene::CsgOperation operation_of(const std::string& word) {
  if (word == "intersection") return scene::CsgOperation::intersection;
  if (word == "difference") return scene::CsgOperation::difference;
  if (word == "merge") return scene::CsgOperation::merge;
  return scene::CsgOperation::union_;
}

}  // namespace

scene::ObjectPtr parse_csg(Parser& parser) {
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, word, loc);
  scene::Object object;
  object.loc = loc;
  object.shape = scene::Csg{operation_of(word), {}};
  auto own = [&](ObjectBuilder& builder) {
    scene::Csg& csg = std::get<scene::Csg>(builder.object().shape);
    if (at_word(parser, "light_source")) {
      if (builder.modified()) builder.fail_after_modifiers("the " + word + "'s light sources");
      csg.lights.push_back(std::make_shared<const scene::Light>(parse_light(parser)));
      return true;
    }
    if (!at_object(parser)) return false;
    if (builder.modified()) builder.fail_after_modifiers("the " + word + "'s objects");
    csg.children.push_back(parse_object(parser));
    return true;
  };
  scene::ObjectPtr result = parse_modifiers(block, std::move(object), object_words(), own);
  const scene::Csg& csg = std::get<scene::Csg>(result->shape);
  if (csg.children.size() + csg.lights.size() < 2) {
    // POV-Ray's warning; an empty union (from a loop that ran zero times) is kept, empty.
    warn_once(parser, loc, "a union, intersection, difference or merge has fewer than 2 objects");
  }
  return result;
}

void add_csg_lights(const scene::Object& object, scene::Scene& scene) {
  collect_csg_lights(object, scene::Transform{}, scene.lights);
}

}  // namespace convray::sdl::items
