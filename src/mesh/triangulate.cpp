#include "mesh/triangulate.hpp"

#include <cmath>
#include <numeric>

namespace convray::mesh {
namespace {

// Ear clipping costs O(n^3) in the worst case; bigger polygons (rare outside fuzzers) get the
// fan, which is right for the convex ones.
constexpr size_t kMaxEarClippingCorners = 64;

void append_fan(std::span<const uint32_t> corners, std::vector<Triangle>& out) {
  for (size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
}

// Newell's method: the area-weighted normal, well defined even for slightly non-planar faces.
Vec3 newell_normal(std::span<const uint32_t> corners, const std::vector<Vec3>& positions) {
  Vec3 normal(0.0);
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec3& a = positions[corners[i]];
    const Vec3& b = positions[corners[(i + 1) % corners.size()]];
    normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return normal;
}

// Drops the coordinate along which the normal is largest, and mirrors the other two if
// needed, so that the polygon runs counter-clockwise in the plane it is projected onto.
std::vector<Vec2> project_counter_clockwise(std::span<const uint32_t> corners,
                                            const std::vector<Vec3>& positions, const Vec3& normal) {
  Vec3 magnitude = glm::abs(normal);
  int axis = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : (magnitude.y >= magnitude.z ? 1 : 2);
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  double mirror = normal[axis] < 0.0 ? -1.0 : 1.0;
  std::vector<Vec2> points;
  points.reserve(corners.size());
  for (uint32_t index : corners) points.emplace_back(positions[index][u], mirror * positions[index][v]);
  return points;
}

double orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Closed test: a point on the border blocks the ear too, which errs on the safe side.
bool inside_or_on(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return orientation(a, b, p) >= 0.0 && orientation(b, c, p) >= 0.0 && orientation(c, a, p) >= 0.0;
}

bool is_ear(const std::vector<size_t>& ring, size_t at, const std::vector<Vec2>& points) {
  size_t n = ring.size();
  size_t prev = ring[(at + n - 1) % n], cur = ring[at], next = ring[(at + 1) % n];
  if (orientation(points[prev], points[cur], points[next]) <= 0.0) return false;  // reflex or flat
  for (size_t other : ring) {
    if (other == prev || other == cur || other == next) continue;
    if (inside_or_on(points[other], points[prev], points[cur], points[next])) return false;
  }
  return true;
}

// False when no ear is left to clip (self-intersecting polygon, or rounding).
bool ear_clip(std::span<const uint32_t> corners, const std::vector<Vec2>& points,
              std::vector<Triangle>& out) {
  std::vector<size_t> ring(corners.size());
  std::iota(ring.begin(), ring.end(), size_t{0});
  std::vector<Triangle> triangles;
  while (ring.size() > 3) {
    // Looking from ring position 1 onwards makes a convex polygon come out as a fan from
    // corner 0, the same triangles a naive reader would produce.
    bool clipped = false;
    for (size_t step = 1; step <= ring.size() && !clipped; ++step) {
      size_t at = step % ring.size();
      if (!is_ear(ring, at, points)) continue;
      size_t n = ring.size();
      triangles.push_back({corners[ring[(at + n - 1) % n]], corners[ring[at]], corners[ring[(at + 1) % n]]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(at));
      clipped = true;
    }
    if (!clipped) return false;
  }
  triangles.push_back({corners[ring[0]], corners[ring[1]], corners[ring[2]]});
  out.insert(out.end(), triangles.begin(), triangles.end());
  return true;
}

}  // namespace

void triangulate_polygon(std::span<const uint32_t> corners, const std::vector<Vec3>& positions,
                         std::vector<Triangle>& out) {
  if (corners.size() < 3) return;
  if (corners.size() == 3 || corners.size() > kMaxEarClippingCorners) return append_fan(corners, out);
  Vec3 normal = newell_normal(corners, positions);
  if (!(glm::dot(normal, normal) > 0.0)) return append_fan(corners, out);  // no plane to work in
  std::vector<Vec2> points = project_counter_clockwise(corners, positions, normal);
  if (!ear_clip(corners, points, out)) append_fan(corners, out);
}

}  // namespace convray::mesh
