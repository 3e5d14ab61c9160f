// Specification of the circular-arc field: arc_value and arc_field agree with adaptive
// Gauss-Kronrod quadrature along the arc (tests/reference) on random arcs of every angle, with
// P anywhere including the arc's centre and axis; arc_through builds the arc through 3 points.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "field/arc.hpp"
#include "reference/checks.hpp"
#include "reference/ratio_check.hpp"
#include "reference/reference_fields.hpp"

namespace convray::field {
namespace {

constexpr unsigned long long kSeed = 0x6172632d61726331ULL;  // "arc-arc1"
constexpr int kCaseCount = 4000;
constexpr double kValueTolerance = 1e-10;    // times (16/15) R, the same line-integral scale
constexpr double kGradientTolerance = 1e-8;  // relative, floor 16/15
constexpr double kStencilMargin = 0.02;
constexpr double kStencilStep = 1e-4;
constexpr double kStencilReach = 100.0;  // stencil only with the whole arc within 100 R (rounding)
constexpr int kMinimumCasesPerKind = 50;

double line_scale(double radius) { return 16.0 / 15.0 * radius; }

// The documented arc point, computed here rather than through Arc::point_at.
Vec3 arc_point(const Arc& arc, double t) {
  return arc.center + arc.radius * (std::cos(t) * arc.start + std::sin(t) * glm::cross(arc.axis, arc.start));
}

struct ArcCase {
  Vec3 p;
  Arc arc;
  double radius = 1.0;
};

std::string describe(const ArcCase& ac) {
  return "p = " + reference::format_vec(ac.p) + ", arc{center = " + reference::format_vec(ac.arc.center) +
         ", axis = " + reference::format_vec(ac.arc.axis) + ", start = " + reference::format_vec(ac.arc.start) +
         ", radius = " + reference::format_double(ac.arc.radius) + ", angle = " +
         reference::format_double(ac.arc.angle) + "}, R = " + reference::format_double(ac.radius);
}

reference::ReferenceSample reference_for(const Vec3& p, const Arc& arc, double radius) {
  return reference::reference_arc(p, arc.center, arc.axis, arc.start, arc.radius, arc.angle, radius);
}

enum Kind {
  kFullCircle,
  kTinyAngle,
  kNearlyFullAngle,
  kPAtCentre,
  kPOnAxis,
  kPInArcPlane,
  kArcInsideSphere,
  kSphereCutsArc,
  kOutsideSupport,
  kEndPointOnSphere,
  kFarFromOrigin,
  kSmallArc,
  kLargeArc,
  kKindCount
};
constexpr const char* kKindNames[kKindCount] = {
    "full circle (angle = 2 pi)",  "tiny angle (< 1e-3)",        "nearly full (2 pi - angle < 1e-3)",
    "P at the arc's centre",       "P on the axis, off centre",  "P in the arc's plane",
    "arc inside the sphere",       "sphere cuts the arc",        "outside the support (F = 0)",
    "end point on the sphere",     "far from the origin (|P| > 100 R)", "arc radius < R/10",
    "arc radius > 10 R"};

// Independent classification: nearest and farthest points of the arc from P are its ends or
// the directions of P's projection on the arc's plane (and the opposite one), when inside.
std::array<bool, kKindCount> classify(const ArcCase& ac, double* smooth_margin) {
  std::array<bool, kKindCount> kind{};
  const Arc& arc = ac.arc;
  const double radius = ac.radius;
  kind[kFullCircle] = arc.angle == 2.0 * kPi;
  kind[kTinyAngle] = arc.angle < 1e-3;
  kind[kNearlyFullAngle] = !kind[kFullCircle] && 2.0 * kPi - arc.angle < 1e-3;
  kind[kFarFromOrigin] = glm::length(ac.p) > 100.0 * radius;
  kind[kSmallArc] = arc.radius < 0.1 * radius;
  kind[kLargeArc] = arc.radius > 10.0 * radius;
  const Vec3 d = ac.p - arc.center;
  const double height = glm::dot(d, arc.axis);
  const Vec3 planar = d - height * arc.axis;
  kind[kPAtCentre] = glm::length(d) <= 1e-12 * radius;
  kind[kPOnAxis] = !kind[kPAtCentre] && glm::length(planar) <= 1e-12 * radius;
  kind[kPInArcPlane] = std::abs(height) <= 1e-12 * radius;

  std::vector<double> candidates = {0.0, arc.angle};
  double phi = std::atan2(glm::dot(planar, glm::cross(arc.axis, arc.start)), glm::dot(planar, arc.start));
  for (double t : {phi, phi + kPi}) {
    t = std::fmod(t + 4.0 * kPi, 2.0 * kPi);
    if (t < arc.angle) candidates.push_back(t);
  }
  double nearest = INFINITY, farthest = 0.0, margin = INFINITY;
  for (double t : candidates) {
    const double distance = glm::length(ac.p - arc_point(arc, t));
    nearest = std::min(nearest, distance);
    farthest = std::max(farthest, distance);
    margin = std::min(margin, std::abs(distance - radius) / radius);
  }
  *smooth_margin = margin;
  for (double t : {0.0, arc.angle})
    kind[kEndPointOnSphere] =
        kind[kEndPointOnSphere] || std::abs(glm::length(ac.p - arc_point(arc, t)) - radius) <= 1e-9 * radius;
  if (farthest < radius) kind[kArcInsideSphere] = true;
  else if (nearest >= radius) kind[kOutsideSupport] = true;
  else kind[kSphereCutsArc] = true;
  return kind;
}

ArcCase make_case(std::mt19937_64& rng) {
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto unit = [&] {
    const double z = uniform(-1.0, 1.0), t = uniform(0.0, 2.0 * kPi), s = std::sqrt(1.0 - z * z);
    return Vec3(s * std::cos(t), s * std::sin(t), z);
  };
  ArcCase ac;
  ac.radius = std::pow(10.0, uniform(-3.0, 3.0));
  const double r = ac.radius;
  Arc& arc = ac.arc;
  arc.radius = r * std::pow(10.0, uniform(-3.0, 3.0));
  arc.axis = unit();
  arc.start = glm::normalize(glm::cross(arc.axis, unit()));
  const double angle_roll = uniform(0.0, 1.0);
  if (angle_roll < 0.15) arc.angle = 2.0 * kPi;
  else if (angle_roll < 0.25) arc.angle = std::pow(10.0, uniform(-8.0, -3.0));
  else if (angle_roll < 0.35) arc.angle = 2.0 * kPi - std::pow(10.0, uniform(-8.0, -3.0));
  else arc.angle = uniform(1e-3, 2.0 * kPi);
  arc.center = uniform(0.0, 1.0) < 0.3 ? unit() * r * std::pow(10.0, uniform(2.0, 4.0))
                                       : r * Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));

