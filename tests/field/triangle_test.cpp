// Specification of the triangle field: triangle_value and triangle_field agree with the
// independent polar quadrature (tests/reference) on more than 10,000 random cases that cover
// every configuration of the clipping circle against the triangle (paper Fig. 1) and every
// degenerate position, shape and scale; the coverage is classified independently and asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "field/triangle.hpp"
#include "reference/checks.hpp"
#include "reference/ratio_check.hpp"
#include "reference/reference_fields.hpp"
#include "reference/triangle_cases.hpp"

namespace convray::field {
namespace {

using reference::TriangleCase;
using reference::TriangleFeature;

constexpr unsigned long long kSeed = 0x7269616e676c6531ULL;  // "riangle1"
constexpr int kCasesPerGenerator = 700;                       // 19 generators: 13,300 cases
constexpr double kValueTolerance = 1e-10;                     // times (pi/3) R^2
constexpr double kGradientTolerance = 1e-8;                   // relative, floor (pi/3) R
constexpr double kStencilMargin = 0.02;  // stencil only where the field is smooth within 0.02 R
constexpr double kStencilStep = 1e-4;    // times R
// The stencil divides rounding noise of order eps * |V - P| by the step, so it is only
// meaningful where every vertex is within 100 R of P.
constexpr double kStencilReach = 100.0;  // times R
constexpr int kMinimumCasesPerFeature = 100;

double plane_scale(double radius) { return kPi / 3.0 * radius * radius; }

std::string describe(const TriangleCase& tc) {
  return "generator \"" + std::string(tc.generator) + "\": p = " + reference::format_vec(tc.p) +
         ", a = " + reference::format_vec(tc.a) + ", b = " + reference::format_vec(tc.b) +
         ", c = " + reference::format_vec(tc.c) + ", R = " + reference::format_double(tc.radius);
}

struct CaseResult {
  TriangleCase input;
  reference::TriangleClassification classification;
  double reference_value = 0.0;
  bool reference_converged = true;
  double value_ratio = 0.0;          // triangle_value
  double field_value_ratio = 0.0;    // triangle_field().value
  double gradient_ratio = 0.0;       // triangle_field().gradient vs quadrature gradient
  double stencil_ratio = -1.0;       // triangle_field().gradient vs 5-point stencil (-1: none)
  double reference_stencil_ratio = -1.0;  // quadrature gradient vs the same stencil
};

// Runs every case once for the whole suite: the tests below only inspect the results.
class TriangleFieldAgainstReference : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    results_ = std::make_unique<std::vector<CaseResult>>();
    const unsigned long long seed = reference::test_seed(kSeed);
    std::printf("[ triangle ] seed 0x%llx (set CONVRAY_TEST_SEED to change)\n", seed);
    std::mt19937_64 rng(seed);
    const auto generators = reference::triangle_generators();
    const int count = kCasesPerGenerator * static_cast<int>(generators.size());
    for (int i = 0; i < count; ++i)
      results_->push_back(run_case(generators[i % generators.size()].make(rng)));
  }
  static void TearDownTestSuite() { results_.reset(); }

  static CaseResult run_case(const TriangleCase& tc) {
    CaseResult r;
    r.input = tc;
    r.classification = reference::classify_triangle_case(tc);
    const Triangle triangle{tc.a, tc.b, tc.c};
    const auto ref = reference::reference_triangle(tc.p, tc.a, tc.b, tc.c, tc.radius);
    const double scale = plane_scale(tc.radius);
    const FieldSample sample = triangle_field(tc.p, triangle, tc.radius);
    r.reference_value = ref.value;
    r.reference_converged = ref.converged;
    r.value_ratio = reference::value_error_ratio(triangle_value(tc.p, triangle, tc.radius), ref.value,
                                                 kValueTolerance, scale);
    r.field_value_ratio = reference::value_error_ratio(sample.value, ref.value, kValueTolerance, scale);
    r.gradient_ratio = reference::gradient_error_ratio(sample.gradient, ref.gradient,
                                                       kGradientTolerance, scale / tc.radius);

    // Where the field is smooth around p, also against the stencil of the reference value.
    const double reach = std::max({glm::length(tc.a - tc.p), glm::length(tc.b - tc.p), glm::length(tc.c - tc.p)});
    if (r.classification.smooth_margin > kStencilMargin && reach <= kStencilReach * tc.radius) {
      const auto reference_value = [&](const Vec3& q) {
        return reference::reference_triangle(q, tc.a, tc.b, tc.c, tc.radius).value;
      };
      if (const auto stencil =
              reference::five_point_gradient(reference_value, tc.p, kStencilStep * tc.radius)) {
        r.stencil_ratio = reference::gradient_error_ratio(sample.gradient, *stencil,
                                                          kGradientTolerance, scale / tc.radius);
        r.reference_stencil_ratio = reference::gradient_error_ratio(
            ref.gradient, *stencil, kGradientTolerance, scale / tc.radius);
      }
    }
    return r;
  }

