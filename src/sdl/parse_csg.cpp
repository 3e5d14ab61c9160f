// union, intersection, difference, merge: children in order, then the modifiers (POV-Ray
// refuses children after the first modifier, and so do we).
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

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
    if (at_word(parser, "light_source")) {
      parser.fail_here("a light_source inside " + word +
                       " is not supported yet: place it at the top level of the scene");
    }
    if (!at_object(parser)) return false;
    if (builder.modified()) builder.fail_after_modifiers("the " + word + "'s objects");
    std::get<scene::Csg>(builder.object().shape).children.push_back(parse_object(parser));
    return true;
  };
  scene::ObjectPtr result = parse_modifiers(block, std::move(object), object_words(), own);
  const size_t children = std::get<scene::Csg>(result->shape).children.size();
  if (children < 2) {
    // POV-Ray's warning; an empty union (from a loop that ran zero times) is kept, empty.
    warn_once(parser, loc, "a union, intersection, difference or merge has fewer than 2 objects");
  }
  return result;
}

}  // namespace convray::sdl::items
