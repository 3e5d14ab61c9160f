// The one polynomial root finder (core/polynomial_roots.hpp) against polynomials built from
// known roots (tests/reference/polynomial_oracle.hpp, evaluated in long double): distinct
// roots of every degree up to eight, roots beside complex pairs, close pairs, roots on the
// ends, touching roots, tiny and huge scales, a vanishing leading coefficient, unbounded
// intervals, the brackets' sign changes, and the smallest root alone; and a brute-force sign
// scan of random polynomials. (Quartics with both callers' settings: quartic_roots_test.)
#include "core/polynomial_roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

// c * prod (x - r), any degree up to eight, constant first.
std::vector<double> from_roots(const std::vector<double>& r, double c) {
  std::vector<double> p = {c};
  for (double root : r) {
    p.push_back(0.0);
    for (size_t k = p.size() - 1; k >= 1; --k) p[k] = p[k - 1] - root * p[k];
    p[0] = -root * p[0];
  }
  return p;
}

// The exact slope at a known root r_k of c prod (x - r_j): c prod_{j != k} (r_k - r_j).
double slope_at(const std::vector<double>& r, size_t k, double c) {
  long double slope = c;
  for (size_t j = 0; j < r.size(); ++j) {
    if (j != k) slope *= (long double)r[k] - r[j];
  }
  return double(slope);
}

double size_at(const std::vector<double>& c, double x) {
  double size = 0.0, power = 1.0;
  for (double ci : c) {
    size += std::abs(ci) * power;
    power *= std::abs(x);
  }
  return size;
}

std::vector<double> roots_of(const std::vector<double>& c, double lo, double hi,
                             int max_roots = kMaxPolynomialDegree, double resolution = 0.0) {
  double out[kMaxPolynomialDegree];
  const int count = polynomial_roots(c, lo, hi, out, max_roots, resolution);
  return {out, out + count};
}

TEST(PolynomialRoots, FindsKnownDistinctRootsOfDegreesSevenAndEight) {
  std::mt19937_64 rng(2025);
  std::uniform_real_distribution<double> where(-1.5, 2.5), scale(0.2, 5.0);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const size_t degree = 7 + size_t(trial % 2);
    std::vector<double> r;
    for (size_t k = 0; k < degree; ++k) r.push_back(where(rng));
    std::sort(r.begin(), r.end());
    bool separated = true;
    for (size_t k = 1; k < degree; ++k) separated = separated && r[k] - r[k - 1] > 1e-2;
    if (!separated) continue;
    const double a = trial % 4 < 2 ? scale(rng) : -scale(rng);
    const std::vector<double> c = from_roots(r, a);
    std::vector<double> found = roots_of(c, 0.0, 1.0);
    std::vector<size_t> expected;
    for (size_t k = 0; k < degree; ++k) {
      if (r[k] >= 0.0 && r[k] <= 1.0) expected.push_back(k);
    }
    ASSERT_EQ(found.size(), expected.size()) << trial;
    for (size_t i = 0; i < found.size(); ++i) {
      const size_t k = expected[i];
      const double tolerance = 1e-14 * size_at(c, r[k]) / std::abs(slope_at(r, k, a)) + 1e-15;
      EXPECT_NEAR(found[i], r[k], tolerance) << trial;
    }
    const std::vector<double> first = roots_of(c, 0.0, 1.0, 1);
    ASSERT_EQ(first.size(), std::min<size_t>(1, expected.size()));
    if (!first.empty()) EXPECT_EQ(first[0], found[0]);
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

// Random polynomials of every degree, sampled densely in long double: each clear sign change
// between samples holds a root found, and each root found is a zero to rounding.
TEST(PolynomialRoots, AgreesWithABruteForceSignScan) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const size_t degree = 1 + size_t(trial % 8);
    std::vector<double> c(degree + 1);
    for (double& ci : c) ci = u(rng);
    const double lo = 2.0 * u(rng), hi = lo + 0.1 + 2.0 * std::abs(u(rng));
    const std::vector<double> found = roots_of(c, lo, hi);
    ASSERT_LE(found.size(), degree);
    for (size_t i = 0; i < found.size(); ++i) {
      EXPECT_GE(found[i], lo);
      EXPECT_LE(found[i], hi);
      if (i > 0) EXPECT_GT(found[i], found[i - 1]) << trial;
      EXPECT_LE(std::abs(evaluate_polynomial(c, found[i])), 1e-13 * size_at(c, found[i]))
          << trial;
    }
    auto value = [&](long double x) {
      long double v = 0.0L;
      for (size_t k = c.size(); k-- > 0;) v = v * x + c[k];
      return v;
    };
    const int samples = 4000;
    long double x0 = lo, v0 = value(x0);
    for (int s = 1; s <= samples; ++s) {
      const long double x1 = lo + (hi - lo) * (long double)s / samples, v1 = value(x1);
      const double clear = 1e-12 * size_at(c, double(x1));
      if (std::abs(v0) > clear && std::abs(v1) > clear && (v0 < 0) != (v1 < 0)) {
        const bool held = std::any_of(found.begin(), found.end(), [&](double x) {
          return x >= double(x0) - 1e-12 && x <= double(x1) + 1e-12;
        });
        EXPECT_TRUE(held) << "trial " << trial << " sign change in [" << double(x0) << ", "
                          << double(x1) << "]";
      }
      x0 = x1;
      v0 = v1;
    }
  }
}

