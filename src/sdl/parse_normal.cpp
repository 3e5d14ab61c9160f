// normal { [N_ID] PATTERN [amount] [bump_size f] [accuracy f] [pattern modifiers] }
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

// POV-Ray's bump height when a normal pattern is given without one.
constexpr double kDefaultBumpAmount = 0.5;

}  // namespace

scene::Normal parse_normal(Parser& parser, const scene::Normal& start) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "normal", loc);
  scene::Normal normal = start;
  if (auto declared = accept_declared<scene::Normal>(parser, "a normal")) normal = *declared;
  static constexpr std::string_view kOwn[] = {"bump_size", "accuracy"};
  while (block.more()) {
    const SourceLoc pattern_loc = parser.peek().loc;
    if (parse_pattern_keyword(parser, normal.space)) {
      normal.amount = kDefaultBumpAmount;
      // Their own bump functions in POV-Ray are not matched yet (normal_perturbation.cpp).
      if (normal.space.pattern == scene::Pattern::ripples ||
          normal.space.pattern == scene::Pattern::waves) {
        warn_once(parser, pattern_loc,
                  "ripples and waves as normals are approximated by convray: their slope is "
                  "not POV-Ray's own bump function");
      }
      // The amount may follow after a comma: `gradient x, 0.5`.
      if (parser.accept(",") || at_float_start(parser)) {
        normal.amount = float_param(parser, "the bump amount");
      }
    } else if (accept_word(parser, "bump_size")) {
      normal.amount = float_param(parser, "bump_size");
    } else if (accept_word(parser, "accuracy")) {
      normal.accuracy = float_param(parser, "accuracy");
    } else if (!parse_pattern_modifier(parser, normal.space)) {
      block.unexpected(pattern_words(), kOwn, pattern_modifier_words());
    }
  }
  return normal;
}

}  // namespace convray::sdl::items
