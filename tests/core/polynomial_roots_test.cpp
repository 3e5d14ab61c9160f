// The one polynomial root finder (core/polynomial_roots.hpp) against polynomials built from
// known roots (tests/reference/polynomial_oracle.hpp, evaluated in long double): distinct
// roots of every degree up to six, roots beside complex pairs, close pairs, roots on the ends,
// touching roots, the brackets' sign changes, and the smallest root alone.
#include "core/polynomial_roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "reference/polynomial_oracle.hpp"

namespace convray {
namespace {

using implicit::oracle::Coefficients;
using implicit::oracle::power_from_roots;
using implicit::oracle::power_value;
using implicit::oracle::times_complex_pair;

std::vector<double> roots_of(const Coefficients& c, double lo, double hi,
                             int max_roots = kMaxPolynomialDegree) {
  double out[kMaxPolynomialDegree];
  const int count = polynomial_roots(c, lo, hi, out, max_roots);
  return {out, out + count};
}

// How well a simple root r is defined by coefficients rounded to doubles: their rounding
// (a few eps times the sum of |c_i r^i|, Horner's bound) over the slope there, which the
// oracle gives in long double.
double conditioning(const Coefficients& c, double r) {
  double size = 0.0, power = 1.0;
  for (double ci : c) {
    size += std::abs(ci * power);
    power *= std::abs(r);
  }
  const long double h = 1e-7L * std::max(1.0, std::abs(r));
  const long double slope = (power_value(c, r + h) - power_value(c, r - h)) / (2.0L * h);
  return 1e-14 * size / double(std::abs(slope)) + 1e-15 * std::max(1.0, std::abs(r));
}

TEST(PolynomialRoots, FindsKnownDistinctRootsOfEveryDegree) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> where(-2.0, 3.0), scale(0.2, 5.0);
  for (int trial = 0; trial < 3000; ++trial) {
    const int degree = 1 + trial % 6;
    std::vector<double> r;
    for (int k = 0; k < degree; ++k) r.push_back(where(rng));
    std::sort(r.begin(), r.end());
    bool separated = true;
    for (int k = 1; k < degree; ++k) separated = separated && r[k] - r[k - 1] > 1e-3;
    if (!separated) continue;
    const Coefficients c = power_from_roots(r, trial % 2 ? scale(rng) : -scale(rng));
    std::vector<double> expected;
    for (double root : r) {
      if (root >= 0.0 && root <= 1.0) expected.push_back(root);
    }
    const std::vector<double> found = roots_of(c, 0.0, 1.0);
    ASSERT_EQ(found.size(), expected.size()) << trial;
    for (size_t k = 0; k < found.size(); ++k) {
      EXPECT_NEAR(found[k], expected[k], conditioning(c, expected[k])) << trial;
    }
  }
}

TEST(PolynomialRoots, ComplexPairsAddNoRoots) {
  // (x - 0.3)(x - 0.8) times two pairs with no real root: still those two roots on [-5, 5].
  Coefficients c = power_from_roots({0.3, 0.8}, 1.0);
  c = times_complex_pair(c, 0.5, 0.01);  // just off the real axis, between the roots
  c = times_complex_pair(c, -1.0, 2.0);
  const std::vector<double> found = roots_of(c, -5.0, 5.0);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0], 0.3, 1e-13);
  EXPECT_NEAR(found[1], 0.8, 1e-13);
  // No real roots at all: a product of complex pairs.
  const Coefficients none = times_complex_pair(times_complex_pair(power_from_roots({}, 2.0),
                                                                   0.2, 0.3), 4.0, 1.0);
  EXPECT_TRUE(roots_of(none, -1e6, 1e6).empty());
}

TEST(PolynomialRoots, SeparatesClosePairs) {
  for (double gap : {1e-2, 1e-4, 1e-6}) {
    const Coefficients c = power_from_roots({0.4 - gap, 0.4 + gap, -2.0, 3.0, 1.7}, 1.0);
    const std::vector<double> found = roots_of(c, 0.0, 1.0);
    ASSERT_EQ(found.size(), 2u) << gap;
    EXPECT_NEAR(found[0], 0.4 - gap, 1e-14 / gap);
    EXPECT_NEAR(found[1], 0.4 + gap, 1e-14 / gap);
  }
}

