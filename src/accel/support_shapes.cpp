#include "accel/support_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "field/triangle_frame.hpp"

namespace convray::accel {
namespace {

Span join(const Span& a, const Span& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.enter, b.enter), std::max(a.exit, b.exit)};
}

// Narrows `span` to where g0 + t g1 >= 0, t = -g0 / g1 given by the caller (clips against
// parallel planes share one reciprocal, as TriangleSpanBatch's; g1 = 0 ignores t).
void clip_half_space_at(double g0, double g1, double t, Span& span) {
  if (g1 == 0.0) {
    if (g0 < 0.0) span = Span{};
    return;
  }
  if (g1 > 0.0) {
    span.enter = std::max(span.enter, t);
  } else {
    span.exit = std::min(span.exit, t);
  }
}

// 1 / x, with 1 for x = 0.
double reciprocal(double x) { return 1.0 / (x != 0.0 ? x : 1.0); }

// Narrows `span` to where g0 + t g1 >= 0.
void clip_half_space(double g0, double g1, Span& span) {
  clip_half_space_at(g0, g1, -g0 * reciprocal(g1), span);
}

// The body of a capsule: points within R of the axis line whose projection lies on the
// segment (the end balls are added by the caller).
Span capsule_body_span(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b,
                       double radius) {
  const Vec3 axis = b - a;
  const double length = glm::length(axis);
  if (length == 0.0) return {};
  const Vec3 u = axis * (1.0 / length);  // as TriangleSpanBatch rounds it
  const Vec3 w = origin - a;
  const double dw = glm::dot(direction, u);
  const double ww = glm::dot(w, u);
  // Components perpendicular to the axis.
  const Vec3 dp = direction - dw * u;
  const Vec3 wp = w - ww * u;
  const double dp2 = glm::dot(dp, dp);
  Span span{-kInfinity, kInfinity};
  if (dp2 <= 0.0) {
    if (glm::dot(wp, wp) > radius * radius) return {};
  } else {
    // Closest approach of the projected line to the axis, then the chord of the disk.
    const double inv_dp2 = reciprocal(dp2);
    const double tc = -glm::dot(wp, dp) * inv_dp2;
    const Vec3 closest = wp + tc * dp;
    const double q2 = glm::dot(closest, closest);
    if (q2 > radius * radius) return {};
    const double half = std::sqrt((radius * radius - q2) * inv_dp2);
    span = {tc - half, tc + half};
  }
  const double inv_dw = reciprocal(dw);
  clip_half_space_at(ww, dw, -ww * inv_dw, span);                      // projection >= 0
  clip_half_space_at(length - ww, -dw, (length - ww) * inv_dw, span);  // projection <= length
  return span.empty() ? Span{} : span;
}

Vec3 triangle_normal(const field::Triangle& t) { return glm::cross(t.b - t.a, t.c - t.a); }

}  // namespace

Span sphere_span(const Vec3& origin, const Vec3& direction, const Vec3& center, double radius) {
  const Vec3 w = origin - center;
  const double tc = -glm::dot(w, direction);
  const Vec3 closest = w + tc * direction;
  const double q2 = glm::dot(closest, closest);
  if (q2 > radius * radius) return {};
  const double half = std::sqrt(radius * radius - q2);
  return {tc - half, tc + half};
}

Span capsule_span(const Vec3& origin, const Vec3& direction, const field::Segment& segment,
                  double radius) {
  Span span = capsule_body_span(origin, direction, segment.a, segment.b, radius);
  span = join(span, sphere_span(origin, direction, segment.a, radius));
  return join(span, sphere_span(origin, direction, segment.b, radius));
}