  const double mode = uniform(0.0, 1.0);
  if (mode < 0.1) {
    ac.p = arc.center;
  } else if (mode < 0.2) {
    ac.p = arc.center + uniform(-1.2 * r, 1.2 * r) * arc.axis;
  } else if (mode < 0.3) {
    const Vec3 in_plane = glm::normalize(glm::cross(arc.axis, unit()));
    ac.p = arc.center + uniform(0.0, arc.radius + 1.2 * r) * in_plane;
  } else if (mode < 0.4) {
    ac.p = arc_point(arc, uniform(0.0, 1.0) < 0.5 ? 0.0 : arc.angle) + r * unit();
  } else if (mode < 0.7) {
    ac.p = arc_point(arc, uniform(0.0, arc.angle)) + uniform(0.0, 1.3 * r) * unit();
  } else {
    ac.p = arc.center + std::cbrt(uniform(0.0, 1.0)) * (arc.radius + 1.2 * r) * unit();
  }
  return ac;
}

TEST(ArcField, MatchesQuadratureOnRandomArcsOfEveryKind) {
  const unsigned long long seed = reference::test_seed(kSeed);
  std::printf("[ arc ] seed 0x%llx (set CONVRAY_TEST_SEED to change)\n", seed);
  std::mt19937_64 rng(seed);
  std::array<int, kKindCount> count{};
  std::array<double, kKindCount> worst_by_kind{};
  reference::RatioCheck value("arc_value and arc_field value vs quadrature");
  reference::RatioCheck gradient("arc_field gradient vs quadrature");
  reference::RatioCheck stencil_check("arc_field gradient vs 5-point stencil");
  for (int i = 0; i < kCaseCount; ++i) {
    const ArcCase ac = make_case(rng);
    double margin = 0.0;
    const auto kind = classify(ac, &margin);
    const double scale = line_scale(ac.radius);
    const auto ref = reference_for(ac.p, ac.arc, ac.radius);
    ASSERT_TRUE(ref.converged) << describe(ac);
    const FieldSample sample = arc_field(ac.p, ac.arc, ac.radius);
    const double value_ratio =
        std::max(reference::value_error_ratio(arc_value(ac.p, ac.arc, ac.radius), ref.value, kValueTolerance, scale),
                 reference::value_error_ratio(sample.value, ref.value, kValueTolerance, scale));
    const double gradient_ratio =
        reference::gradient_error_ratio(sample.gradient, ref.gradient, kGradientTolerance, scale / ac.radius);
    value.add(value_ratio, describe(ac) + " (value " + reference::format_double(sample.value) + ", reference " +
                               reference::format_double(ref.value) + ")");
    gradient.add(gradient_ratio, describe(ac) + " (gradient " + reference::format_vec(sample.gradient) +
                                     ", reference " + reference::format_vec(ref.gradient) + ")");
    for (int k = 0; k < kKindCount; ++k) {
      count[k] += kind[k];
      if (kind[k]) worst_by_kind[k] = std::max({worst_by_kind[k], value_ratio, gradient_ratio});
    }

    const double reach = glm::length(ac.arc.center - ac.p) + ac.arc.radius;
    if (margin > kStencilMargin && reach <= kStencilReach * ac.radius) {
      const auto reference_value = [&](const Vec3& q) { return reference_for(q, ac.arc, ac.radius).value; };
      if (const auto stencil = reference::five_point_gradient(reference_value, ac.p, kStencilStep * ac.radius))
        stencil_check.add(
            reference::gradient_error_ratio(sample.gradient, *stencil, kGradientTolerance, scale / ac.radius),
            describe(ac));
    }
  }
  std::printf("[ arc ] %-40s %6s %12s\n", "kind", "cases", "worst ratio");
  for (int k = 0; k < kKindCount; ++k)
    std::printf("[ arc ] %-40s %6d %12.3g\n", kKindNames[k], count[k], worst_by_kind[k]);
  for (const reference::RatioCheck* check : {&value, &gradient, &stencil_check}) {
    std::printf("[ arc ] %-48s %5d cases, worst error/tolerance %.3g\n", check->what().c_str(), check->checked(),
                check->worst().ratio);
    check->expect_no_failure();
  }
  for (int k = 0; k < kKindCount; ++k) EXPECT_GE(count[k], kMinimumCasesPerKind) << kKindNames[k];
  EXPECT_GE(stencil_check.checked(), 500);
}

