#pragma once
// Supports of skeleton primitives: the set of points within R of the skeleton, outside of
// which a primitive's field is exactly zero. Two questions, answered exactly in double
// precision and without Embree: where does a line cross a support (one interval, since every
// support is convex except the arc's), and is a point inside it.
#include "field/arc.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
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
// `frame`: the triangle's (field::triangle_frame), where the caller has it; otherwise made here.
Span triangle_span(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                   const field::TriangleFrame& frame, double radius);
Span triangle_span(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                   double radius);
// The smallest ball around a triangle: the middle of its longest side for an obtuse one, else
// the circumcentre; `reach` is measured from the centre as computed (every corner within it).
// Where that centre is no better (or not finite), the centroid's ball.
struct SmallestBall {
  Vec3 center;
  double reach;
};
SmallestBall triangle_smallest_ball(const field::Triangle& triangle);
// A ball that holds the triangle's support: its smallest ball grown by R; and the slab around
// the triangle's plane through the ball's centre that holds the support as well (half width
// R). In floats, 32 bytes (the Embree callbacks read one per box crossed: the dragon's 200,000
// take 6.5 MB, where doubles took 9.7 MB and the render at R = 1 2 % longer): the radius and
// the slab rounded up and grown by how far the float centre strays from the exact one, the
// slab also by the float normal's error over the ball and the centre's height off the plane.
struct BoundingBall {
  float center[3];
  float radius;
  float normal[3];  // unit; zero where the triangle has no plane (the slab is then everything)
  float slab;       // half width
};
BoundingBall triangle_bounding_ball(const field::Triangle& triangle, double radius);
// A cheap test that the line may cross a support with some t in [tmin, tmax]: it crosses the
// chunk of the line within the support's bounding ball and its slab (false means the span
// there is empty; rounding slacks keep every grazing line in). No square root or division.
// The ball alone left 37 % of the dragon's candidates at R = 1 with an empty exact span and
// 8 % with a span outside the chunk (the soup 20 % and 9 %), each an exact span in the batch
// for nothing. Line fans (line_fans.hpp) run it in SIMD lanes; inline for its scalar users.
inline bool may_cross_chunk(const Vec3& origin, const Vec3& direction, double tmin,
                            double tmax, const BoundingBall& ball) {
  const Vec3 w = Vec3(ball.center[0], ball.center[1], ball.center[2]) - origin;
  const double ww = glm::dot(w, w), along = glm::dot(w, direction);
  const double r2 = double(ball.radius) * double(ball.radius);
  const double half2 = r2 + 1e-12 * (ww + r2) - (ww - along * along);
  const double before = tmin - along, past = along - tmax;
  return half2 >= 0.0 && !(before > 0.0 && before * before > half2) &&
         !(past > 0.0 && past * past > half2);
}
inline bool may_cross(const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                      const BoundingBall& ball) {
  const Vec3 w = Vec3(ball.center[0], ball.center[1], ball.center[2]) - origin;
  const double ww = glm::dot(w, w), along = glm::dot(w, direction);
  const double r2 = double(ball.radius) * double(ball.radius);
  // The squared distance to the line loses up to a few ulps of |w|^2 to cancellation, and the
  // ball's radius was rounded: the slack covers both many times over. half2: the squared
  // half chord.
  const double half2 = r2 + 1e-12 * (ww + r2) - (ww - along * along);
  if (!(half2 >= 0.0)) return false;
  // The chord [along - half, along + half] against [tmin, tmax].
  const double before = tmin - along, past = along - tmax;
  if ((before > 0.0 && before * before > half2) || (past > 0.0 && past * past > half2)) {
    return false;
  }
  // The slab: the line's height above the plane at the chord's middle is its least over the
  // chord less |slope| half, where the slope does not take it through the plane.
  const Vec3 n(ball.normal[0], ball.normal[1], ball.normal[2]);
  const double slope = glm::dot(direction, n), height = along * slope - glm::dot(w, n);
  // Within the ball |w| <= |along| + radius: the height's rounding is far below 1e-12 of it.
  const double excess =
      std::abs(height) - double(ball.slab) - 1e-12 * (std::abs(along) + double(ball.radius));
  return !(excess > 0.0 && excess * excess > slope * slope * half2);
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