TEST(PolynomialRoots, TinyAndHugeScales) {
  for (double s : {1e-30, 1e-9, 1.0, 1e9, 1e30}) {
    const std::vector<double> c = from_roots({0.2 * s, 0.5 * s, 0.9 * s}, 1.0);
    const std::vector<double> found = roots_of(c, 0.0, s);
    ASSERT_EQ(found.size(), 3u) << s;
    EXPECT_NEAR(found[0], 0.2 * s, 1e-14 * s);
    EXPECT_NEAR(found[1], 0.5 * s, 1e-14 * s);
    EXPECT_NEAR(found[2], 0.9 * s, 1e-14 * s);
    // The same roots on an interval far wider than them.
    const std::vector<double> wide = roots_of(c, -1e6 * s, 1e6 * s);
    ASSERT_EQ(wide.size(), 3u) << s;
    EXPECT_NEAR(wide[1], 0.5 * s, 1e-14 * s);
  }
}

// A ray nearly along an asymptotic direction of a quartic surface: the leading coefficient
// vanishes against the others, and the interval runs to Cauchy's bound (polynomial_surface).
TEST(PolynomialRoots, AVanishingLeadingCoefficient) {
  for (double e : {1e-8, 1e-17, 1e-20, 1e-40, 1e-60, 1e-100}) {
    const double c[5] = {3.0, -4.0, 1.0, 0.0, e};  // (x - 1)(x - 3) + e x^4
    const double hi = 1.0 + 4.0 / e;
    double out[4];
    ASSERT_EQ(polynomial_roots(c, 0.0, hi, out), 2) << e;
    // e x^4 moves the roots by about e x^4 / |slope| (at most 81 e / 2).
    EXPECT_NEAR(out[0], 1.0, 1e-15 + 50.0 * e) << e;
    EXPECT_NEAR(out[1], 3.0, 4e-15 + 50.0 * e) << e;
  }
}

TEST(PolynomialRoots, UnboundedIntervalsAreClippedToTheRootsBound) {
  const std::vector<double> c = from_roots({1.0, 3.0, 1e6}, -2.0);
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> found = roots_of(c, 0.0, inf);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NEAR(found[0], 1.0, 1e-14);
  EXPECT_NEAR(found[1], 3.0, 1e-14);
  EXPECT_NEAR(found[2], 1e6, 1e-8);
  EXPECT_EQ(roots_of(c, -inf, inf).size(), 3u);
  // Coefficients that are not numbers: no roots, and an answer.
  const std::vector<double> nan = {1.0, std::nan(""), -1.0, 2.0};
  EXPECT_TRUE(roots_of(nan, 0.0, 1.0).empty());
}

