// Specification of the segment field: segment_value and segment_field agree with adaptive
// Gauss-Kronrod quadrature along the segment (tests/reference) on random cases covering every
// way the support sphere can meet the segment, plus the degenerate ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <random>
#include <string>

#include "field/segment.hpp"
#include "reference/checks.hpp"
#include "reference/ratio_check.hpp"
#include "reference/reference_fields.hpp"

namespace convray::field {
namespace {

constexpr unsigned long long kSeed = 0x7365676d656e7431ULL;  // "segment1"
constexpr int kCaseCount = 4000;
constexpr double kValueTolerance = 1e-10;     // times (16/15) R, the infinite line's peak
constexpr double kGradientTolerance = 1e-8;   // relative, floor 16/15
constexpr double kStencilMargin = 0.02;
constexpr double kStencilStep = 1e-4;
constexpr double kStencilReach = 100.0;  // stencil only with both ends within 100 R (rounding)
constexpr int kMinimumCasesPerKind = 50;

double line_scale(double radius) { return 16.0 / 15.0 * radius; }

struct SegmentCase {
  Vec3 p, a, b;
  double radius = 1.0;
};

std::string describe(const SegmentCase& sc) {
  return "p = " + reference::format_vec(sc.p) + ", a = " + reference::format_vec(sc.a) +
         ", b = " + reference::format_vec(sc.b) + ", R = " + reference::format_double(sc.radius);
}

enum Kind {
  kZeroLength,
  kLineMissesSphere,
  kSphereBesideLineBeyondEnds,
  kSegmentInsideSphere,
  kSphereInsideSegmentSpan,
  kSphereCoversOneEnd,
  kPOnLine,
  kEndpointOnSphere,
  kFarFromOrigin,
  kKindCount
};
constexpr const char* kKindNames[kKindCount] = {
    "zero-length segment",       "line misses the sphere",        "sphere beside the line, past the ends",
    "segment inside the sphere", "sphere inside the segment span", "sphere covers one end",
    "P on the segment's line",   "end point on the sphere",       "far from the origin (|P| > 100 R)"};

// Independent classification from the support interval [along - w, along + w] against [0, L].
std::array<bool, kKindCount> classify(const SegmentCase& sc, double* smooth_margin) {
  std::array<bool, kKindCount> kind{};
  const double radius = sc.radius;
  kind[kFarFromOrigin] = glm::length(sc.p) > 100.0 * radius;
  const Vec3 span = sc.b - sc.a;
  const double length = glm::length(span);
  *smooth_margin = 0.0;
  if (length == 0.0) {
    kind[kZeroLength] = true;
    return kind;
  }
  const Vec3 d = sc.p - sc.a;
  const double along = glm::dot(d, span) / length;
  const double across = glm::length(glm::cross(d, span)) / length;
  kind[kPOnLine] = across <= 1e-12 * radius;
  const double to_a = glm::length(sc.p - sc.a), to_b = glm::length(sc.p - sc.b);
  kind[kEndpointOnSphere] = std::min(std::abs(to_a - radius), std::abs(to_b - radius)) <= 1e-9 * radius;
  const double to_segment = glm::length(d - std::clamp(along, 0.0, length) * span / length);
  *smooth_margin = std::min({std::abs(to_a - radius), std::abs(to_b - radius),
                             std::abs(to_segment - radius)}) / radius;
  if (across >= radius) {
    kind[kLineMissesSphere] = true;
    return kind;
  }
  const double w = std::sqrt(radius * radius - across * across);
  const double enter = along - w, leave = along + w;
  if (leave <= 0.0 || enter >= length) kind[kSphereBesideLineBeyondEnds] = true;
  else if (enter <= 0.0 && leave >= length) kind[kSegmentInsideSphere] = true;
  else if (enter > 0.0 && leave < length) kind[kSphereInsideSegmentSpan] = true;
  else kind[kSphereCoversOneEnd] = true;
  return kind;
}

SegmentCase make_case(std::mt19937_64& rng) {
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto unit = [&] {
    const double z = uniform(-1.0, 1.0), t = uniform(0.0, 2.0 * kPi), s = std::sqrt(1.0 - z * z);
    return Vec3(s * std::cos(t), s * std::sin(t), z);
  };
  SegmentCase sc;
  sc.radius = std::pow(10.0, uniform(-3.0, 3.0));
  const double r = sc.radius;
  const double length = r * std::pow(10.0, uniform(-3.0, 3.0));
  const double roll = uniform(0.0, 1.0);
  const Vec3 origin = roll < 0.3 ? unit() * r * std::pow(10.0, uniform(2.0, 4.0))
                                 : r * Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
  const double mode = uniform(0.0, 1.0);
  if (mode < 0.08) {  // P exactly on an axis-aligned line: dyadic R, integer-grid coordinates
    const double unit_length = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(r))) - 4);
    const int axis = static_cast<int>(uniform(0.0, 3.0));
    Vec3 base = glm::round(origin / unit_length) * unit_length;
    sc.radius = 16.0 * unit_length;
    sc.a = base;
    sc.b = base;
    sc.b[axis] += unit_length * std::round(uniform(1.0, 200.0));
    sc.p = base;
    sc.p[axis] += unit_length * std::round(uniform(-40.0, 240.0));
    return sc;
  }
  const Vec3 u = unit();
  const Vec3 perp = glm::normalize(glm::cross(u, unit()));
  sc.a = origin;
  sc.b = mode < 0.14 ? origin : origin + length * u;  // zero length
  if (mode < 0.24) {  // P on the line, up to rounding
    sc.p = origin + uniform(-1.5 * r, length + 1.5 * r) * u;
  } else if (mode < 0.34) {  // an end point on the sphere
    sc.p = (uniform(0.0, 1.0) < 0.5 ? sc.a : sc.b) + r * unit();
  } else {
    sc.p = origin + uniform(-1.5 * r, length + 1.5 * r) * u + r * uniform(0.0, 1.2) * perp;
  }
  return sc;
}

