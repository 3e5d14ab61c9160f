// Specification by known closed values (DESIGN.md section 4) and by superposition:
//  - a triangle covering the whole disk is the infinite plane (pi/3) R^2 (1 - h^2/R^2)^3;
//  - a segment reaching past the sphere is the infinite line (16/15) R (1 - q^2/R^2)^(5/2);
//  - a full circle of radius a seen from its axis at height z: 2 pi a (1 - (a^2+z^2)/R^2)^2;
//  - the field is additive: a triangle split in two or three, a segment or an arc split in two,
//    sum to the whole within 1e-12 of the natural scale.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field/arc.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "reference/checks.hpp"

namespace convray::field {
namespace {

constexpr double kAnalyticTolerance = 1e-12;      // times the natural scale
constexpr double kSuperpositionTolerance = 1e-12;  // times the natural scale
constexpr double kGradientTolerance = 1e-8;       // relative, as everywhere

double plane_scale(double radius) { return kPi / 3.0 * radius * radius; }
double line_scale(double radius) { return 16.0 / 15.0 * radius; }

// --- Infinite plane -----------------------------------------------------------------------------

TEST(TriangleAnalytic, TriangleCoveringTheDiskIsTheInfinitePlane) {
  const Vec3 normal = glm::normalize(Vec3(1.0, -2.0, 0.5));
  const Vec3 e1 = glm::normalize(glm::cross(normal, Vec3(0.0, 0.0, 1.0)));
  const Vec3 e2 = glm::cross(normal, e1);
  for (double radius : {1e-3, 0.37, 1.0, 20.0, 1e3}) {
    const Vec3 origin = radius * Vec3(3.0, -1.0, 2.0);
    // Equilateral-ish, inradius 5 R around O (the disk never reaches an edge).
    const Triangle big{origin + radius * (10.0 * e1 - 6.0 * e2), origin + radius * (0.5 * e1 + 12.0 * e2),
                       origin + radius * (-11.0 * e1 - 7.0 * e2)};
    for (double h_over_r : {0.0, 0.1, -0.3, 0.5, 0.9, -0.999, 0.999999, 1.0, 1.5}) {
      const double h = h_over_r * radius;
      const Vec3 p = origin + radius * (0.3 * e1 - 0.2 * e2) + h * normal;
      const double inside = std::max(0.0, 1.0 - h_over_r * h_over_r);
      const double expected = plane_scale(radius) * inside * inside * inside;
      // d/dh of (pi/3) R^2 (1 - h^2/R^2)^3, along the normal.
      const Vec3 expected_gradient = plane_scale(radius) * 3.0 * inside * inside * (-2.0 * h / (radius * radius)) * normal;
      const FieldSample s = triangle_field(p, big, radius);
      EXPECT_LE(reference::value_error_ratio(s.value, expected, kAnalyticTolerance, plane_scale(radius)), 1.0)
          << "R = " << radius << ", h/R = " << h_over_r << ": " << s.value << " vs " << expected;
      EXPECT_LE(reference::value_error_ratio(triangle_value(p, big, radius), expected, kAnalyticTolerance,
                                             plane_scale(radius)),
                1.0)
          << "R = " << radius << ", h/R = " << h_over_r;
      EXPECT_LE(reference::gradient_error_ratio(s.gradient, expected_gradient, kGradientTolerance,
                                                plane_scale(radius) / radius),
                1.0)
          << "R = " << radius << ", h/R = " << h_over_r << ": " << reference::format_vec(s.gradient);
    }
  }
}

// --- Infinite line ------------------------------------------------------------------------------

TEST(SegmentAnalytic, SegmentReachingPastTheSphereIsTheInfiniteLine) {
  const Vec3 axis = glm::normalize(Vec3(2.0, 1.0, -1.0));
  const Vec3 across = glm::normalize(glm::cross(axis, Vec3(0.0, 1.0, 0.0)));
  for (double radius : {1e-3, 0.5, 1.0, 30.0, 1e3}) {
    const Vec3 a = radius * Vec3(-1.0, 4.0, 2.0) - 3.0 * radius * axis;
    const Segment segment{a, a + 7.0 * radius * axis};
    for (double q_over_r : {0.0, 0.2, 0.5, 0.9, 0.999, 1.0, 1.2}) {
      const Vec3 p = a + 3.5 * radius * axis + q_over_r * radius * across;
      const double inside = std::max(0.0, 1.0 - q_over_r * q_over_r);
      const double expected = line_scale(radius) * std::pow(inside, 2.5);
      // d/dq of (16/15) R (1 - q^2/R^2)^(5/2), away from the axis.
      const Vec3 expected_gradient =
          line_scale(radius) * 2.5 * std::pow(inside, 1.5) * (-2.0 * q_over_r / radius) * across;
      const FieldSample s = segment_field(p, segment, radius);
      EXPECT_LE(reference::value_error_ratio(s.value, expected, kAnalyticTolerance, line_scale(radius)), 1.0)
          << "R = " << radius << ", q/R = " << q_over_r << ": " << s.value << " vs " << expected;
      EXPECT_LE(reference::value_error_ratio(segment_value(p, segment, radius), expected, kAnalyticTolerance,
                                             line_scale(radius)),
                1.0);
      EXPECT_LE(reference::gradient_error_ratio(s.gradient, expected_gradient, kGradientTolerance,
                                                line_scale(radius) / radius),
                1.0)
          << "R = " << radius << ", q/R = " << q_over_r << ": " << reference::format_vec(s.gradient);
    }
  }
}

// --- Full circle seen from its axis -------------------------------------------------------------

TEST(ArcAnalytic, FullCircleSeenFromItsCentreAndAxis) {
  const Vec3 axis = glm::normalize(Vec3(0.3, -1.0, 0.4));
  const Vec3 start = glm::normalize(glm::cross(axis, Vec3(1.0, 0.0, 0.0)));
  for (double radius : {1e-3, 1.0, 250.0}) {
    for (double a_over_r : {0.01, 0.3, 0.7, 0.99, 1.0, 1.4}) {
      const Arc circle{radius * Vec3(2.0, 0.5, -1.0), axis, start, a_over_r * radius, 2.0 * kPi};
      for (double z_over_r : {0.0, 0.2, -0.5}) {
        // Every point of the circle is at distance s = sqrt(a^2 + z^2).
        const Vec3 p = circle.center + z_over_r * radius * axis;
        const double inside = std::max(0.0, 1.0 - a_over_r * a_over_r - z_over_r * z_over_r);
        const double expected = 2.0 * kPi * circle.radius * inside * inside;
        const Vec3 expected_gradient =
            2.0 * kPi * circle.radius * 2.0 * inside * (-2.0 * z_over_r / radius) * axis;
        const FieldSample s = arc_field(p, circle, radius);
        EXPECT_LE(reference::value_error_ratio(s.value, expected, kAnalyticTolerance, line_scale(radius)), 1.0)
            << "R = " << radius << ", a/R = " << a_over_r << ", z/R = " << z_over_r << ": " << s.value
            << " vs " << expected;
        EXPECT_LE(reference::value_error_ratio(arc_value(p, circle, radius), expected, kAnalyticTolerance,
                                               line_scale(radius)),
                  1.0);
        EXPECT_LE(reference::gradient_error_ratio(s.gradient, expected_gradient, kGradientTolerance,
                                                  line_scale(radius) / radius),
                  1.0)
            << "R = " << radius << ", a/R = " << a_over_r << ", z/R = " << z_over_r << ": "
            << reference::format_vec(s.gradient);
      }
    }
  }
}

// --- Superposition ------------------------------------------------------------------------------

struct Random {
  std::mt19937_64 rng;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vec3 in_box(double half) { return {uniform(-half, half), uniform(-half, half), uniform(-half, half)}; }
};

void expect_sums_to_whole(const FieldSample& whole, const FieldSample& sum, double scale, double radius,
                          const std::string& what) {
  EXPECT_LE(reference::value_error_ratio(sum.value, whole.value, kSuperpositionTolerance, scale), 1.0)
      << what << ": parts " << reference::format_double(sum.value) << " whole "
      << reference::format_double(whole.value);
  EXPECT_LE(reference::gradient_error_ratio(sum.gradient, whole.gradient, kGradientTolerance, scale / radius), 1.0)
      << what;
}

TEST(TriangleSuperposition, TriangleSplitInTwoOrThreeSumsToTheWhole) {
  Random random{std::mt19937_64(0x73706c6974ULL)};
  for (int i = 0; i < 2000; ++i) {
    const double radius = std::pow(10.0, random.uniform(-3.0, 3.0));
    const Triangle t{radius * random.in_box(1.5), radius * random.in_box(1.5), radius * random.in_box(1.5)};
    const Vec3 p = radius * random.in_box(1.2);
    const std::string what = "p = " + reference::format_vec(p) + ", a = " + reference::format_vec(t.a) +
                             ", b = " + reference::format_vec(t.b) + ", c = " + reference::format_vec(t.c) +
                             ", R = " + reference::format_double(radius);
    const FieldSample whole = triangle_field(p, t, radius);
    // In two, through a point on edge a-b.
    const Vec3 m = t.a + random.uniform(0.05, 0.95) * (t.b - t.a);
    FieldSample two = triangle_field(p, Triangle{t.a, m, t.c}, radius);
    two += triangle_field(p, Triangle{m, t.b, t.c}, radius);
    expect_sums_to_whole(whole, two, plane_scale(radius), radius, "split in two: " + what);
    // In three, through an interior point.
    const double u = random.uniform(0.05, 0.9), v = random.uniform(0.05, 0.95 - u);
    const Vec3 g = t.a + u * (t.b - t.a) + v * (t.c - t.a);
    FieldSample three = triangle_field(p, Triangle{t.a, t.b, g}, radius);
    three += triangle_field(p, Triangle{t.b, t.c, g}, radius);
    three += triangle_field(p, Triangle{t.c, t.a, g}, radius);
    expect_sums_to_whole(whole, three, plane_scale(radius), radius, "split in three: " + what);
    if (HasFailure()) return;
  }
}

TEST(SegmentSuperposition, SegmentSplitInTwoSumsToTheWhole) {
  Random random{std::mt19937_64(0x73706c6974ULL + 1)};
  for (int i = 0; i < 2000; ++i) {
    const double radius = std::pow(10.0, random.uniform(-3.0, 3.0));
    const Segment s{radius * random.in_box(2.0), radius * random.in_box(2.0)};
    const Vec3 p = radius * random.in_box(1.5);
    const Vec3 m = s.a + random.uniform(0.02, 0.98) * (s.b - s.a);
    FieldSample parts = segment_field(p, Segment{s.a, m}, radius);
    parts += segment_field(p, Segment{m, s.b}, radius);
    expect_sums_to_whole(segment_field(p, s, radius), parts, line_scale(radius), radius,
                         "p = " + reference::format_vec(p) + ", a = " + reference::format_vec(s.a) +
                             ", b = " + reference::format_vec(s.b) + ", m = " + reference::format_vec(m) +
                             ", R = " + reference::format_double(radius));
    if (HasFailure()) return;
  }
}

TEST(ArcSuperposition, ArcSplitInTwoSumsToTheWhole) {
  Random random{std::mt19937_64(0x73706c6974ULL + 2)};
  for (int i = 0; i < 2000; ++i) {
    const double radius = std::pow(10.0, random.uniform(-3.0, 3.0));
    const Vec3 axis = glm::normalize(random.in_box(1.0));
    const Vec3 start = glm::normalize(glm::cross(axis, random.in_box(1.0)));
    const Arc whole{radius * random.in_box(1.0), axis, start, radius * std::pow(10.0, random.uniform(-1.5, 0.7)),
                    random.uniform(0.01, 2.0 * kPi)};
    const Vec3 p = whole.center + (whole.radius + radius) * random.in_box(1.0);
    // The second part starts where the first ends: rotate start by the split angle.
    const double split = random.uniform(0.02, 0.98) * whole.angle;
    const Vec3 split_start = std::cos(split) * start + std::sin(split) * glm::cross(axis, start);
    FieldSample parts = arc_field(p, Arc{whole.center, axis, start, whole.radius, split}, radius);
    parts += arc_field(p, Arc{whole.center, axis, split_start, whole.radius, whole.angle - split}, radius);
    expect_sums_to_whole(arc_field(p, whole, radius), parts, line_scale(radius), radius,
                         "p = " + reference::format_vec(p) + ", center = " + reference::format_vec(whole.center) +
                             ", axis = " + reference::format_vec(axis) + ", start = " + reference::format_vec(start) +
                             ", arc radius = " + reference::format_double(whole.radius) + ", angle = " +
                             reference::format_double(whole.angle) + ", split = " + reference::format_double(split) +
                             ", R = " + reference::format_double(radius));
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace convray::field
