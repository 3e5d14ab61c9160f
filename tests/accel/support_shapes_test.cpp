// Supports against brute force: distances against dense sampling of the skeleton, and each
// span's ends against the distance function along the line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "accel/support_shapes.hpp"
#include "reference/random_vectors.hpp"

namespace convray::accel {
namespace {

using testing::random_point;
using testing::random_unit;

field::Arc random_arc(std::mt19937_64& rng) {
  field::Arc arc;
  arc.center = random_point(rng, 0.5);
  arc.axis = random_unit(rng);
  arc.start = glm::normalize(glm::cross(arc.axis, random_unit(rng)));
  std::uniform_real_distribution<double> u(0.2, 1.0);
  arc.radius = u(rng);
  arc.angle = 2.0 * kPi * u(rng);
  return arc;
}

// Squared distance to the skeleton by sampling it densely (an upper bound that converges).
double sampled_distance2(const Vec3& p, const field::Triangle& t) {
  double best = INFINITY;
  const int n = 200;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const Vec3 q = t.a + (double(i) / n) * (t.b - t.a) + (double(j) / n) * (t.c - t.a);
      best = std::min(best, glm::dot(p - q, p - q));
    }
  }
  return best;
}

double sampled_distance2(const Vec3& p, const field::Arc& arc) {
  double best = INFINITY;
  for (int i = 0; i <= 20000; ++i) {
    const Vec3 q = arc.point_at(arc.angle * i / 20000.0);
    best = std::min(best, glm::dot(p - q, p - q));
  }
  return best;
}

TEST(SupportShapes, TriangleDistanceMatchesDenseSampling) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const field::Triangle t{random_point(rng, 1), random_point(rng, 1), random_point(rng, 1)};
    const Vec3 p = random_point(rng, 1.5);
    const double exact = std::sqrt(distance2_to_triangle(p, t));
    const double sampled = std::sqrt(sampled_distance2(p, t));
    // The grid step is about 2 * 1.7 / 200: sampling overestimates by at most that.
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_NEAR(exact, sampled, 0.02) << trial;
  }
}

TEST(SupportShapes, ArcDistanceMatchesDenseSampling) {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 300; ++trial) {
    const field::Arc arc = random_arc(rng);
    const Vec3 p = random_point(rng, 1.5);
    const double exact = std::sqrt(distance2_to_arc(p, arc));
    const double sampled = std::sqrt(sampled_distance2(p, arc));
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_NEAR(exact, sampled, 1e-3) << trial;
  }
}

// Along the line, inside the span the distance is below R, at its ends it equals R, and a
// step outside it exceeds R; a line that misses has distance > R everywhere sampled.
template <class Distance2>
void check_span(const Span& span, const Vec3& o, const Vec3& d, double r, Distance2 distance2) {
  if (span.empty()) {
    for (int i = -4000; i <= 4000; ++i) {
      ASSERT_GT(distance2(o + (i * 1e-3) * d), r * r * (1 - 1e-9));
    }
    return;
  }
  EXPECT_NEAR(std::sqrt(distance2(o + span.enter * d)), r, 1e-9);
  EXPECT_NEAR(std::sqrt(distance2(o + span.exit * d)), r, 1e-9);
  for (int i = 1; i < 100; ++i) {
    const double t = span.enter + (span.exit - span.enter) * i / 100.0;
    EXPECT_LE(distance2(o + t * d), r * r * (1 + 1e-9));
  }
  EXPECT_GT(distance2(o + (span.enter - 1e-6) * d), r * r);
  EXPECT_GT(distance2(o + (span.exit + 1e-6) * d), r * r);
}

TEST(SupportShapes, SpansAreExactForSpheresCapsulesAndTriangles) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> radius(0.05, 0.8);
  int hits = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Vec3 o = random_point(rng, 2.0), d = random_unit(rng);
    const double r = radius(rng);
    const Vec3 c = random_point(rng, 1.0);
    const field::Segment s{random_point(rng, 1), random_point(rng, 1)};
    const field::Triangle t{random_point(rng, 1), random_point(rng, 1), random_point(rng, 1)};
    const Span a = sphere_span(o, d, c, r), b = capsule_span(o, d, s, r), e = triangle_span(o, d, t, r);
    hits += !a.empty() + !b.empty() + !e.empty();
    check_span(a, o, d, r, [&](const Vec3& p) { return glm::dot(p - c, p - c); });
    check_span(b, o, d, r, [&](const Vec3& p) { return distance2_to_segment(p, s); });
    check_span(e, o, d, r, [&](const Vec3& p) { return distance2_to_triangle(p, t); });
  }
  EXPECT_GT(hits, 150);  // both outcomes are exercised
}

