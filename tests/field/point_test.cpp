// Specification of the point field: the quartic kernel (1 - d^2/R^2)^2 itself, exact to 1e-14,
// with the exact gradient -(4/R^2) (1 - d^2/R^2) (P - C), and 0 beyond R.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "field/point.hpp"
#include "reference/checks.hpp"
#include "reference/ratio_check.hpp"
#include "reference/reference_fields.hpp"

namespace convray::field {
namespace {

constexpr unsigned long long kSeed = 0x706f696e742d3031ULL;  // "point-01"
constexpr int kCaseCount = 3000;
constexpr double kValueTolerance = 1e-14;    // absolute: the kernel peaks at 1
constexpr double kGradientTolerance = 1e-8;  // relative, floor 1/R
constexpr double kStencilMargin = 0.02;
constexpr double kStencilStep = 1e-4;

std::string describe(const Vec3& p, const Vec3& center, double radius) {
  return "p = " + reference::format_vec(p) + ", center = " + reference::format_vec(center) +
         ", R = " + reference::format_double(radius);
}

TEST(PointField, IsTheKernelOnRandomPoints) {
  const unsigned long long seed = reference::test_seed(kSeed);
  std::printf("[ point ] seed 0x%llx (set CONVRAY_TEST_SEED to change)\n", seed);
  std::mt19937_64 rng(seed);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int inside = 0, outside = 0, at_centre = 0;
  reference::RatioCheck value("point_value and point_field value vs kernel");
  reference::RatioCheck gradient("point_field gradient vs kernel gradient");
  reference::RatioCheck stencil_check("point_field gradient vs 5-point stencil");
  for (int i = 0; i < kCaseCount; ++i) {
    const double radius = std::pow(10.0, uniform(-3.0, 3.0));
    const Vec3 center =
        uniform(0.0, 1.0) < 0.3
            ? radius * std::pow(10.0, uniform(2.0, 4.0)) *
                  glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)))
            : radius * Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
    const Vec3 direction = glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    const Vec3 p = uniform(0.0, 1.0) < 0.05 ? center : center + radius * uniform(0.0, 1.3) * direction;
    const std::string inputs = describe(p, center, radius);
    const auto ref = reference::reference_point(p, center, radius);
    const FieldSample sample = point_field(p, center, radius);
    value.add(std::max(reference::value_error_ratio(point_value(p, center, radius), ref.value, kValueTolerance, 1.0),
                       reference::value_error_ratio(sample.value, ref.value, kValueTolerance, 1.0)),
              inputs);
    gradient.add(reference::gradient_error_ratio(sample.gradient, ref.gradient, kGradientTolerance, 1.0 / radius),
                 inputs);
    const double distance = glm::length(p - center);
    at_centre += p == center;
    (distance < radius ? inside : outside) += 1;

    if (std::abs(distance - radius) > kStencilMargin * radius) {
      const auto kernel = [&](const Vec3& q) { return reference::reference_point(q, center, radius).value; };
      if (const auto stencil = reference::five_point_gradient(kernel, p, kStencilStep * radius))
        stencil_check.add(
            reference::gradient_error_ratio(sample.gradient, *stencil, kGradientTolerance, 1.0 / radius), inputs);
    }
  }
  std::printf("[ point ] %d inside, %d outside, %d at the centre\n", inside, outside, at_centre);
  for (const reference::RatioCheck* check : {&value, &gradient, &stencil_check}) {
    std::printf("[ point ] %-46s %5d cases, worst error/tolerance %.3g\n", check->what().c_str(), check->checked(),
                check->worst().ratio);
    check->expect_no_failure();
  }
  EXPECT_GE(inside, 1000);
  EXPECT_GE(outside, 300);
  EXPECT_GE(at_centre, 50);
  EXPECT_GE(stencil_check.checked(), 1000);
}

TEST(PointField, KnownValues) {
  const Vec3 c(1.0, -2.0, 3.0);
  const double r = 2.0;
  EXPECT_EQ(point_value(c, c, r), 1.0);
  EXPECT_EQ(point_field(c, c, r).gradient, Vec3(0.0));
  EXPECT_NEAR(point_value(c + Vec3(1.0, 0.0, 0.0), c, r), 9.0 / 16.0, 1e-15);  // d = R/2
  // gradient at d = R/2 along x: -(4/R^2)(3/4)(1) = -3/4
  const FieldSample half = point_field(c + Vec3(1.0, 0.0, 0.0), c, r);
  EXPECT_NEAR(half.gradient.x, -0.75, 1e-15);
  EXPECT_EQ(half.gradient.y, 0.0);
  EXPECT_EQ(half.gradient.z, 0.0);
  EXPECT_EQ(point_value(c + Vec3(0.0, 2.0, 0.0), c, r), 0.0);   // d = R
  EXPECT_EQ(point_value(c + Vec3(0.0, 0.0, 2.5), c, r), 0.0);   // beyond R
  EXPECT_EQ(point_field(c + Vec3(0.0, 0.0, 2.5), c, r).gradient, Vec3(0.0));
}

}  // namespace
}  // namespace convray::field
