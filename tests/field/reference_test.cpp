// The references themselves are checked before anything is checked against them: the
// quadrature on known integrals, the reference fields on the analytic values of DESIGN.md
// section 4, the polar triangle quadrature against an unrelated (collapsed Gauss product) rule
// where the integrand is a polynomial, superposition, and gradients against the stencil.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reference/checks.hpp"
#include "reference/quadrature.hpp"
#include "reference/reference_fields.hpp"

namespace convray::reference {
namespace {

constexpr double kSelfTolerance = 1e-13;  // times the natural scale: well below the tests' 1e-10

TEST(Quadrature, IntegratesKnownFunctionsToFullPrecision) {
  const double tolerance = 1e-14;
  // A square-root end point singularity, a kink at a breakpoint, a smooth oscillation.
  const auto sqrt_integrand = [](double x) { return Vec4(std::sqrt(x), std::abs(x - 0.3), std::cos(20.0 * x), 1.0); };
  const double breakpoint[] = {0.3};
  const QuadratureResult r = integrate_adaptive(sqrt_integrand, 0.0, 1.0, breakpoint, tolerance);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.integral.x, 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.integral.y, 0.5 * 0.3 * 0.3 + 0.5 * 0.7 * 0.7, 1e-15);
  EXPECT_NEAR(r.integral.z, std::sin(20.0) / 20.0, 1e-15);
  EXPECT_NEAR(r.integral.w, 1.0, 1e-15);
}

TEST(Quadrature, GaussLegendreIsExactForItsDegree) {
  for (int points : {4, 8}) {
    const GaussLegendreRule rule = gauss_legendre(points);
    double sum = 0.0;
    for (std::size_t k = 0; k < rule.nodes.size(); ++k) sum += rule.weights[k] * std::pow(rule.nodes[k], 2 * points - 2);
    EXPECT_NEAR(sum, 2.0 / (2 * points - 1), 1e-15) << points;
  }
}

TEST(ReferenceFields, ReproduceTheAnalyticValues) {
  const double radius = 1.7;
  for (double h : {0.0, 0.4, 1.1, 1.69}) {  // plane
    const auto s = reference_triangle(Vec3(0.1, 0.2, h), Vec3(-50, -50, 0), Vec3(60, -40, 0), Vec3(0, 70, 0), radius);
    const double inside = 1.0 - h * h / (radius * radius);
    EXPECT_NEAR(s.value, kPi / 3.0 * radius * radius * inside * inside * inside, kSelfTolerance * radius * radius);
    EXPECT_NEAR(s.gradient.z, kPi / 3.0 * radius * radius * 3.0 * inside * inside * (-2.0 * h / (radius * radius)),
                kSelfTolerance * radius);
  }
  for (double q : {0.0, 0.7, 1.5}) {  // line
    const auto s = reference_segment(Vec3(0.3, q, 0.0), Vec3(-20, 0, 0), Vec3(25, 0, 0), radius);
    EXPECT_NEAR(s.value, 16.0 / 15.0 * radius * std::pow(1.0 - q * q / (radius * radius), 2.5), kSelfTolerance * radius);
  }
  for (double a : {0.1, 1.0, 1.6}) {  // circle, from its centre
    const auto s = reference_arc(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(0, 0, 1), Vec3(1, 0, 0), a, 2.0 * kPi, radius);
    const double inside = 1.0 - a * a / (radius * radius);
    EXPECT_NEAR(s.value, 2.0 * kPi * a * inside * inside, kSelfTolerance * radius);
    EXPECT_NEAR(glm::length(s.gradient), 0.0, kSelfTolerance);
  }
  const auto point = reference_point(Vec3(0.5, 0.0, 0.0), Vec3(0.0), 1.0);
  EXPECT_EQ(point.value, 0.5625);
}

// Collapsed (Duffy) Gauss product rule: Q = a + u (b - a) + v (1 - u) (c - a), dA = 2A (1 - u).
// Exact for the kernel's polynomial when the whole triangle is inside the support sphere.
ReferenceSample product_rule_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double radius) {
  const GaussLegendreRule rule = gauss_legendre(8);
  const double twice_area = glm::length(glm::cross(b - a, c - a));
  ReferenceSample sum;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      const double u = 0.5 * (rule.nodes[i] + 1.0), v = 0.5 * (rule.nodes[j] + 1.0);
      const double weight = 0.25 * rule.weights[i] * rule.weights[j] * twice_area * (1.0 - u);
      const Vec3 q = a + u * (b - a) + v * (1.0 - u) * (c - a);
      const double inside = 1.0 - glm::dot(p - q, p - q) / (radius * radius);
      sum.value += weight * inside * inside;
      sum.gradient += weight * (-4.0 / (radius * radius)) * inside * (p - q);
    }
  }
  return sum;
}

