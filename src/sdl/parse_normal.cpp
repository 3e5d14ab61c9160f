// normal { [N_ID] PATTERN [amount] [bump_size f] [pattern modifiers] }
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
    const SourceLoc pattern_at = parser.peek().loc;
    if (parse_pattern_keyword(parser, normal.space)) {
      normal.amount = kDefaultBumpAmount;
      if (scene::is_block_pattern(normal.space.pattern)) {
        // POV-Ray tilts whole blocks of checker, brick and hexagon normals; how is not
        // measured yet, so the renderer leaves such normals out (render/normal_perturbation).
        warn_once(parser, pattern_at,
                  "checker, brick and hexagon as normal patterns are left out by convray (the "
                  "surface is drawn without their bumps)");
      }
      // The amount may follow after a comma: `gradient x, 0.5`.
      if (parser.accept(",") || at_float_start(parser)) {
        normal.amount = float_param(parser, "the bump amount");
      }
    } else if (accept_word(parser, "bump_size")) {
      normal.amount = float_param(parser, "bump_size");
    } else if (accept_word(parser, "accuracy")) {
      float_param(parser, "accuracy");  // POV-Ray's sampling step; the renderer has its own
    } else if (!parse_pattern_modifier(parser, normal.space)) {
      block.unexpected(pattern_words(), kOwn, pattern_modifier_words());
    }
  }
  return normal;
}

}  // namespace convray::sdl::items