namespace {

// The farthest corner's squared distance from `center`.
double corner_reach2(const field::Triangle& t, const Vec3& center) {
  return std::max({glm::dot(t.a - center, t.a - center), glm::dot(t.b - center, t.b - center),
                   glm::dot(t.c - center, t.c - center)});
}

// The centre of the smallest ball holding the triangle: the middle of the side facing an
// angle of 90 degrees or more, else the circumcentre (in the triangle's plane).
Vec3 smallest_ball_center(const field::Triangle& t) {
  const Vec3 corners[3] = {t.a, t.b, t.c};
  for (int k = 0; k < 3; ++k) {
    const Vec3 &p = corners[k], &q = corners[(k + 1) % 3], &r = corners[(k + 2) % 3];
    if (glm::dot(q - p, r - p) <= 0.0) return 0.5 * (q + r);
  }
  const Vec3 u = t.b - t.a, v = t.c - t.a, w = glm::cross(u, v);
  return t.a + (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u)) /
                   (2.0 * glm::dot(w, w));
}

}  // namespace

// The smallest ball around the triangle, grown by R: an obtuse or skinny triangle's is far
// smaller than the ball around its centroid (a random soup's line queries tested 10 % fewer
// triangles' exact spans, the dragon's at R = 1 8 %). Its radius is measured from the centre
// as computed, so rounding in the circumcentre never leaves a corner out; where that centre
// is no better (or not finite), the centroid's ball.
SmallestBall triangle_smallest_ball(const field::Triangle& triangle) {
  const Vec3 centroid = (triangle.a + triangle.b + triangle.c) * (1.0 / 3.0);
  const double centroid_reach2 = corner_reach2(triangle, centroid);
  const Vec3 smallest = smallest_ball_center(triangle);
  const double smallest_reach2 = corner_reach2(triangle, smallest);
  if (smallest_reach2 < centroid_reach2) return {smallest, std::sqrt(smallest_reach2)};
  return {centroid, std::sqrt(centroid_reach2)};
}

BoundingBall triangle_bounding_ball(const field::Triangle& triangle, double radius) {
  constexpr float kUp = std::numeric_limits<float>::infinity();
  const SmallestBall exact = triangle_smallest_ball(triangle);
  BoundingBall ball{};
  Vec3 rounded;
  for (int axis = 0; axis < 3; ++axis) {
    ball.center[axis] = float(exact.center[axis]);
    rounded[axis] = double(ball.center[axis]);
  }
  const double stray = glm::length(rounded - exact.center);  // exact in all but the last bits
  const double grown = (exact.reach + radius + stray) * (1.0 + 1e-12);
  ball.radius = std::isfinite(grown) ? std::nextafter(float(grown), kUp) : kUp;
  ball.slab = kUp;
  const Vec3 n = triangle_normal(triangle);
  const double n_length = glm::length(n);
  if (n_length > 0.0 && std::isfinite(n_length) && std::isfinite(ball.radius)) {
    const Vec3 unit = n / n_length;
    for (int axis = 0; axis < 3; ++axis) ball.normal[axis] = float(unit[axis]);
    // The float normal strays from the unit one by under 1e-7 (heights within the ball by
    // 1e-7 of its radius), and the exact centre lies off the plane by its rounding.
    const double off_plane = std::abs(glm::dot(exact.center - triangle.a, unit));
    ball.slab = std::nextafter(float((radius + off_plane + stray + 1e-6 * grown) * (1.0 + 1e-12)),
                               kUp);
  }
  return ball;
}

namespace {

// The bounds the pieces of a triangle's support give its span, joined bound by bound: a piece
// may give an end without the other (+inf and -inf: no bound), as TriangleSpanBatch's lanes.
struct SpanBounds {
  double enter = kInfinity;
  double exit = -kInfinity;

