#include "mesh/triangle_contact.hpp"

#include <algorithm>

#include "mesh/exact_predicates.hpp"

namespace convray::mesh {
namespace {

// Dropping coordinate `axis` maps the plane of a triangle one-to-one onto the other two
// coordinates exactly when the triangle's projection there is not flat, and the mapping keeps
// every incidence and betweenness of points in that plane. Some such axis exists for a
// triangle that is not flat.
Vec2 drop(const Vec3& p, int axis) {
  return axis == 0 ? Vec2{p.y, p.z} : (axis == 1 ? Vec2{p.x, p.z} : Vec2{p.x, p.y});
}

int faithful_axis(const Corners& t) {
  for (int axis = 0; axis < 3; ++axis) {
    if (orient2d(drop(t[0], axis), drop(t[1], axis), drop(t[2], axis)) != 0) return axis;
  }
  return -1;  // flat: callers exclude this
}

using Corners2 = std::array<Vec2, 3>;

Corners2 drop(const Corners& t, int axis) {
  return {drop(t[0], axis), drop(t[1], axis), drop(t[2], axis)};
}

// Whether p, known to be collinear with a and b, lies on the closed segment [a, b].
bool within_box(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_meet_2d(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const int d0 = orient2d(q0, q1, p0), d1 = orient2d(q0, q1, p1);
  const int d2 = orient2d(p0, p1, q0), d3 = orient2d(p0, p1, q1);
  if (d0 * d1 < 0 && d2 * d3 < 0) return true;
  return (d0 == 0 && within_box(q0, q1, p0)) || (d1 == 0 && within_box(q0, q1, p1)) ||
         (d2 == 0 && within_box(p0, p1, q0)) || (d3 == 0 && within_box(p0, p1, q1));
}

// Closed triangle t (not flat) contains p: no corner pair sees p on the wrong side.
bool triangle_contains_2d(const Corners2& t, const Vec2& p) {
  const int a = orient2d(t[0], t[1], p), b = orient2d(t[1], t[2], p), c = orient2d(t[2], t[0], p);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

bool segment_meets_triangle_2d(const Vec2& s0, const Vec2& s1, const Corners2& t) {
  if (triangle_contains_2d(t, s0) || triangle_contains_2d(t, s1)) return true;
  for (int k = 0; k < 3; ++k) {
    if (segments_meet_2d(s0, s1, t[k], t[(k + 1) % 3])) return true;
  }
  return false;
}

bool triangles_meet_2d(const Corners2& p, const Corners2& q) {
  for (int k = 0; k < 3; ++k) {
    if (segment_meets_triangle_2d(p[k], p[(k + 1) % 3], q)) return true;
  }
  return triangle_contains_2d(p, q[0]);  // q inside p, edges apart
}

// All three signs strictly on one side.
bool one_side(int a, int b, int c) {
  return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
}

int shared_corner_count(const Corners& p, const Corners& q) {
  int shared = 0;
  for (const Vec3& corner : p) shared += int(std::count(q.begin(), q.end(), corner));
  return shared;
}

// p and q share corner p[i] == q[j]: they meet elsewhere exactly when the edge of either
// opposite the shared corner meets the other. (Their common part is convex and contains the
// shared corner; if it has another point, one of its other extreme points is a corner of p in
// q, a corner of q in p, or a crossing of two edges, and an edge through the shared corner
// can only cross the other's edges at the other's far edge or by running along one of them.)
bool meet_beyond_corner(const Corners& p, int i, const Corners& q, int j) {
  return segment_meets_triangle(p[(i + 1) % 3], p[(i + 2) % 3], q) ||
         segment_meets_triangle(q[(j + 1) % 3], q[(j + 2) % 3], p);
}

// p and q share an edge; a and b are their corners off it. Non-coplanar faces meet only on
// the common edge (each meets the other's plane only there); coplanar ones overlap beyond it
// when a and b lie on the same side of it.
bool overlap_beyond_edge(const Vec3& e0, const Vec3& e1, const Vec3& a, const Vec3& b) {
  if (orient3d(e0, e1, a, b) != 0) return false;
  const int axis = faithful_axis({e0, e1, a});
  return orient2d(drop(e0, axis), drop(e1, axis), drop(a, axis)) ==
         orient2d(drop(e0, axis), drop(e1, axis), drop(b, axis));
}

}  // namespace

bool is_flat(const Corners& t) { return faithful_axis(t) < 0; }

bool segment_meets_triangle(const Vec3& s0, const Vec3& s1, const Corners& t) {
  const int o0 = orient3d(t[0], t[1], t[2], s0), o1 = orient3d(t[0], t[1], t[2], s1);
  if (o0 * o1 > 0) return false;
  if (o0 == 0 && o1 == 0) {
    const int axis = faithful_axis(t);
    return segment_meets_triangle_2d(drop(s0, axis), drop(s1, axis), drop(t, axis));
  }
  // The segment crosses the plane at one point; it lies in the closed triangle when the line
  // passes no edge of t on the wrong side (signs of the line against the three edges agree).
  const int a = orient3d(s0, s1, t[0], t[1]), b = orient3d(s0, s1, t[1], t[2]),
            c = orient3d(s0, s1, t[2], t[0]);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

bool triangles_meet(const Corners& p, const Corners& q) {
  const int q0 = orient3d(p[0], p[1], p[2], q[0]), q1 = orient3d(p[0], p[1], p[2], q[1]),
            q2 = orient3d(p[0], p[1], p[2], q[2]);
  if (one_side(q0, q1, q2)) return false;
  if (q0 == 0 && q1 == 0 && q2 == 0) {
    const int axis = faithful_axis(p);
    return triangles_meet_2d(drop(p, axis), drop(q, axis));
  }
  if (one_side(orient3d(q[0], q[1], q[2], p[0]), orient3d(q[0], q[1], q[2], p[1]),
               orient3d(q[0], q[1], q[2], p[2]))) {
    return false;
  }
  // Not coplanar: the common part lies on the line where the planes meet, and its ends are
  // ends of p's or q's stretch of that line, which lie on their edges.
  for (int k = 0; k < 3; ++k) {
    if (segment_meets_triangle(p[k], p[(k + 1) % 3], q)) return true;
    if (segment_meets_triangle(q[k], q[(k + 1) % 3], p)) return true;
  }
  return false;
}

bool faces_intersect(const Corners& p, const Corners& q) {
  switch (shared_corner_count(p, q)) {
    case 0:
      return triangles_meet(p, q);
    case 1:
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          if (p[i] == q[j]) return meet_beyond_corner(p, i, q, j);
        }
      }
      return false;  // unreachable
    case 2:
      for (int i = 0; i < 3; ++i) {
        const Vec3& a = p[i];  // the corner of p off the common edge
        if (std::count(q.begin(), q.end(), a) != 0) continue;
        for (const Vec3& b : q) {
          if (b != p[(i + 1) % 3] && b != p[(i + 2) % 3]) {
            return overlap_beyond_edge(p[(i + 1) % 3], p[(i + 2) % 3], a, b);
          }
        }
      }
      return false;  // unreachable
    default:
      return true;
  }
}

}  // namespace convray::mesh
