// Specification of the Cauchy kernel's closed-form fields (field/cauchy.hpp): point, segment
// and triangle values and gradients agree with independent adaptive quadrature of the
// definition (tests/reference/cauchy_reference.hpp) on random configurations, including p in
// and near the triangle's plane, above edges and vertices, far away, and slivers; and with
// the analytic limits of the infinite plane and the infinite line.
#include "field/cauchy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "reference/cauchy_reference.hpp"
#include "reference/checks.hpp"

namespace convray::field {
namespace {

constexpr unsigned long long kSeed = 0x6361756368793121ULL;  // "cauchy1!"
constexpr double kValueTolerance = 1e-10;    // times the plane's field pi / s^2 (triangles)
constexpr double kGradientTolerance = 1e-8;  // relative, floor pi / s (triangles)

using reference::format_double;
using reference::format_vec;

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}
Vec3 random_vec(std::mt19937_64& rng, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng), u(rng)};
}

struct TriangleCase {
  Vec3 p, a, b, c;
  double s = 1.0;
};

std::string describe(const TriangleCase& tc) {
  return "p = " + format_vec(tc.p) + ", a = " + format_vec(tc.a) + ", b = " + format_vec(tc.b) +
         ", c = " + format_vec(tc.c) + ", s = " + format_double(tc.s);
}

// Where p sits relative to the triangle: the configurations the closed form must survive.
enum class Place { near, in_plane, near_plane, above_edge, above_vertex, far, sliver };

TriangleCase make_case(std::mt19937_64& rng, Place place) {
  TriangleCase tc;
  tc.s = log_uniform(rng, 0.2, 5.0);
  const double size = log_uniform(rng, 0.1, 10.0) / tc.s;
  tc.a = random_vec(rng, size);
  tc.b = random_vec(rng, size);
  tc.c = random_vec(rng, size);
  if (place == Place::sliver) tc.c = 0.5 * (tc.a + tc.b) + 1e-4 * random_vec(rng, size);
  const Vec3 n = glm::normalize(glm::cross(tc.b - tc.a, tc.c - tc.a));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double wa = unit(rng), wb = unit(rng) * (1.0 - wa);
  const Vec3 inside = tc.a + wb * (tc.b - tc.a) + (1.0 - wa - wb) * (tc.c - tc.a);
  const double height = (unit(rng) - 0.5) * 4.0 / tc.s;
  switch (place) {
    case Place::near:
    case Place::sliver:
      tc.p = inside + random_vec(rng, 2.0 * size);
      break;
    case Place::in_plane: {
      const Vec3 q = tc.a + random_vec(rng, 2.0 * size);
      tc.p = q - glm::dot(q - tc.a, n) * n;
      break;
    }
    case Place::near_plane:
      tc.p = inside + n * (log_uniform(rng, 1e-9, 1e-3) / tc.s) * (unit(rng) < 0.5 ? -1.0 : 1.0);
      break;
    case Place::above_edge: {
      const double t = unit(rng) * 1.4 - 0.2;  // on the edge or on its line beyond the ends
      const double nudge = unit(rng) < 0.5 ? 0.0 : 1e-9 * size;
      tc.p = tc.a + t * (tc.b - tc.a) + nudge * glm::normalize(tc.c - tc.a) + height * n;
      break;
    }
    case Place::above_vertex:
      tc.p = tc.b + height * n;
      break;
    case Place::far:
      tc.p = inside + glm::normalize(random_vec(rng, 1.0)) * (log_uniform(rng, 5.0, 50.0) / tc.s);
      break;
  }
  return tc;
}

void check_triangle(const TriangleCase& tc) {
  const Triangle triangle{tc.a, tc.b, tc.c};
  const auto ref = reference::reference_cauchy_triangle(tc.p, tc.a, tc.b, tc.c, tc.s);
  ASSERT_TRUE(ref.converged) << describe(tc);
  const double plane = kPi / (tc.s * tc.s);
  const FieldSample sample = cauchy_triangle_field(tc.p, triangle, tc.s);
  EXPECT_LE(reference::value_error_ratio(sample.value, ref.value, kValueTolerance, plane), 1.0)
      << describe(tc) << "\nvalue " << format_double(sample.value) << ", reference "
      << format_double(ref.value);
  EXPECT_EQ(sample.value, cauchy_triangle_value(tc.p, triangle, tc.s)) << describe(tc);
  EXPECT_LE(reference::gradient_error_ratio(sample.gradient, ref.gradient, kGradientTolerance,
                                            kPi / tc.s),
            1.0)
      << describe(tc) << "\ngradient " << format_vec(sample.gradient) << ", reference "
      << format_vec(ref.gradient);
}

class CauchyTriangle : public ::testing::TestWithParam<Place> {};

TEST_P(CauchyTriangle, MatchesQuadrature) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + static_cast<unsigned>(GetParam()));
  for (int i = 0; i < 250; ++i) {
    check_triangle(make_case(rng, GetParam()));
    if (HasFailure()) return;  // one replayable case is enough
  }
}