TEST(PolynomialRoots, RootsOnTheEndsAreExactAndReportedOnce) {
  // 0 and 1 are exact roots (the products are exact there); 0.5 inside.
  const Coefficients c = power_from_roots({0.0, 0.5, 1.0, 4.0}, 2.0);
  const std::vector<double> found = roots_of(c, 0.0, 1.0);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0], 0.0);
  EXPECT_NEAR(found[1], 0.5, 1e-15);
  EXPECT_EQ(found[2], 1.0);
  // An empty interval, and an interval beside the roots.
  EXPECT_TRUE(roots_of(c, 2.0, 3.0).empty());
  EXPECT_TRUE(roots_of(c, 0.25, 0.25).empty());
}

TEST(PolynomialRoots, ATouchIsFoundWhereItIsExactlyZero) {
  // x^2 (x - 2): the double root 0 is a critical point where the value is exactly zero.
  const std::vector<double> found = roots_of(power_from_roots({0.0, 0.0, 2.0}, 1.0), -1.0, 3.0);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0], 0.0, 1e-15);
  EXPECT_NEAR(found[1], 2.0, 1e-15);
}

TEST(PolynomialRoots, BracketsHoldOneSignChangeEach) {
  const std::vector<double> r = {-0.7, 0.1, 0.2, 0.9, 1.4, 2.5};
  const Coefficients c = power_from_roots(r, -1.5);
  RootBracket brackets[kMaxPolynomialDegree];
  const int count = polynomial_brackets(c, -1.0, 2.0, brackets);
  ASSERT_EQ(count, 5);
  for (int k = 0; k < count; ++k) {
    const RootBracket& b = brackets[k];
    EXPECT_LT(b.lo, r[size_t(k)]);
    EXPECT_GT(b.hi, r[size_t(k)]);
    EXPECT_EQ(b.f_lo, evaluate_polynomial(c, b.lo));
    EXPECT_EQ(b.f_hi, evaluate_polynomial(c, b.hi));
    EXPECT_NE(b.f_lo < 0.0, b.f_hi < 0.0);
    if (k > 0) EXPECT_GE(b.lo, brackets[k - 1].hi);
  }
}

TEST(PolynomialRoots, TheSmallestRootAlone) {
  const Coefficients c = power_from_roots({0.25, 0.5, 0.75}, 1.0);
  const std::vector<double> first = roots_of(c, 0.0, 1.0, 1);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_NEAR(first[0], 0.25, 1e-15);
  EXPECT_EQ(roots_of(c, 0.3, 1.0, 1), std::vector<double>(1, roots_of(c, 0.3, 1.0)[0]));
}

TEST(PolynomialRoots, LeadingZerosLowerTheDegree) {
  const double linear[3] = {-1.0, 2.0, 0.0};  // 2x - 1
  double out[kMaxPolynomialDegree];
  ASSERT_EQ(polynomial_roots(linear, -1.0, 1.0, out), 1);
  EXPECT_EQ(out[0], 0.5);
  const double constant[4] = {3.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(polynomial_roots(constant, -1.0, 1.0, out), 0);
}

TEST(PolynomialRoots, QuadraticKeepsTheSmallRootsDigits) {
  double t[2];
  ASSERT_EQ(quadratic_roots(1.0, -1e8, 1.0, t), 2);  // x^2 - 2e8 x + 1: roots 1e8 +- sqrt(1e16 - 1)
  EXPECT_NEAR(t[0], 5e-9, 1e-24);
  EXPECT_NEAR(t[1], 2e8, 1e-7);
  ASSERT_EQ(quadratic_roots(2.0, -2.5, 2.0, t), 2);  // 2x^2 - 5x + 2 = (2x - 1)(x - 2)
  EXPECT_EQ(t[0], 0.5);
  EXPECT_EQ(t[1], 2.0);
}

}  // namespace
}  // namespace convray
