// `isosurface { function { f } [contained_by { box | sphere }] [threshold T] [accuracy A]
// [max_gradient G] [evaluate P0, P1, P2] [open] [max_trace N | all_intersections]
// [modifiers] }` (geometry/isosurface.hpp has the surface).
#include <cmath>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

constexpr std::string_view kOwn[] = {"function",   "contained_by", "threshold", "accuracy",
                                     "max_gradient", "evaluate",   "open",      "max_trace",
                                     "all_intersections"};

// contained_by { box { A, B } } or { sphere { C, R } }, untransformed.
void parse_container(Parser& parser, scene::Isosurface& iso) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "contained_by", loc);
  const SourceLoc object_at = parser.peek().loc;
  const scene::ObjectPtr object = parse_object(parser);
  const bool plain = object->clipped_by.empty() && !object->inverse &&
                     object->transform.is_identity();
  if (const auto* box = std::get_if<scene::Box>(&object->shape); box && plain) {
    iso.sphere_container = false;
    iso.box_lo = glm::min(box->corner1, box->corner2);
    iso.box_hi = glm::max(box->corner1, box->corner2);
  } else if (const auto* sphere = std::get_if<scene::Sphere>(&object->shape); sphere && plain) {
    iso.sphere_container = true;
    iso.center = sphere->center;
    iso.radius = std::abs(sphere->radius);
  } else {
    parser.fail(object_at, "contained_by takes a box or a sphere (without transformations)");
  }
  if (block.more()) block.unexpected({});
}

}  // namespace

scene::ObjectPtr parse_isosurface(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "isosurface", loc);
  scene::Isosurface iso;
  bool evaluate_warned = false;
  const auto own = [&](ObjectBuilder&) {
    if (at_word(parser, "function")) {
      iso.function = parser.parse_function_block();
    } else if (at_word(parser, "contained_by")) {
      parse_container(parser, iso);
    } else if (accept_word(parser, "threshold")) {
      iso.threshold = parser.parse_float();
    } else if (accept_word(parser, "accuracy")) {
      iso.accuracy = std::abs(parser.parse_float());
    } else if (accept_word(parser, "max_gradient")) {
      iso.max_gradient = std::abs(parser.parse_float());
    } else if (at_word(parser, "evaluate")) {
      const SourceLoc at = take_keyword(parser);
      const Vec3 p = vector_param(parser, "evaluate's P0, P1, P2");
      (void)p;
      if (!evaluate_warned) {
        warn_once(parser, at, "isosurface: 'evaluate' (an adaptive max_gradient) is ignored by "
                              "convray, which steps by max_gradient");
        evaluate_warned = true;
      }
    } else if (accept_word(parser, "open")) {
      iso.open = true;
    } else if (accept_word(parser, "max_trace")) {
      // convray always finds every crossing, which max_trace only limits.
      parser.parse_float();
    } else if (!accept_word(parser, "all_intersections")) {
      return false;
    }
    return true;
  };
  scene::Object object;
  object.loc = loc;
  object.shape = iso;
  scene::ObjectPtr result = parse_modifiers(block, std::move(object), kOwn, [&](ObjectBuilder& b) {
    if (!own(b)) return false;
    std::get<scene::Isosurface>(b.object().shape) = iso;
    return true;
  });
  if (!std::get<scene::Isosurface>(result->shape).function) {
    parser.fail(loc, "isosurface needs a function { ... }");
  }
  return result;
}

}  // namespace convray::sdl::items