INSTANTIATE_TEST_SUITE_P(Places, CauchyTriangle,
                         ::testing::Values(Place::near, Place::in_plane, Place::near_plane,
                                           Place::above_edge, Place::above_vertex, Place::far,
                                           Place::sliver));

TEST(CauchyTriangle, OrientationAndVertexOrderDoNotMatter) {
  const Vec3 a{0.1, -0.3, 0.2}, b{1.2, 0.4, -0.1}, c{-0.4, 0.9, 0.5}, p{0.3, 0.2, 0.7};
  const FieldSample ref = cauchy_triangle_field(p, {a, b, c}, 1.3);
  for (const Triangle& t : {Triangle{b, c, a}, Triangle{c, a, b}, Triangle{a, c, b}}) {
    const FieldSample other = cauchy_triangle_field(p, t, 1.3);
    EXPECT_NEAR(other.value, ref.value, 1e-15);
    EXPECT_NEAR(glm::length(other.gradient - ref.gradient), 0.0, 1e-14);
  }
}

TEST(CauchyTriangle, ZeroAreaGivesZero) {
  const Vec3 a{0.0}, b{1.0, 1.0, 0.0};
  EXPECT_EQ(cauchy_triangle_field({0.2, 0.3, 0.1}, {a, b, 0.5 * b}, 1.0).value, 0.0);
  EXPECT_EQ(cauchy_triangle_field({0.2, 0.3, 0.1}, {a, a, a}, 1.0).value, 0.0);
}

// A triangle so large that p sees an infinite plane: the neglected tail beyond the inscribed
// radius rho is pi / (s^2 (a + s^2 rho^2)), below 1e-12 of the plane's field here.
TEST(CauchyTriangle, LargeTriangleIsThePlane) {
  for (const double s : {0.3, 1.0, 4.0}) {
    const double big = 1e7 / s;
    const Triangle t{{-big, -big, 0.0}, {2.0 * big, -big, 0.0}, {-big, 2.0 * big, 0.0}};
    for (const double h : {0.0, 0.1 / s, 1.0 / s, 3.0 / s, -2.0 / s}) {
      const Vec3 p{0.3 / s, -0.2 / s, h};
      const FieldSample f = cauchy_triangle_field(p, t, s);
      const double a = 1.0 + s * s * h * h;
      const double plane = kPi / (s * s * a);
      EXPECT_NEAR(f.value, plane, 1e-11 * plane) << "s " << s << " h " << h;
      // d/dh of pi / (s^2 (1 + s^2 h^2)) = -2 pi h / a^2, along the normal only.
      EXPECT_NEAR(f.gradient.z, -2.0 * kPi * h / (a * a), 1e-10 * kPi / s);
      EXPECT_NEAR(f.gradient.x, 0.0, 1e-10 * kPi / s);
      EXPECT_NEAR(f.gradient.y, 0.0, 1e-10 * kPi / s);
      EXPECT_NEAR(cauchy_plane_value(h, s), plane, 1e-15 * plane);
    }
  }
}

// A segment long enough to be the infinite line: integral over x of (c + s^2 x^2)^-2 is
// pi / (2 s c^(3/2)) with c = 1 + s^2 q^2; the tails beyond X are below 1 / (3 s^4 X^3).
TEST(CauchySegment, LongSegmentIsTheLine) {
  for (const double s : {0.3, 1.0, 4.0}) {
    const double half = 1e6 / s;
    const Segment line{{-half, 0.0, 0.0}, {half, 0.0, 0.0}};
    for (const double q : {0.0, 0.2 / s, 1.0 / s, 5.0 / s}) {
      const Vec3 p{0.7 / s, q * 0.6, q * 0.8};
      const double c = 1.0 + s * s * q * q;
      const double expected = kPi / (2.0 * s * c * std::sqrt(c));
      const FieldSample f = cauchy_segment_field(p, line, s);
      EXPECT_NEAR(f.value, expected, 1e-12 * kPi / s) << "s " << s << " q " << q;
      // d/dq = -3 pi s q / (2 c^(5/2)), in the direction of p's offset from the line.
      const double slope = -3.0 * kPi * s * q / (2.0 * c * c * std::sqrt(c));
      EXPECT_NEAR(f.gradient.y, slope * 0.6, 1e-11 * kPi);
      EXPECT_NEAR(f.gradient.z, slope * 0.8, 1e-11 * kPi);
      EXPECT_NEAR(f.gradient.x, 0.0, 1e-11 * kPi);
    }
  }
}