TEST(ReferenceFields, PolarTriangleQuadratureMatchesAProductRuleInsideTheSphere) {
  std::mt19937_64 rng(42);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (int i = 0; i < 500; ++i) {
    const double radius = std::pow(10.0, uniform(-3.0, 3.0));
    const Vec3 p = radius * Vec3(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5));
    std::array<Vec3, 3> v;
    for (Vec3& x : v) {  // within 0.95 R of p
      Vec3 d;
      do d = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      while (glm::length(d) > 0.95);
      x = p + radius * d;
    }
    const auto polar = reference_triangle(p, v[0], v[1], v[2], radius);
    const auto product = product_rule_triangle(p, v[0], v[1], v[2], radius);
    const double scale = kPi / 3.0 * radius * radius;
    EXPECT_LE(value_error_ratio(polar.value, product.value, kSelfTolerance, scale), 1.0) << i;
    EXPECT_LE(gradient_error_ratio(polar.gradient, product.gradient, 1e-12, scale / radius), 1.0) << i;
  }
}

TEST(ReferenceFields, TriangleQuadratureIsAdditive) {
  std::mt19937_64 rng(43);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (int i = 0; i < 500; ++i) {
    const Vec3 a(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-0.5, 0.5));
    const Vec3 b(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-0.5, 0.5));
    const Vec3 c(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-0.5, 0.5));
    const Vec3 p(uniform(-1.2, 1.2), uniform(-1.2, 1.2), uniform(-0.8, 0.8));
    const Vec3 g = (a + b + c) / 3.0;
    const double parts = reference_triangle(p, a, b, g, 1.0).value + reference_triangle(p, b, c, g, 1.0).value +
                         reference_triangle(p, c, a, g, 1.0).value;
    EXPECT_NEAR(parts, reference_triangle(p, a, b, c, 1.0).value, kSelfTolerance) << i;
  }
}

TEST(ReferenceFields, SegmentAndArcGradientsMatchTheStencil) {
  std::mt19937_64 rng(44);
  auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (int i = 0; i < 300; ++i) {
    const Vec3 a(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)), b(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    const Vec3 p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    const auto segment = [&](const Vec3& q) { return reference_segment(q, a, b, 1.0).value; };
    const auto arc = [&](const Vec3& q) {
      return reference_arc(q, a, Vec3(0, 0, 1), Vec3(1, 0, 0), 0.8, 4.0, 1.0).value;
    };
    // Points near a non-smooth place give a poorer stencil: demand only 1e-6 here.
    EXPECT_LE(gradient_error_ratio(reference_segment(p, a, b, 1.0).gradient, *five_point_gradient(segment, p, 1e-4),
                                   1e-6, 16.0 / 15.0),
              1.0);
    EXPECT_LE(gradient_error_ratio(reference_arc(p, a, Vec3(0, 0, 1), Vec3(1, 0, 0), 0.8, 4.0, 1.0).gradient,
                                   *five_point_gradient(arc, p, 1e-4), 1e-6, 16.0 / 15.0),
              1.0);
  }
}

}  // namespace
}  // namespace convray::reference