// The bounding ball's test must keep every line that crosses the support within the asked
// range of t, grazing ones and far origins too (where the distance to the line loses digits to
// cancellation): the exact span against it, on lines aimed at the support's edge, over random
// ranges that overlap the span by little or miss it by little. It rejects lines outside the
// ball, outside the slab around the plane, and ranges beside the chord.
TEST(SupportShapes, BoundingBallKeepsEveryCrossingLine) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> radius(0.01, 0.8), unit(0.0, 1.0);
  int crossings = 0, grazing = 0, rejected = 0, in_range = 0, beside = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    const double r = radius(rng);
    const field::Triangle t{random_point(rng, 1), random_point(rng, 1),
                            trial % 7 ? random_point(rng, 1) : Vec3(0.0)};
    // Through a point about R from a point of the triangle, from up to 10^4 away.
    const Vec3 q = t.a + unit(rng) * (t.b - t.a) + unit(rng) * unit(rng) * (t.c - t.a);
    const Vec3 d = random_unit(rng);
    const Vec3 side = glm::normalize(glm::cross(d, random_unit(rng)));
    const Vec3 through = q + side * (r * (0.9 + 0.2 * unit(rng)));
    const Vec3 o = through - std::pow(10.0, 4.0 * unit(rng)) * d;
    const Span exact = triangle_span(o, d, t, r);
    const BoundingBall ball = triangle_bounding_ball(t, r);
    const bool line_kept = may_cross(o, d, -kInfinity, kInfinity, ball);
    rejected += !line_kept;
    if (exact.empty()) continue;
    ++crossings;
    grazing += exact.exit - exact.enter < 0.5 * r;  // a chord of a ball R: 0.03 R deep
    EXPECT_TRUE(line_kept) << trial;
    // A range ending before the span (within 1e-3 R, or within three times the ball's radius),
    // or starting after it, or overlapping it.
    const double gap = (trial % 2 ? 1e-3 * r : 3.0 * double(ball.radius)) * unit(rng);
    const double tmin = trial % 3 == 0 ? exact.exit + gap : exact.enter - r * unit(rng);
    const double tmax = trial % 3 == 1 ? exact.enter - gap : exact.exit + r * unit(rng);
    const bool meets = tmin <= exact.exit && exact.enter <= tmax;
    const bool kept = may_cross(o, d, tmin, tmax, ball);
    in_range += meets;
    beside += !meets && !kept;
    if (meets) EXPECT_TRUE(kept) << trial;
  }
  EXPECT_GT(crossings, 10000);
  EXPECT_GT(grazing, 100);
  EXPECT_GT(in_range, 3000);
  EXPECT_GT(rejected, 200);  // and it does reject lines
  EXPECT_GT(beside, 100);    // and ranges
}

