#pragma once
// The splines of POV-Ray's lathe and prism as polynomial pieces (scene::SplinePiece).
//   linear_spline     N >= 2 points: a straight piece from each point to the next.
//   quadratic_spline  N >= 3: a piece from each point P[i] (i >= 1) to the next, the parabola
//                     through P[i-1], P[i], P[i+1]: the first point only sets a slope.
//   cubic_spline      N >= 4: Catmull-Rom pieces from P[i] to P[i+1] (1 <= i <= N-3), the
//                     slopes at the ends (P[i+1] - P[i-1]) / 2: the first and last points
//                     only set slopes.
//   bezier_spline     N a multiple of 4: each group of four is a cubic Bezier curve.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/object.hpp"

namespace convray::sdl {

enum class SplineKind { linear, quadratic, cubic, bezier };

// The kind a POV-Ray keyword names (linear_spline, ...), or none.
std::optional<SplineKind> spline_kind(std::string_view word);

// Why `count` points cannot make this kind's spline ("a cubic_spline needs at least 4
// points"), or an empty string when they can.
std::string spline_count_problem(SplineKind kind, size_t count);

std::vector<scene::SplinePiece> spline_pieces(SplineKind kind, const std::vector<Vec2>& points);

}  // namespace convray::sdl