  // Expects ratio(result) <= 1 for every case (negative: not checked for that case); reports
  // the worst and the first failures.
  template <class Ratio>
  static void expect_all_within_tolerance(const char* what, Ratio ratio) {
    reference::RatioCheck check(what);
    for (const CaseResult& r : *results_) {
      const double value = ratio(r);
      if (value >= 0.0 || std::isnan(value))
        check.add(value, describe(r.input) + " (reference value " + reference::format_double(r.reference_value) + ")");
    }
    std::printf("[ triangle ] %-46s %6d cases, worst error/tolerance %.3g\n", what, check.checked(),
                check.worst().ratio);
    check.expect_no_failure();
  }

  static std::unique_ptr<std::vector<CaseResult>> results_;
};

std::unique_ptr<std::vector<CaseResult>> TriangleFieldAgainstReference::results_;

TEST_F(TriangleFieldAgainstReference, RunsAtLeastTenThousandCases) {
  EXPECT_GE(results_->size(), 10000u);
}

TEST_F(TriangleFieldAgainstReference, ReferenceQuadratureConvergesInEveryCase) {
  for (const CaseResult& r : *results_)
    ASSERT_TRUE(r.reference_converged) << describe(r.input);
}

TEST_F(TriangleFieldAgainstReference, ValueMatchesQuadratureWithinTenToMinusTenOfPlaneScale) {
  expect_all_within_tolerance("triangle_value vs quadrature",
                              [](const CaseResult& r) { return r.value_ratio; });
}

TEST_F(TriangleFieldAgainstReference, FieldValueMatchesQuadratureWithinTenToMinusTenOfPlaneScale) {
  expect_all_within_tolerance("triangle_field value vs quadrature",
                              [](const CaseResult& r) { return r.field_value_ratio; });
}

TEST_F(TriangleFieldAgainstReference, GradientMatchesQuadratureOfDifferentiatedKernel) {
  expect_all_within_tolerance("triangle_field gradient vs quadrature",
                              [](const CaseResult& r) { return r.gradient_ratio; });
}

TEST_F(TriangleFieldAgainstReference, GradientMatchesFivePointStencilWhereFieldIsSmooth) {
  expect_all_within_tolerance("triangle_field gradient vs 5-point stencil",
                              [](const CaseResult& r) { return r.stencil_ratio; });
}

TEST_F(TriangleFieldAgainstReference, ReferenceGradientMatchesStencilOfReferenceValue) {
  expect_all_within_tolerance("reference gradient vs 5-point stencil",
                              [](const CaseResult& r) { return r.reference_stencil_ratio; });
}

TEST_F(TriangleFieldAgainstReference, StencilSubsetIsLarge) {
  int stencils = 0;
  for (const CaseResult& r : *results_) stencils += r.stencil_ratio >= 0.0;
  EXPECT_GE(stencils, 2000);
}

// Clearly outside the support (the sphere misses the plane, or the disk misses the triangle,
// by more than 1e-9 R), or with zero area, the reference is exactly 0 and the field vanishes.
TEST_F(TriangleFieldAgainstReference, OutsideTheSupportTheFieldVanishes) {
  int checked = 0;
  for (const CaseResult& r : *results_) {
    const bool misses = r.classification[TriangleFeature::kSphereMissesPlane] ||
                        r.classification[TriangleFeature::kZeroPointsDisjoint];
    const bool zero_area = r.classification[TriangleFeature::kZeroArea];
    if (!(zero_area || (misses && r.classification.smooth_margin > 1e-9))) continue;
    ++checked;
    EXPECT_EQ(r.reference_value, 0.0) << describe(r.input);
    EXPECT_LE(r.value_ratio, 1.0) << describe(r.input);
    EXPECT_LE(r.gradient_ratio, 1.0) << describe(r.input);
  }
  EXPECT_GE(checked, 1000);
}

// Prints the coverage table (cases and worst value/gradient error ratios per configuration)
// and asserts that every configuration was hit often.
TEST_F(TriangleFieldAgainstReference, EveryConfigurationIsCoveredManyTimes) {
  std::array<int, reference::kTriangleFeatureCount> count{};
  std::array<double, reference::kTriangleFeatureCount> worst_value{}, worst_gradient{};
  for (const CaseResult& r : *results_) {
    for (int f = 0; f < reference::kTriangleFeatureCount; ++f) {
      if (!r.classification.has[f]) continue;
      ++count[f];
      worst_value[f] = std::max({worst_value[f], r.value_ratio, r.field_value_ratio});
      worst_gradient[f] = std::max({worst_gradient[f], r.gradient_ratio, r.stencil_ratio});
    }
  }
  std::printf("[ triangle ] %-44s %7s %12s %12s\n", "configuration", "cases", "worst value",
              "worst grad");
  for (int f = 0; f < reference::kTriangleFeatureCount; ++f)
    std::printf("[ triangle ] %-44s %7d %12.3g %12.3g\n",
                std::string(reference::feature_name(static_cast<TriangleFeature>(f))).c_str(),
                count[f], worst_value[f], worst_gradient[f]);
  for (int f = 0; f < reference::kTriangleFeatureCount; ++f)
    EXPECT_GE(count[f], kMinimumCasesPerFeature)
        << reference::feature_name(static_cast<TriangleFeature>(f));
}

}  // namespace
}  // namespace convray::field
