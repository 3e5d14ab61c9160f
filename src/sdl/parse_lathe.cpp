// `lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <r, y>, ...
// [sturm] [modifiers] }`: the spline of the points (sdl/splines.hpp) turned about the y axis.
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"
#include "sdl/spline_points.hpp"
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
  const std::vector<Vec2> points =
      parse_spline_points(parser, kind, "lathe", "a lathe point <r, y>", 0,
                          "a lathe needs a positive number of points");
  accept_word(parser, "sturm");  // the roots are exact anyway
  scene::Object object;
  object.shape = scene::Lathe{spline_pieces(kind, points)};
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
