#pragma once
// The point list of a lathe or a prism: `N, <u, v>, <u, v>, ...`, checked against the
// spline's rule for N (splines.hpp) where the count is written, as POV-Ray checks it.
#include <string_view>
#include <vector>

#include "sdl/splines.hpp"
#include "util/math.hpp"

namespace convray::sdl {
class Parser;
}

namespace convray::sdl::items {

// `object` names the item in messages ("lathe"), `point` each point ("a lathe point <r, y>");
// fewer than `min_count` points is refused with `too_few`.
std::vector<Vec2> parse_spline_points(Parser& parser, SplineKind kind, std::string_view object,
                                      std::string_view point, int min_count,
                                      std::string_view too_few);

}  // namespace convray::sdl::items