// Lines through the ball that keep more than R from the triangle's plane (parallel to it, or
// crossing it outside the ball) are rejected by the slab; lines within it are kept.
TEST(SupportShapes, BoundingBallSlabRejectsLinesFarFromThePlane) {
  const double r = 0.1;
  const field::Triangle t{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const BoundingBall ball = triangle_bounding_ball(t, r);
  ASSERT_GT(ball.radius, 0.7f);
  const Vec3 center(ball.center[0], ball.center[1], ball.center[2]);
  // Parallel to the plane at heights 0.2 and 0.09 through the ball's centre.
  const Vec3 along = glm::normalize(Vec3(1, 1, 0));
  EXPECT_FALSE(may_cross(center + Vec3(0, 0, 0.2) - 5.0 * along, along, -kInfinity,
                         kInfinity, ball));
  EXPECT_TRUE(may_cross(center + Vec3(0, 0, 0.09) - 5.0 * along, along, -kInfinity,
                        kInfinity, ball));
  EXPECT_TRUE(triangle_span(center + Vec3(0, 0, 0.2) - 5.0 * along, along, t, r).empty());
  EXPECT_FALSE(triangle_span(center + Vec3(0, 0, 0.09) - 5.0 * along, along, t, r).empty());
  // Steep lines cross the slab wherever they cross the ball.
  EXPECT_TRUE(may_cross(center - 5.0 * Vec3(0, 0, 1), Vec3(0, 0, 1), -kInfinity,
                        kInfinity, ball));
  // A zero-area triangle has no slab: only its ball.
  const field::Triangle flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const BoundingBall line_ball = triangle_bounding_ball(flat, r);
  const Vec3 line_center(line_ball.center[0], line_ball.center[1], line_ball.center[2]);
  EXPECT_TRUE(may_cross(line_center + Vec3(0, 0, 0.5) - 5.0 * Vec3(1, 0, 0), Vec3(1, 0, 0),
                        -kInfinity, kInfinity, line_ball));
}

// The smallest ball around the triangle (the bounding ball's, before R): it holds every corner
// (to rounding), is never larger than the ball around the centroid, is half the longest side
// around that side's middle for an obtuse triangle, and the circumradius (a^2 b^2 c^2 over 16
// times the squared area, Heron's formula) for an acute one.
TEST(SupportShapes, BoundingBallIsTheSmallestAroundTheTriangle) {
  std::mt19937_64 rng(15);
  int obtuse = 0, acute = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = 0.1;
    const field::Triangle t{random_point(rng, 1), random_point(rng, 1),
                            trial % 5 ? random_point(rng, 1) : random_point(rng, 1e-3)};
    const SmallestBall smallest = triangle_smallest_ball(t);
    const double reach = smallest.reach;
    for (const Vec3& corner : {t.a, t.b, t.c}) {
      EXPECT_LE(glm::length(corner - smallest.center), reach * (1.0 + 1e-12)) << trial;
    }
    // Its float copy grown by R holds every corner's ball of radius R, and is as tight as
    // floats allow.
    const BoundingBall ball = triangle_bounding_ball(t, r);
    const Vec3 center(ball.center[0], ball.center[1], ball.center[2]);
    for (const Vec3& corner : {t.a, t.b, t.c}) {
      EXPECT_LE(glm::length(corner - center) + r, double(ball.radius)) << trial;
    }
    EXPECT_LE(double(ball.radius), (reach + r) * (1.0 + 1e-6)) << trial;
    const Vec3 centroid = (t.a + t.b + t.c) / 3.0;
    const double centroid_reach = std::max(
        {glm::length(t.a - centroid), glm::length(t.b - centroid), glm::length(t.c - centroid)});
    EXPECT_LE(reach, centroid_reach * (1.0 + 1e-12)) << trial;
    const double a2 = glm::dot(t.b - t.c, t.b - t.c), b2 = glm::dot(t.c - t.a, t.c - t.a),
                 c2 = glm::dot(t.a - t.b, t.a - t.b);
    const double longest2 = std::max({a2, b2, c2});
    if (2.0 * longest2 > a2 + b2 + c2 + 1e-9) {  // the longest side faces an obtuse angle
      ++obtuse;
      EXPECT_NEAR(reach, 0.5 * std::sqrt(longest2), 1e-12) << trial;
    } else if (2.0 * longest2 < a2 + b2 + c2 - 1e-3) {  // clearly acute
      ++acute;
      const double area4 = glm::length(glm::cross(t.b - t.a, t.c - t.a)) * 2.0;  // 4 * area
      const double circumradius = std::sqrt(a2 * b2 * c2) / area4;
      EXPECT_NEAR(reach, circumradius, 1e-9 * circumradius) << trial;
    }
  }
  EXPECT_GT(obtuse, 1000);
  EXPECT_GT(acute, 1000);
}

TEST(SupportShapes, ArcSpanHoldsTheWholeCrossing) {
  std::mt19937_64 rng(14);
  for (int trial = 0; trial < 300; ++trial) {
    const field::Arc arc = random_arc(rng);
    const Vec3 o = random_point(rng, 2.0), d = random_unit(rng);
    const double r = 0.3;
    const Span span = arc_span(o, d, arc, r);
    for (int i = -4000; i <= 4000; ++i) {
      const double t = i * 1e-3;
      if (distance2_to_arc(o + t * d, arc) < r * r) {
        ASSERT_FALSE(span.empty()) << trial;
        ASSERT_GE(t, span.enter);
        ASSERT_LE(t, span.exit);
      }
    }
  }
}

TEST(SupportShapes, DegenerateTrianglesAndSegmentsAreCapsules) {
  const field::Triangle flat{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const Span span = triangle_span({1, -5, 0.0}, {0, 1, 0}, flat, 0.5);
  EXPECT_NEAR(span.enter, 4.5, 1e-12);
  EXPECT_NEAR(span.exit, 5.5, 1e-12);
  const Span point = capsule_span({0, -5, 0}, {0, 1, 0}, {{0, 0, 0}, {0, 0, 0}}, 1.0);
  EXPECT_NEAR(point.enter, 4.0, 1e-12);
  EXPECT_NEAR(point.exit, 6.0, 1e-12);
  // A line along the capsule's axis.
  const Span along = capsule_span({-3, 0, 0}, {1, 0, 0}, {{0, 0, 0}, {2, 0, 0}}, 0.5);
  EXPECT_NEAR(along.enter, 2.5, 1e-12);
  EXPECT_NEAR(along.exit, 5.5, 1e-12);
}

}  // namespace
}  // namespace convray::accel
