#pragma once
// Supports of skeleton primitives: the set of points within R of the skeleton, outside of
// which a primitive's field is exactly zero. Two questions, answered exactly in double
// precision and without Embree: where does a line cross a support (one interval, since every
// support is convex except the arc's), and is a point inside it.
#include "field/arc.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "util/math.hpp"

namespace convray::accel {

// An interval of the ray parameter; empty when enter > exit.
struct Span {
  double enter = 1.0;
  double exit = -1.0;
  bool empty() const { return !(enter <= exit); }
};

// The line origin + t * direction (direction of unit length) against each support.
// Ball of radius R around a point.
Span sphere_span(const Vec3& origin, const Vec3& direction, const Vec3& center, double radius);
// Capsule: segment swept by a ball of radius R.
Span capsule_span(const Vec3& origin, const Vec3& direction, const field::Segment& segment,
                  double radius);
// Triangle swept by a ball of radius R: the prism over the triangle (|height| <= R) joined to
// the three edge capsules. Convex, so the union of their intervals is one interval.
Span triangle_span(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                   double radius);
// A ball that holds the triangle's support: the smallest ball around the triangle (the
// middle of its longest side for an obtuse one, else the circumcentre), grown by R.
struct BoundingBall {
  Vec3 center;
  double radius;
};
BoundingBall triangle_bounding_ball(const field::Triangle& triangle, double radius);
// A cheap test that the line may cross a support: it crosses the support's bounding ball
// (false means the span is empty; a rounding slack keeps every grazing line in). No square
// root: the Embree callbacks run it on every triangle whose box the line crosses, with the
// balls made once per mesh. Inline: it runs on every candidate of every line query.
inline bool may_cross(const Vec3& origin, const Vec3& direction, const BoundingBall& ball) {
  const Vec3 w = ball.center - origin;
  const double ww = glm::dot(w, w), along = glm::dot(w, direction);
  const double r2 = ball.radius * ball.radius;
  // The squared distance to the line loses up to a few ulps of |w|^2 to cancellation, and the
  // ball's radius was rounded: the slack covers both many times over.
  return ww - along * along <= r2 + 1e-12 * (ww + r2);
}
// Arc swept by a ball (a piece of a torus, not convex): a conservative interval, the ball
// around the circle's centre of radius (arc radius + R) cut by the slab |height| <= R.
Span arc_span(const Vec3& origin, const Vec3& direction, const field::Arc& arc, double radius);

// Squared distances from p to each skeleton primitive, exact.
double distance2_to_segment(const Vec3& p, const field::Segment& segment);
double distance2_to_triangle(const Vec3& p, const field::Triangle& triangle);
double distance2_to_arc(const Vec3& p, const field::Arc& arc);

// Axis-aligned bounds of each support.
Box3 segment_support_box(const field::Segment& segment, double radius);
Box3 triangle_support_box(const field::Triangle& triangle, double radius);
Box3 arc_support_box(const field::Arc& arc, double radius);

}  // namespace convray::accel