TEST(SegmentField, MatchesQuadratureOnRandomCasesOfEveryKind) {
  const unsigned long long seed = reference::test_seed(kSeed);
  std::printf("[ segment ] seed 0x%llx (set CONVRAY_TEST_SEED to change)\n", seed);
  std::mt19937_64 rng(seed);
  std::array<int, kKindCount> count{};
  std::array<double, kKindCount> worst_by_kind{};
  reference::RatioCheck value("segment_value and segment_field value vs quadrature");
  reference::RatioCheck gradient("segment_field gradient vs quadrature");
  reference::RatioCheck stencil_check("segment_field gradient vs 5-point stencil");
  for (int i = 0; i < kCaseCount; ++i) {
    const SegmentCase sc = make_case(rng);
    double margin = 0.0;
    const auto kind = classify(sc, &margin);
    const Segment segment{sc.a, sc.b};
    const double scale = line_scale(sc.radius);
    const auto ref = reference::reference_segment(sc.p, sc.a, sc.b, sc.radius);
    ASSERT_TRUE(ref.converged) << describe(sc);
    const FieldSample sample = segment_field(sc.p, segment, sc.radius);
    const double value_ratio = std::max(
        reference::value_error_ratio(segment_value(sc.p, segment, sc.radius), ref.value, kValueTolerance, scale),
        reference::value_error_ratio(sample.value, ref.value, kValueTolerance, scale));
    const double gradient_ratio =
        reference::gradient_error_ratio(sample.gradient, ref.gradient, kGradientTolerance, scale / sc.radius);
    value.add(value_ratio, describe(sc) + " (reference " + reference::format_double(ref.value) + ")");
    gradient.add(gradient_ratio, describe(sc));
    for (int k = 0; k < kKindCount; ++k) {
      count[k] += kind[k];
      if (kind[k]) worst_by_kind[k] = std::max({worst_by_kind[k], value_ratio, gradient_ratio});
    }
    if (kind[kZeroLength]) {
      EXPECT_EQ(sample.value, 0.0) << describe(sc);
    }

    const double reach = std::max(glm::length(sc.a - sc.p), glm::length(sc.b - sc.p));
    if (margin > kStencilMargin && reach <= kStencilReach * sc.radius) {
      const auto reference_value = [&](const Vec3& q) {
        return reference::reference_segment(q, sc.a, sc.b, sc.radius).value;
      };
      if (const auto stencil = reference::five_point_gradient(reference_value, sc.p, kStencilStep * sc.radius))
        stencil_check.add(
            reference::gradient_error_ratio(sample.gradient, *stencil, kGradientTolerance, scale / sc.radius),
            describe(sc));
    }
  }
  std::printf("[ segment ] %-40s %6s %12s\n", "kind", "cases", "worst ratio");
  for (int k = 0; k < kKindCount; ++k)
    std::printf("[ segment ] %-40s %6d %12.3g\n", kKindNames[k], count[k], worst_by_kind[k]);
  for (const reference::RatioCheck* check : {&value, &gradient, &stencil_check}) {
    std::printf("[ segment ] %-52s %5d cases, worst error/tolerance %.3g\n", check->what().c_str(),
                check->checked(), check->worst().ratio);
    check->expect_no_failure();
  }
  for (int k = 0; k < kKindCount; ++k) EXPECT_GE(count[k], kMinimumCasesPerKind) << kKindNames[k];
  EXPECT_GE(stencil_check.checked(), 500);
}