TEST(CauchySegment, MatchesQuadrature) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + 100);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) {
    const double s = log_uniform(rng, 0.2, 5.0);
    const double size = log_uniform(rng, 0.01, 20.0) / s;
    const Segment seg{random_vec(rng, size), random_vec(rng, size)};
    Vec3 p;
    switch (i % 4) {
      case 0:  // anywhere near
        p = seg.a + random_vec(rng, 2.0 * size + 1.0 / s);
        break;
      case 1:  // on the segment's line, inside or beyond the ends
        p = seg.a + (unit(rng) * 3.0 - 1.0) * (seg.b - seg.a);
        break;
      case 2:  // above an end point
        p = seg.b + glm::cross(seg.b - seg.a, random_vec(rng, 1.0)) * (unit(rng) / size);
        break;
      default:  // far
        p = seg.a + glm::normalize(random_vec(rng, 1.0)) * (log_uniform(rng, 5.0, 50.0) / s);
    }
    const auto ref = reference::reference_cauchy_segment(p, seg.a, seg.b, s);
    ASSERT_TRUE(ref.converged);
    const FieldSample f = cauchy_segment_field(p, seg, s);
    const std::string where = "p = " + format_vec(p) + ", a = " + format_vec(seg.a) +
                              ", b = " + format_vec(seg.b) + ", s = " + format_double(s);
    EXPECT_LE(reference::value_error_ratio(f.value, ref.value, 1e-11, kPi / s), 1.0) << where;
    EXPECT_EQ(f.value, cauchy_segment_value(p, seg, s)) << where;
    EXPECT_LE(reference::gradient_error_ratio(f.gradient, ref.gradient, 1e-9, kPi), 1.0)
        << where << "\ngradient " << format_vec(f.gradient) << " reference "
        << format_vec(ref.gradient);
    if (HasFailure()) return;
  }
}

TEST(CauchyPoint, IsTheKernelWithItsGradient) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + 200);
  for (int i = 0; i < 1000; ++i) {
    const double s = log_uniform(rng, 0.2, 5.0);
    const Vec3 center = random_vec(rng, 3.0), p = center + random_vec(rng, 4.0 / s);
    const auto ref = reference::reference_cauchy_point(p, center, s);
    const FieldSample f = cauchy_point_field(p, center, s);
    EXPECT_NEAR(f.value, ref.value, 1e-15);
    EXPECT_EQ(f.value, cauchy_point_value(p, center, s));
    EXPECT_LE(glm::length(f.gradient - ref.gradient), 1e-14 * s);
  }
}

// The closed forms' gradients against finite differences of their own values: a second,
// weaker check that value and gradient describe the same function.
TEST(CauchyFields, GradientsMatchFiniteDifferences) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + 300);
  for (int i = 0; i < 300; ++i) {
    const double s = log_uniform(rng, 0.3, 3.0);
    const Triangle t{random_vec(rng, 2.0), random_vec(rng, 2.0), random_vec(rng, 2.0)};
    const Segment seg{t.a, t.b};
    const Vec3 p = random_vec(rng, 3.0);
    const auto tri_value = [&](const Vec3& q) { return cauchy_triangle_value(q, t, s); };
    const auto seg_value = [&](const Vec3& q) { return cauchy_segment_value(q, seg, s); };
    const auto tri_fd = reference::five_point_gradient(tri_value, p, 1e-3);
    const auto seg_fd = reference::five_point_gradient(seg_value, p, 1e-3);
    ASSERT_TRUE(tri_fd && seg_fd);
    EXPECT_LE(glm::length(cauchy_triangle_field(p, t, s).gradient - *tri_fd), 1e-7);
    EXPECT_LE(glm::length(cauchy_segment_field(p, seg, s).gradient - *seg_fd), 1e-7);
  }
}

TEST(CauchyKernel, SlopeBoundIsTheMaximumSlope) {
  for (const double s : {0.5, 1.0, 3.0}) {
    double largest = 0.0;
    for (int i = 0; i <= 200000; ++i) {
      const double r = i * 1e-5 * 4.0 / s;
      const double k = 1.0 / (1.0 + s * s * r * r);
      largest = std::max(largest, 4.0 * s * s * r * k * k * k);
    }
    EXPECT_GE(cauchy_kernel_slope_bound(s), largest);
    EXPECT_NEAR(cauchy_kernel_slope_bound(s), largest, 1e-8 * s);
    // Beyond rho: the largest slope at any r >= rho, by dense sampling.
    for (const double rho : {0.0, 0.1 / s, 0.4472 / s, 0.5 / s, 1.0 / s, 3.0 / s}) {
      double beyond = 0.0;
      for (int i = 0; i <= 200000; ++i) {
        const double r = rho + i * 1e-5 * 4.0 / s;
        const double k = 1.0 / (1.0 + s * s * r * r);
        beyond = std::max(beyond, 4.0 * s * s * r * k * k * k);
      }
      EXPECT_GE(cauchy_kernel_slope_beyond(rho, s), beyond * (1.0 - 1e-15)) << rho;
      EXPECT_NEAR(cauchy_kernel_slope_beyond(rho, s), beyond, 1e-8 * s) << rho;
    }
  }
}

}  // namespace
}  // namespace convray::field