TEST(ArcField, AtTheCentreOfAPartialArcTheGradientIsFiniteAndRight) {
  for (double angle : {1e-6, 0.5, kPi, 4.0, 2.0 * kPi - 1e-6, 2.0 * kPi}) {
    const Arc arc{Vec3(1.0, -2.0, 0.5), Vec3(0.0, 0.0, 1.0), Vec3(1.0, 0.0, 0.0), 0.6, angle};
    for (const Vec3& p : {arc.center, arc.center + Vec3(0.0, 0.0, 0.3)}) {
      const FieldSample s = arc_field(p, arc, 1.0);
      const auto ref = reference_for(p, arc, 1.0);
      ASSERT_TRUE(std::isfinite(s.value) && std::isfinite(s.gradient.x) && std::isfinite(s.gradient.y) &&
                  std::isfinite(s.gradient.z))
          << "angle " << angle;
      EXPECT_NEAR(s.value, ref.value, 1e-13) << "angle " << angle;
      EXPECT_LE(reference::gradient_error_ratio(s.gradient, ref.gradient, kGradientTolerance, 16.0 / 15.0), 1.0)
          << "angle " << angle << " gradient " << reference::format_vec(s.gradient) << " reference "
          << reference::format_vec(ref.gradient);
    }
  }
}