TEST(SegmentField, ZeroLengthSegmentGivesZero) {
  const Vec3 a(1.0, 2.0, 3.0);
  const FieldSample s = segment_field(a + Vec3(0.1, 0.0, 0.0), Segment{a, a}, 1.0);
  EXPECT_EQ(s.value, 0.0);
  EXPECT_EQ(s.gradient, Vec3(0.0));
  EXPECT_EQ(segment_value(a, Segment{a, a}, 1.0), 0.0);
}

TEST(SegmentField, OnTheSegmentItselfTheGradientPointsAlongTheAxisOnly) {
  // At the middle of a segment shorter than 2R, symmetry leaves no gradient at all; near an
  // end it points away from the segment's bulk, along the axis.
  const Segment segment{Vec3(-0.5, 0.0, 0.0), Vec3(0.5, 0.0, 0.0)};
  const FieldSample middle = segment_field(Vec3(0.0), segment, 1.0);
  EXPECT_NEAR(glm::length(middle.gradient), 0.0, 1e-14);
  const FieldSample near_end = segment_field(Vec3(0.4, 0.0, 0.0), segment, 1.0);
  const auto ref = reference::reference_segment(Vec3(0.4, 0.0, 0.0), segment.a, segment.b, 1.0);
  EXPECT_LT(near_end.gradient.x, 0.0);
  EXPECT_EQ(near_end.gradient.y, 0.0);
  EXPECT_EQ(near_end.gradient.z, 0.0);
  EXPECT_NEAR(near_end.gradient.x, ref.gradient.x, 1e-12);
  EXPECT_NEAR(near_end.value, ref.value, 1e-13);
}

TEST(SegmentField, ReversingTheSegmentChangesNothing) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + 1);
  for (int i = 0; i < 200; ++i) {
    const SegmentCase sc = make_case(rng);
    const FieldSample forward = segment_field(sc.p, Segment{sc.a, sc.b}, sc.radius);
    const FieldSample backward = segment_field(sc.p, Segment{sc.b, sc.a}, sc.radius);
    const double scale = line_scale(sc.radius);
    EXPECT_LE(reference::value_error_ratio(forward.value, backward.value, 1e-12, scale), 1.0) << describe(sc);
    EXPECT_LE(reference::gradient_error_ratio(forward.gradient, backward.gradient, 1e-10, scale / sc.radius), 1.0)
        << describe(sc);
  }
}

}  // namespace
}  // namespace convray::field
