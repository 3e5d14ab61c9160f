#include "sdl/spline_points.hpp"

#include <string>

#include "sdl/item_helpers.hpp"

namespace convray::sdl::items {

std::vector<Vec2> parse_spline_points(Parser& parser, SplineKind kind, std::string_view object,
                                      std::string_view point, int min_count,
                                      std::string_view too_few) {
  const SourceLoc count_at = parser.peek().loc;
  const int count = int(parser.parse_float_before_points());
  if (count < min_count) parser.fail(count_at, std::string(too_few));
  if (const std::string problem = spline_count_problem(kind, size_t(count)); !problem.empty()) {
    parser.fail(count_at, std::string(object) + ": " + problem + ", found " + std::to_string(count));
  }
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    parser.accept_comma();
    const Vec3 p = vector_param(parser, point);
    points.emplace_back(p.x, p.y);
  }
  return points;
}

}  // namespace convray::sdl::items