TEST(ArcField, PointAtFollowsTheDocumentedParametrisation) {
  const Arc arc{Vec3(0.5, 1.0, -1.0), glm::normalize(Vec3(1.0, 2.0, 2.0)),
                glm::normalize(glm::cross(Vec3(1.0, 2.0, 2.0), Vec3(0.0, 0.0, 1.0))), 2.5, 5.0};
  for (double t : {0.0, 0.3, 1.0, 2.5, 5.0})
    EXPECT_LT(glm::length(arc.point_at(t) - arc_point(arc, t)), 1e-14) << "t = " << t;
}

TEST(ArcThrough, BuildsTheArcFromFirstThroughToLast) {
  std::mt19937_64 rng(reference::test_seed(kSeed) + 7);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (int i = 0; i < 500; ++i) {
    // Three points on a known circle, in order, at least 0.1 rad apart.
    const Vec3 axis = glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    const Vec3 start = glm::normalize(glm::cross(axis, Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))));
    const Arc circle{Vec3(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)), axis, start,
                     std::pow(10.0, uniform(-2.0, 2.0)), 2.0 * kPi};
    const double t0 = uniform(0.0, 2.0 * kPi);
    const double span = uniform(0.2, 2.0 * kPi - 0.1);
    const double t1 = t0 + uniform(0.1, span - 0.1);
    const Vec3 first = arc_point(circle, t0), through = arc_point(circle, t1), last = arc_point(circle, t0 + span);

    Arc built;
    ASSERT_TRUE(arc_through(first, through, last, built)) << i;
    const double tolerance = 1e-10 * circle.radius;
    EXPECT_NEAR(built.radius, circle.radius, tolerance) << i;
    EXPECT_LT(glm::length(built.center - circle.center), tolerance) << i;
    EXPECT_NEAR(glm::length(built.axis), 1.0, 1e-14);
    EXPECT_NEAR(glm::length(built.start), 1.0, 1e-14);
    EXPECT_NEAR(glm::dot(built.axis, built.start), 0.0, 1e-14);
    EXPECT_NEAR(built.angle, span, 1e-10) << i;
    EXPECT_LT(glm::length(arc_point(built, 0.0) - first), tolerance) << i;
    EXPECT_LT(glm::length(arc_point(built, built.angle) - last), tolerance) << i;
    EXPECT_LT(glm::length(arc_point(built, t1 - t0) - through), tolerance) << i;
  }
}

TEST(ArcThrough, RejectsCollinearAndCoincidentPoints) {
  Arc arc;
  EXPECT_FALSE(arc_through(Vec3(0.0), Vec3(1.0, 1.0, 1.0), Vec3(2.0, 2.0, 2.0), arc));
  EXPECT_FALSE(arc_through(Vec3(0.0), Vec3(2.0, 2.0, 2.0), Vec3(1.0, 1.0, 1.0), arc));
  EXPECT_FALSE(arc_through(Vec3(1.0, 0.0, 0.0), Vec3(-3.0, 0.0, 0.0), Vec3(7.0, 0.0, 0.0), arc));
  EXPECT_FALSE(arc_through(Vec3(1.0, 2.0, 3.0), Vec3(1.0, 2.0, 3.0), Vec3(4.0, 0.0, 0.0), arc));
  EXPECT_FALSE(arc_through(Vec3(1.0, 2.0, 3.0), Vec3(4.0, 0.0, 0.0), Vec3(1.0, 2.0, 3.0), arc));
  EXPECT_FALSE(arc_through(Vec3(1.0, 2.0, 3.0), Vec3(1.0, 2.0, 3.0), Vec3(1.0, 2.0, 3.0), arc));
}

}  // namespace
}  // namespace convray::field
