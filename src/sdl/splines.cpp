#include "sdl/splines.hpp"

namespace convray::sdl {

namespace {

scene::SplinePiece linear_piece(Vec2 a, Vec2 b) { return {{a, b - a, Vec2(0.0), Vec2(0.0)}}; }

// The parabola q(s) with q(-1) = a, q(0) = b, q(1) = c.
scene::SplinePiece quadratic_piece(Vec2 a, Vec2 b, Vec2 c) {
  return {{b, 0.5 * (c - a), 0.5 * (a - 2.0 * b + c), Vec2(0.0)}};
}

// Catmull-Rom from b to c: the slopes (c - a) / 2 at b and (d - b) / 2 at c.
scene::SplinePiece cubic_piece(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return {{b, 0.5 * (c - a), 0.5 * (2.0 * a - 5.0 * b + 4.0 * c - d),
           0.5 * (-a + 3.0 * b - 3.0 * c + d)}};
}

scene::SplinePiece bezier_piece(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return {{a, 3.0 * (b - a), 3.0 * (a - 2.0 * b + c), -a + 3.0 * b - 3.0 * c + d}};
}

}  // namespace

std::optional<SplineKind> spline_kind(std::string_view word) {
  if (word == "linear_spline") return SplineKind::linear;
  if (word == "quadratic_spline") return SplineKind::quadratic;
  if (word == "cubic_spline") return SplineKind::cubic;
  if (word == "bezier_spline") return SplineKind::bezier;
  return std::nullopt;
}

std::string spline_count_problem(SplineKind kind, size_t count) {
  switch (kind) {
    case SplineKind::linear:
      return count >= 2 ? "" : "a linear_spline needs at least 2 points";
    case SplineKind::quadratic:
      return count >= 3 ? "" : "a quadratic_spline needs at least 3 points";
    case SplineKind::cubic:
      return count >= 4 ? "" : "a cubic_spline needs at least 4 points";
    case SplineKind::bezier:
      return count >= 4 && count % 4 == 0 ? "" : "a bezier_spline needs a multiple of 4 points";
  }
  return "";
}

std::vector<scene::SplinePiece> spline_pieces(SplineKind kind, const std::vector<Vec2>& p) {
  std::vector<scene::SplinePiece> pieces;
  const size_t n = p.size();
  switch (kind) {
    case SplineKind::linear:
      for (size_t i = 0; i + 1 < n; ++i) pieces.push_back(linear_piece(p[i], p[i + 1]));
      break;
    case SplineKind::quadratic:
      for (size_t i = 1; i + 1 < n; ++i)
        pieces.push_back(quadratic_piece(p[i - 1], p[i], p[i + 1]));
      break;
    case SplineKind::cubic:
      for (size_t i = 1; i + 2 < n; ++i) {
        pieces.push_back(cubic_piece(p[i - 1], p[i], p[i + 1], p[i + 2]));
      }
      break;
    case SplineKind::bezier:
      for (size_t i = 0; i + 3 < n; i += 4) {
        pieces.push_back(bezier_piece(p[i], p[i + 1], p[i + 2], p[i + 3]));
      }
      break;
  }
  return pieces;
}

}  // namespace convray::sdl