  static double least(double a, double b) { return b < a ? b : a; }
  static double most(double a, double b) { return b > a ? b : a; }
  void add_enter(double t) { enter = least(enter, t); }
  void add_exit(double t) { exit = most(exit, t); }
};

// The ends of the chord of the cylinder around the edge a-b (of length `length`, the frame's)
// that project onto the edge. The body's other ends lie on its end disks, inside the corner
// balls, which the caller joins.
void add_capsule_body(SpanBounds& bounds, const Vec3& origin, const Vec3& direction,
                      const Vec3& a, const Vec3& b, double length, double radius) {
  const Vec3 axis = b - a;
  if (!(length > 0.0)) return;
  const Vec3 u = axis * (1.0 / length);  // as TriangleSpanBatch rounds it
  const Vec3 w = origin - a;
  const double dw = glm::dot(direction, u);
  const double ww = glm::dot(w, u);
  const Vec3 dp = direction - dw * u;  // components perpendicular to the axis
  const Vec3 wp = w - ww * u;
  const double dp2 = glm::dot(dp, dp);
  if (!(dp2 > 0.0)) return;  // parallel to the edge: its body's ends are on the end disks
  const double inv_dp2 = reciprocal(dp2);
  const double tc = -glm::dot(wp, dp) * inv_dp2;
  const Vec3 closest = wp + tc * dp;
  const double q2 = glm::dot(closest, closest);
  const double r2 = radius * radius;
  if (!(r2 - q2 >= 0.0)) return;
  const double half = std::sqrt((r2 - q2) * inv_dp2);
  const double enter = tc - half, exit = tc + half;
  const double along_enter = ww + enter * dw, along_exit = ww + exit * dw;
  if (SpanBounds::least(along_enter, length - along_enter) >= 0.0) bounds.add_enter(enter);
  if (SpanBounds::least(along_exit, length - along_exit) >= 0.0) bounds.add_exit(exit);
}

// Where the line crosses the faces |height| = R of the prism over the triangle, each counted
// only over the triangle: the prism's other ends lie on its side faces, every point of which
// is within R of its edge (inside the edge's capsule, which the caller joins).
void add_prism_faces(SpanBounds& bounds, const Vec3& origin, const Vec3& direction,
                     const field::Triangle& triangle, const Vec3& n, double radius) {
  if (!(glm::dot(n, n) > 0.0)) return;  // no area: the frame has no normal
  const double h0 = glm::dot(origin - triangle.a, n);
  const double h1 = glm::dot(direction, n);
  if (h1 == 0.0) return;  // parallel to the plane: in and out through side faces
  const double inv_h1 = reciprocal(h1);
  const double top = (radius - h0) * inv_h1, bottom = -(radius + h0) * inv_h1;
  const double enter = SpanBounds::least(top, bottom), exit = SpanBounds::most(top, bottom);
  const Vec3 vertex[3] = {triangle.a, triangle.b, triangle.c};
  double g0[3], g1[3];
  for (int i = 0; i < 3; ++i) {
    const Vec3 inward = glm::cross(n, vertex[(i + 1) % 3] - vertex[i]);
    g0[i] = glm::dot(origin - vertex[i], inward);
    g1[i] = glm::dot(direction, inward);
  }
  const auto over_triangle = [&](double t) {
    return SpanBounds::least(SpanBounds::least(g0[0] + t * g1[0], g0[1] + t * g1[1]),
                             g0[2] + t * g1[2]);
  };
  if (over_triangle(enter) >= 0.0) bounds.add_enter(enter);
  if (over_triangle(exit) >= 0.0) bounds.add_exit(exit);
}

}  // namespace

Span triangle_span(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                   double radius) {
  return triangle_span(origin, direction, triangle, field::triangle_frame(triangle), radius);
}

// The square roots of the triangle from its frame, as TriangleSpanBatch's lanes take them.
Span triangle_span(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                   const field::TriangleFrame& frame, double radius) {
  if (!may_cross(origin, direction, -kInfinity, kInfinity,
                 triangle_bounding_ball(triangle, radius))) {
    return {};
  }
  SpanBounds bounds;
  add_prism_faces(bounds, origin, direction, triangle, frame.normal, radius);
  const Vec3 vertex[3] = {triangle.a, triangle.b, triangle.c};
  for (int i = 0; i < 3; ++i) {
    add_capsule_body(bounds, origin, direction, vertex[i], vertex[(i + 1) % 3], frame.length[i],
                     radius);
    const Span ball = sphere_span(origin, direction, vertex[i], radius);
    if (!ball.empty()) {
      bounds.add_enter(ball.enter);
      bounds.add_exit(ball.exit);
    }
  }
  if (!(bounds.enter <= bounds.exit)) return {};
  return {bounds.enter, bounds.exit};
}

