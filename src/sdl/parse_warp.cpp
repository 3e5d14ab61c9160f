// `warp { turbulence ... }` and `warp { repeat ... }` (scene::Warp); POV-Ray's other warps
// (black_hole, cylindrical, spherical, toroidal, planar, cubic) are refused by name.
#include <cmath>
#include <string>

#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

constexpr std::string_view kWarpWords[] = {"turbulence", "octaves", "omega", "lambda",
                                           "repeat",     "offset",  "flip"};
constexpr std::string_view kUnsupportedWarps[] = {"black_hole", "cylindrical", "spherical",
                                                  "toroidal",   "planar",      "cubic"};

// repeat's direction: one axis, its length the width of the repeated slab.
void parse_repeat_direction(Parser& parser, scene::Warp& warp) {
  const SourceLoc loc = parser.peek().loc;
  const Vec3 direction = vector_param(parser, "repeat");
  int axes = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) continue;
    ++axes;
    warp.axis = axis;
    warp.width = direction[axis];
  }
  if (axes != 1 || !(warp.width > 0.0) || !std::isfinite(warp.width)) {
    parser.fail(loc, "repeat needs a positive direction along one axis (x, y or z times a width)");
  }
}

}  // namespace

scene::Warp parse_warp(Parser& parser) {
  Block block(parser, "warp", take_keyword(parser));
  scene::Warp warp;
  bool has_kind = false;
  while (block.more()) {
    if (at_any_word(parser, kUnsupportedWarps)) {
      parser.fail_unsupported_here("'warp { " + parser.peek().text +
                                   " }' is not supported yet by convray");
    }
    if (!at_any_word(parser, kWarpWords)) block.unexpected(kWarpWords, kUnsupportedWarps);
    const std::string word = parser.peek().text;
    const SourceLoc loc = take_keyword(parser);
    const bool repeat_word = word == "repeat" || word == "offset" || word == "flip";
    const scene::Warp::Kind kind =
        repeat_word ? scene::Warp::Kind::repeat : scene::Warp::Kind::turbulence;
    if (has_kind && kind != warp.kind) {
      parser.fail(loc, "'" + word + "' does not belong in this kind of warp");
    }
    has_kind = true;
    warp.kind = kind;
    if (word == "repeat") {
      parse_repeat_direction(parser, warp);
    } else if (word == "offset") {
      warp.offset = vector_param(parser, "offset");
    } else if (word == "flip") {
      warp.flip = vector_param(parser, "flip");
    } else {
      parse_turbulence_setting(parser, word, warp.turbulence);
    }
  }
  if (!has_kind) parser.fail(block.loc(), "an empty warp: expected turbulence or repeat");
  return warp;
}

}  // namespace convray::sdl::items
