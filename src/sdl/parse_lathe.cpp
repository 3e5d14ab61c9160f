// `lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <r, y>, ...
// [sturm] [modifiers] }`: the spline of the points (sdl/splines.hpp) turned about the y axis.
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"
#include "sdl/splines.hpp"

namespace convray::sdl::items {

scene::ObjectPtr parse_lathe(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "lathe", loc);
  SplineKind kind = SplineKind::linear;  // POV-Ray's default
  while (const auto named = spline_kind(parser.peek().text)) {
    kind = *named;
    parser.next();
  }
  const SourceLoc count_at = parser.peek().loc;
  const int count = int(parser.parse_float_before_points());
  if (count < 0) parser.fail(count_at, "a lathe needs a positive number of points");
  if (const std::string problem = spline_count_problem(kind, size_t(count)); !problem.empty()) {
    parser.fail(count_at, "lathe: " + problem + ", found " + std::to_string(count));
  }
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    parser.accept_comma();
    const Vec3 point = vector_param(parser, "a lathe point <r, y>");
    points.emplace_back(point.x, point.y);
  }
  accept_word(parser, "sturm");  // the roots are exact anyway
  scene::Object object;
  object.shape = scene::Lathe{spline_pieces(kind, points)};
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