Span arc_span(const Vec3& origin, const Vec3& direction, const field::Arc& arc, double radius) {
  Span span = sphere_span(origin, direction, arc.center, arc.radius + radius);
  if (span.empty()) return {};
  const double h0 = glm::dot(origin - arc.center, arc.axis);
  const double h1 = glm::dot(direction, arc.axis);
  clip_half_space(radius - h0, -h1, span);
  clip_half_space(radius + h0, h1, span);
  return span.empty() ? Span{} : span;
}

double distance2_to_segment(const Vec3& p, const field::Segment& segment) {
  const Vec3 axis = segment.b - segment.a;
  const double length2 = glm::dot(axis, axis);
  double s = length2 > 0.0 ? glm::dot(p - segment.a, axis) / length2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  const Vec3 d = p - (segment.a + s * axis);
  return glm::dot(d, d);
}

// Closest point by Voronoi regions of the triangle (Ericson, Real-Time Collision Detection 5.1.5).
double distance2_to_triangle(const Vec3& p, const field::Triangle& t) {
  const Vec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  auto dist2 = [&](const Vec3& q) { return glm::dot(p - q, p - q); };
  if (d1 <= 0.0 && d2 <= 0.0) return dist2(t.a);
  const Vec3 bp = p - t.b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return dist2(t.b);
  const Vec3 cp = p - t.c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return dist2(t.c);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return distance2_to_segment(p, {t.a, t.b});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return distance2_to_segment(p, {t.a, t.c});
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return distance2_to_segment(p, {t.b, t.c});
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) {  // degenerate: the nearest of the three edges
    return std::min({distance2_to_segment(p, {t.a, t.b}), distance2_to_segment(p, {t.b, t.c}),
                     distance2_to_segment(p, {t.c, t.a})});
  }
  const double v = vb / denominator, w = vc / denominator;
  return dist2(t.a + v * ab + w * ac);
}

// On the circle the distance grows with the angle between p's direction and the point's, so
// outside the arc's range the nearer end (in angle) is closest.
double distance2_to_arc(const Vec3& p, const field::Arc& arc) {
  const Vec3 w = p - arc.center;
  const double h = glm::dot(w, arc.axis);
  const Vec3 in_plane = w - h * arc.axis;
  const double rho = glm::length(in_plane);
  const Vec3 second = glm::cross(arc.axis, arc.start);
  double phi = std::atan2(glm::dot(in_plane, second), glm::dot(in_plane, arc.start));
  if (phi < 0.0) phi += 2.0 * kPi;
  double gap = 0.0;  // angle from p's direction to the nearest point of the arc
  if (rho > 0.0 && phi > arc.angle) gap = std::min(phi - arc.angle, 2.0 * kPi - phi);
  const double r = arc.radius;
  return h * h + rho * rho + r * r - 2.0 * rho * r * std::cos(gap);
}

Box3 segment_support_box(const field::Segment& segment, double radius) {
  Box3 box;
  box.extend(segment.a);
  box.extend(segment.b);
  return {box.lo - Vec3(radius), box.hi + Vec3(radius)};
}

Box3 triangle_support_box(const field::Triangle& triangle, double radius) {
  Box3 box;
  box.extend(triangle.a);
  box.extend(triangle.b);
  box.extend(triangle.c);
  return {box.lo - Vec3(radius), box.hi + Vec3(radius)};
}

// The whole circle's box: along axis e, a circle of radius r with unit normal k reaches
// r sqrt(1 - k_e^2) from its centre.
Box3 arc_support_box(const field::Arc& arc, double radius) {
  const Vec3 reach = arc.radius * glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - arc.axis * arc.axis)) +
                     Vec3(radius);
  return {arc.center - reach, arc.center + reach};
}

}  // namespace convray::accel
