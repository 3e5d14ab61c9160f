// `prism { [linear_sweep] [linear_spline] HEIGHT1, HEIGHT2, N, <P1>, ..., <PN> [sturm]
// [modifiers] }`: the points (x, z) form closed polygons, each ending where its first point
// comes again. The other splines and sweeps are not supported yet.
#include <algorithm>
#include <string>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

constexpr std::string_view kUnsupportedForms[] = {"quadratic_spline", "cubic_spline",
                                                  "bezier_spline", "conic_sweep"};

void parse_prism_forms(Parser& parser) {
  while (true) {
    if (at_any_word(parser, kUnsupportedForms)) {
      parser.fail_unsupported_here("prism with " + parser.peek().text +
                                   " is not supported yet by convray (linear_spline and "
                                   "linear_sweep are)");
    }
    if (!accept_word(parser, "linear_spline") && !accept_word(parser, "linear_sweep")) return;
  }
}

// The polygons of the points: each closes where its first point comes again; a last one
// left open is closed, as POV-Ray closes it (with a warning).
std::vector<std::vector<scene::OutlinePiece>> polygons_of(Parser& parser,
                                                          const std::vector<Vec2>& points,
                                                          const SourceLoc& loc) {
  std::vector<std::vector<scene::OutlinePiece>> polygons;
  size_t start = 0;
  while (start < points.size()) {
    std::vector<scene::OutlinePiece> polygon;
    size_t k = start + 1;
    for (; k < points.size(); ++k) {
      polygon.push_back({points[k - 1], 0.5 * (points[k - 1] + points[k]), points[k]});
      if (points[k] == points[start]) break;
    }
    if (k >= points.size()) {
      warn_once(parser, loc, "a prism's last polygon does not end at its first point: closed");
      const Vec2 last = points.back(), first = points[start];
      if (last != first) polygon.push_back({last, 0.5 * (last + first), first});
    }
    if (polygon.size() >= 2) polygons.push_back(std::move(polygon));
    start = k + 1;
  }
  return polygons;
}

}  // namespace

scene::ObjectPtr parse_prism(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "prism", loc);
  parse_prism_forms(parser);
  double height1 = float_param(parser, "the prism's first height");
  parser.accept_comma();
  double height2 = float_param(parser, "the prism's second height");
  parser.accept_comma();
  const SourceLoc count_at = parser.peek().loc;
  const int count = int(parser.parse_float_before_points());
  if (count < 3) parser.fail(count_at, "a prism needs at least 3 points");
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    parser.accept_comma();
    const Vec3 point = vector_param(parser, "a prism point <x, z>");
    points.emplace_back(point.x, point.y);
  }
  if (accept_word(parser, "open")) {
    parser.fail_unsupported(loc, "an open prism (without caps) is not supported yet by convray");
  }
  accept_word(parser, "sturm");  // the roots are exact anyway
  scene::Prism prism;
  prism.polygons = polygons_of(parser, points, loc);
  prism.height1 = std::min(height1, height2);
  prism.height2 = std::max(height1, height2);
  scene::Object object;
  object.shape = std::move(prism);
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
