// `sor { N, <r, h>, ... [open] [sturm] [modifiers] }`: a surface of revolution about y
// (geometry/sor.hpp). At least 4 points; the heights from the second to the last but one
// ascend; radii are not negative.
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

scene::ObjectPtr parse_sor(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "sor", loc);
  const SourceLoc count_at = parser.peek().loc;
  const int count = int_param(parser, "the sor's number of points");
  if (count < 4) {
    parser.fail(count_at, "a sor needs at least 4 points, found " + std::to_string(count));
  }
  scene::Sor sor;
  for (int k = 0; k < count; ++k) {
    parser.accept_comma();
    const SourceLoc at = parser.peek().loc;
    const Vec3 p = vector_param(parser, "a sor point <r, h>");
    if (p.x < 0.0) parser.fail(at, "a sor's radius must not be negative");
    sor.points.emplace_back(p.x, p.y);
  }
  // The segments run from the second point to the last but one: their heights must ascend
  // (each segment's cubic is a function of the height); the first and last points only set
  // slopes (POV-Ray's objects/sor1.pov starts with two points at one height).
  const std::vector<Vec2>& p = sor.points;
  for (size_t k = 1; k + 2 < p.size(); ++k) {
    if (!(p[k + 1].y > p[k].y)) {
      parser.fail(loc, "a sor's points must ascend in height from the second to the last but "
                       "one (point " + std::to_string(k + 2) + " is not above point " +
                       std::to_string(k + 1) + ")");
    }
  }
  if (!(p[2].y != p[0].y) || !(p[p.size() - 1].y != p[p.size() - 3].y)) {
    parser.fail(loc, "a sor's first and last points must not lie at the height of the points "
                     "two places away (they set the slopes)");
  }
  scene::Object object;
  object.shape = std::move(sor);
  object.loc = loc;
  static constexpr std::string_view kOwn[] = {"open", "sturm"};
  return parse_modifiers(block, std::move(object), kOwn, [&parser](ObjectBuilder& builder) {
    if (accept_word(parser, "open")) {
      std::get<scene::Sor>(builder.object().shape).open = true;
    } else if (!accept_word(parser, "sturm")) {  // sturm: the roots are exact anyway
      return false;
    }
    return true;
  });
}

}  // namespace convray::sdl::items
