// `prism { [linear_sweep | conic_sweep] [linear_spline | quadratic_spline | cubic_spline |
// bezier_spline] HEIGHT1, HEIGHT2, N, <P1>, ..., <PN> [sturm] [modifiers] }`: the points
// (x, z) form closed sub-outlines, each ending where its first point on the curve comes
// again: linear_spline, the first point; quadratic_spline, the second (the first only sets a
// slope); cubic_spline, the second, followed by one more point that sets the last slope;
// bezier_spline, a group of four whose last point is the first group's first.
#include <algorithm>
#include <string>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"
#include "sdl/spline_points.hpp"
#include "sdl/splines.hpp"

namespace convray::sdl::items {

namespace {

struct PrismForm {
  SplineKind spline = SplineKind::linear;
  bool conic = false;
};

PrismForm parse_prism_forms(Parser& parser) {
  PrismForm form;
  while (true) {
    if (const auto kind = spline_kind(parser.peek().text)) {
      form.spline = *kind;
    } else if (parser.peek().text == "linear_sweep" || parser.peek().text == "conic_sweep") {
      form.conic = parser.peek().text == "conic_sweep";
    } else {
      return form;
    }
    parser.next();
  }
}

// The pieces of one sub-outline starting at points[start]; `next` is set to where the next
// one starts. False when the points end before it closes.
bool sub_outline(SplineKind kind, const std::vector<Vec2>& p, size_t start,
                 std::vector<scene::SplinePiece>& pieces, size_t& next) {
  const size_t n = p.size();
  switch (kind) {
    case SplineKind::linear:
      for (size_t m = start + 1; m < n; ++m) {
        pieces.push_back(spline_pieces(kind, {p[m - 1], p[m]})[0]);
        if (p[m] == p[start]) return next = m + 1, true;
      }
      break;
    case SplineKind::quadratic:
      for (size_t m = start + 2; m < n; ++m) {
        pieces.push_back(spline_pieces(kind, {p[m - 2], p[m - 1], p[m]})[0]);
        if (p[m] == p[start + 1]) return next = m + 1, true;
      }
      break;
    case SplineKind::cubic:
      for (size_t m = start + 2; m + 1 < n; ++m) {
        pieces.push_back(spline_pieces(kind, {p[m - 2], p[m - 1], p[m], p[m + 1]})[0]);
        if (p[m] == p[start + 1]) return next = m + 2, true;
      }
      break;
    case SplineKind::bezier:
      for (size_t m = start; m + 3 < n; m += 4) {
        pieces.push_back(spline_pieces(kind, {p[m], p[m + 1], p[m + 2], p[m + 3]})[0]);
        if (p[m + 3] == p[start]) return next = m + 4, true;
      }
      break;
  }
  next = n;
  return false;
}

// The closed outlines of the points; a last one left open is closed by a straight piece (with
// a warning), as POV-Ray closes it.
std::vector<std::vector<scene::SplinePiece>> outlines_of(Parser& parser, SplineKind kind,
                                                         const std::vector<Vec2>& points,
                                                         const SourceLoc& loc) {
  std::vector<std::vector<scene::SplinePiece>> outlines;
  size_t start = 0;
  while (start + 1 < points.size()) {
    std::vector<scene::SplinePiece> outline;
    size_t next = 0;
    if (!sub_outline(kind, points, start, outline, next)) {
      warn_once(parser, loc, "a prism's last polygon does not end at its first point: closed");
      if (!outline.empty()) {
        const scene::SplinePiece& first = outline.front();
        const scene::SplinePiece& last = outline.back();
        const Vec2 end = last.c[0] + last.c[1] + last.c[2] + last.c[3];
        if (end != first.c[0]) {
          outline.push_back(spline_pieces(SplineKind::linear, {end, first.c[0]})[0]);
        }
      }
    }
    if (outline.size() >= 2) outlines.push_back(std::move(outline));
    start = next;
  }
  return outlines;
}

}  // namespace

scene::ObjectPtr parse_prism(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "prism", loc);
  const PrismForm form = parse_prism_forms(parser);
  double height1 = float_param(parser, "the prism's first height");
  parser.accept_comma();
  double height2 = float_param(parser, "the prism's second height");
  parser.accept_comma();
  const std::vector<Vec2> points =
      parse_spline_points(parser, form.spline, "prism", "a prism point <x, z>", 3,
                          "a prism needs at least 3 points");
  if (accept_word(parser, "open")) {
    parser.fail_unsupported(loc, "an open prism (without caps) is not supported yet by convray");
  }
  accept_word(parser, "sturm");  // the roots are exact anyway
  scene::Prism prism;
  prism.polygons = outlines_of(parser, form.spline, points, loc);
  prism.height1 = std::min(height1, height2);
  prism.height2 = std::max(height1, height2);
  prism.conic = form.conic;
  scene::Object object;
  object.shape = std::move(prism);
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