TEST(PolynomialRoots, RootsOnTheEndsOfAnyInterval) {
  // (x + 1.5)(x - 2.5)(x - 1)(x + 3) on [-1.5, 2.5]: both ends, and 1 inside, once each.
  const std::vector<double> c = from_roots({-1.5, 2.5, 1.0, -3.0}, 0.5);
  const std::vector<double> found = roots_of(c, -1.5, 2.5);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NEAR(found[0], -1.5, 1e-15);
  EXPECT_NEAR(found[1], 1.0, 1e-15);
  EXPECT_NEAR(found[2], 2.5, 1e-15);
}

// Double roots: a touch (the polynomial only meets zero) is no crossing; with a resolution, a
// pair closer than it is told from a miss by the sign at the middle of its piece.
TEST(PolynomialRoots, DoubleAndNearDoubleRootsOfHigherDegree) {
  const std::vector<double> touch = from_roots({0.3, 0.3, -1.0, 2.0, 1.7, -0.4}, 1.0);
  for (double x : roots_of(touch, 0.0, 1.0)) EXPECT_NEAR(x, 0.3, 1e-7);
  // touch = (x - 0.3)^2 g(x), g(0.3) = 1.3 (-1.7) (-1.4) 0.7 > 0.
  const double g = evaluate_polynomial(from_roots({-1.0, 2.0, 1.7, -0.4}, 1.0), 0.3);
  std::vector<double> miss = touch, cross = touch;
  miss[0] += 1e-10 * g;   // away from zero: no root
  cross[0] -= 1e-10 * g;  // through zero: two roots 1e-5 either side of 0.3
  for (double resolution : {0.0, 1e-12}) {
    EXPECT_TRUE(roots_of(miss, 0.0, 1.0, 8, resolution).empty()) << resolution;
    const std::vector<double> found = roots_of(cross, 0.0, 1.0, 8, resolution);
    ASSERT_EQ(found.size(), 2u) << resolution;
    EXPECT_NEAR(found[0], 0.3 - 1e-5, 1e-9);
    EXPECT_NEAR(found[1], 0.3 + 1e-5, 1e-9);
  }
  // A pair far closer than the resolution: its piece is not halved, and the sign at its
  // middle decides; either way no root away from the pair, and never one alone.
  const std::vector<double> pair = from_roots({0.3 - 1e-10, 0.3 + 1e-10, -1.0, 2.0}, 1.0);
  const std::vector<double> coarse = roots_of(pair, 0.0, 1.0, 4, 1e-6);
  EXPECT_TRUE(coarse.empty() || coarse.size() == 2u);
  for (double x : coarse) EXPECT_NEAR(x, 0.3, 1e-6);
}

TEST(PolynomialRoots, BracketsOfDegreeEight) {
  const std::vector<double> r = {-0.9, -0.2, 0.05, 0.3, 0.31, 0.8, 1.2, 2.0};
  const std::vector<double> c = from_roots(r, 0.7);
  RootBracket brackets[kMaxPolynomialDegree];
  const int count = polynomial_brackets(c, -0.5, 1.5, brackets);
  ASSERT_EQ(count, 6);
  for (int k = 0; k < count; ++k) {
    const RootBracket& b = brackets[k];
    EXPECT_LT(b.lo, r[size_t(k) + 1]);
    EXPECT_GT(b.hi, r[size_t(k) + 1]);
    EXPECT_NE(b.f_lo < 0.0, b.f_hi < 0.0);
    EXPECT_NEAR(refine_polynomial_root(c, b), r[size_t(k) + 1], 1e-14);
  }
}

}  // namespace
}  // namespace convray
