// `polygon { N, <P1>, <P2>, ..., <PN> [modifiers] }`: points in 3D, or <x, y> in the plane
// z = 0. As POV-Ray reads them, a sub-polygon ends where a point repeats its first point, and
// the next point starts another; a last one left open is closed. A point is inside the
// polygon when it is inside an odd number of sub-polygons (geometry/polygon.hpp).
#include <cmath>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

// Newell's normal of a closed outline: the sum of its edges' cross terms, whatever its shape.
Vec3 newell_normal(const std::vector<Vec3>& outline) {
  Vec3 n(0.0);
  for (size_t k = 0, previous = outline.size() - 1; k < outline.size(); previous = k++) {
    const Vec3& a = outline[previous];
    const Vec3& b = outline[k];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

std::vector<std::vector<Vec3>> split_outlines(const std::vector<Vec3>& points) {
  std::vector<std::vector<Vec3>> outlines;
  std::vector<Vec3> current;
  for (const Vec3& p : points) {
    if (!current.empty() && p == current.front()) {
      if (current.size() >= 3) outlines.push_back(std::move(current));
      current.clear();
      continue;
    }
    current.push_back(p);
  }
  if (current.size() >= 3) outlines.push_back(std::move(current));
  return outlines;
}

}  // namespace

scene::ObjectPtr parse_polygon(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "polygon", loc);
  const SourceLoc count_at = parser.peek().loc;
  const int count = int_param(parser, "the polygon's number of points");
  if (count < 3) {
    parser.fail(count_at, "a polygon needs at least 3 points, found " + std::to_string(count));
  }
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    parser.accept_comma();
    points.push_back(vector_param(parser, "a polygon point"));
  }
  scene::Polygon polygon;
  polygon.outlines = split_outlines(points);
  if (polygon.outlines.empty()) parser.fail(loc, "this polygon has no sub-polygon of 3 points");
  polygon.normal = newell_normal(polygon.outlines.front());
  const double area2 = glm::length(polygon.normal);
  if (!(area2 > 0.0) || !std::isfinite(area2)) {
    parser.fail(loc, "the polygon's points lie on one line: it has no plane");
  }
  // All corners in one plane, as POV-Ray requires (to a tolerance relative to the size).
  const Vec3 unit = polygon.normal / area2;
  const Vec3 origin = polygon.outlines.front().front();
  double size = 0.0;
  for (const Vec3& p : points) size = std::max(size, glm::length(p - origin));
  for (const Vec3& p : points) {
    if (std::abs(glm::dot(p - origin, unit)) > 1e-6 * std::max(size, 1.0)) {
      parser.fail(loc, "the polygon's points do not lie in one plane");
    }
  }
  scene::Object object;
  object.shape = std::move(polygon);
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
