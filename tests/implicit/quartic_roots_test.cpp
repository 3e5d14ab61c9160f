// The quartic helpers of the sphere sweep against direct evaluation, and both quartic root
// finders (the sweep's Bernstein isolator and its exact twin, the one polynomial root finder of
// core/polynomial_roots.hpp) against quartics built from known roots: distinct, close pairs,
// double roots, none, and roots exactly on the ends of the interval; then against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "implicit/insertion_sort.hpp"
#include "implicit/quartic.hpp"
#include "implicit/quartic_roots.hpp"
#include "core/polynomial_roots.hpp"

namespace convray::implicit {
namespace {

// a (v - r0)(v - r1)(v - r2)(v - r3), expanded.
Quartic from_roots(double a, const std::array<double, 4>& r) {
  Quartic q;
  q.c = {a, 0.0, 0.0, 0.0, 0.0};
  int degree = 0;
  for (double root : r) {  // multiply by (v - root)
    for (int k = degree + 1; k >= 1; --k) q.c[k] = q.c[k - 1] - root * q.c[k];
    q.c[0] = -root * q.c[0];
    ++degree;
  }
  return q;
}

enum class Finder { bernstein_isolator, polynomial_roots };

std::vector<double> roots_with(Finder finder, const Quartic& q, double width, bool first_only) {
  std::vector<double> out;
  if (finder == Finder::bernstein_isolator) {
    QuarticRootOptions options;
    options.resolution = 1e-12;
    options.first_only = first_only;
    quartic_roots(q, width, options, out);
  } else {
    out.resize(4);
    out.resize(size_t(polynomial_roots(q.c, 0.0, width, out.data(), first_only ? 1 : 4)));
  }
  return out;
}

// Each root-finding test runs with both finders.
class QuarticRoots : public testing::TestWithParam<Finder> {
 protected:
  std::vector<double> roots_of(const Quartic& q, double width, bool first_only = false) const {
    return roots_with(GetParam(), q, width, first_only);
  }
};
INSTANTIATE_TEST_SUITE_P(BothFinders, QuarticRoots,
                         testing::Values(Finder::bernstein_isolator, Finder::polynomial_roots));

TEST(Quartic, SphereTermShiftAndBernsteinAgreeWithDirectEvaluation) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double k = u(rng), h2 = std::abs(u(rng)), vc = u(rng), d = u(rng);
    const Quartic q = sphere_term(k, h2, vc);
    const Quartic moved = shifted(q, d);
    const double width = 0.1 + std::abs(u(rng));
    const auto b = bernstein(q, width);
    const auto [least, most] = std::minmax_element(b.begin(), b.end());
    for (int j = 0; j <= 20; ++j) {
      const double v = width * j / 20.0;
      const double e = h2 - (v - vc) * (v - vc);
      const double direct = k * e * e;
      const double scale = std::abs(k) * (h2 + 36.0) * (h2 + 36.0);
      EXPECT_NEAR(q(v), direct, 1e-13 * scale);
      EXPECT_NEAR(moved(v - d), direct, 1e-12 * scale);
      EXPECT_NEAR(q.slope(v), -4.0 * k * e * (v - vc), 1e-12 * scale);
      // The Bernstein hull holds the polynomial; its end points are the end values.
      EXPECT_GE(q(v), *least - 1e-12 * scale);
      EXPECT_LE(q(v), *most + 1e-12 * scale);
    }
    EXPECT_NEAR(b[0], q(0.0), 1e-13 * std::abs(k) * (h2 + 36.0) * (h2 + 36.0));
    EXPECT_NEAR(b[4], q(width), 1e-12 * std::abs(k) * (h2 + 36.0) * (h2 + 36.0));
  }
}

TEST_P(QuarticRoots, FindsKnownDistinctRootsInAscendingOrder) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-0.5, 1.5), scale(-3.0, 3.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<double, 4> r = {u(rng), u(rng), u(rng), u(rng)};
    std::sort(r.begin(), r.end());
    if (r[1] - r[0] < 1e-3 || r[2] - r[1] < 1e-3 || r[3] - r[2] < 1e-3) continue;
    double a = scale(rng);
    if (std::abs(a) < 0.1) a = 1.0;
    const Quartic q = from_roots(a, r);
    std::vector<double> expected;
    for (double root : r) {
      if (root >= 0.0 && root <= 1.0) expected.push_back(root);
    }
    // A root is as well defined as the coefficients' rounding over the slope there.
    auto tolerance = [&](double root) {
      double size = 0.0;
      for (double c : q.c) size += std::abs(c);
      return 1e-15 * size / std::abs(q.slope(root)) + 1e-15;
    };
    const std::vector<double> found = roots_of(q, 1.0);
    ASSERT_EQ(found.size(), expected.size()) << trial;
    for (size_t i = 0; i < found.size(); ++i) {
      EXPECT_NEAR(found[i], expected[i], tolerance(expected[i]));
    }
    const std::vector<double> first = roots_of(q, 1.0, true);
    ASSERT_EQ(first.size(), expected.empty() ? 0u : 1u);
    if (!expected.empty()) EXPECT_NEAR(first[0], expected[0], tolerance(expected[0]));
  }
}

TEST_P(QuarticRoots, SeparatesACloseCrossingPair) {
  // The coefficients' rounding (1e-16 of values about 6) moves roots by that over the slope
  // at them, about 12 gap: the pair is as well conditioned as 1e-15 / gap.
  for (double gap : {1e-2, 1e-4, 1e-6}) {
    const Quartic q = from_roots(1.0, {0.4 - gap, 0.4 + gap, -2.0, 3.0});
    const std::vector<double> found = roots_of(q, 1.0);
    ASSERT_EQ(found.size(), 2u) << gap;
    EXPECT_NEAR(found[0], 0.4 - gap, 1e-14 / gap);
    EXPECT_NEAR(found[1], 0.4 + gap, 1e-14 / gap);
  }
}

TEST_P(QuarticRoots, TellsATouchFromAMiss) {
  // (v - 0.25)^2 (v + 1)(v - 3) touches zero at 0.25 from below: at most the touching pair,
  // never a root elsewhere.
  const Quartic touch = from_roots(1.0, {0.25, 0.25, -1.0, 3.0});
  for (double v : roots_of(touch, 1.0)) EXPECT_NEAR(v, 0.25, 1e-7);
  // Lifted slightly above zero: no root at all.
  Quartic miss = touch;
  miss.c[0] -= 1e-9;  // the factor (v + 1)(v - 3) is negative on [0, 1]
  EXPECT_TRUE(roots_of(miss, 1.0).empty());
  // Pushed slightly through zero: two roots about sqrt(1e-9 / 3.75) either side.
  Quartic cross = touch;
  cross.c[0] += 1e-9;
  const std::vector<double> found = roots_of(cross, 1.0);
  ASSERT_EQ(found.size(), 2u);
  const double half_gap = std::sqrt(1e-9 / (1.25 * 2.75));
  EXPECT_NEAR(found[0], 0.25 - half_gap, 1e-9);
  EXPECT_NEAR(found[1], 0.25 + half_gap, 1e-9);
}

TEST_P(QuarticRoots, RootsOnTheEndsAreReportedOnce) {
  const std::vector<double> both = roots_of(from_roots(2.0, {0.0, 0.5, 1.0, 4.0}), 1.0);
  ASSERT_EQ(both.size(), 3u);
  EXPECT_EQ(both[0], 0.0);
  EXPECT_NEAR(both[1], 0.5, 1e-14);
  EXPECT_NEAR(both[2], 1.0, 1e-14);
  // No roots: a positive quartic, and an empty interval.
  EXPECT_TRUE(roots_of(from_roots(1.0, {-1.0, -2.0, 2.0, 3.0}), 1.0).empty());
  EXPECT_TRUE(roots_of(from_roots(1.0, {0.5, -2.0, 2.0, 3.0}), 0.0).empty());
}

TEST_P(QuarticRoots, WorksOnWideAndNarrowIntervals) {
  for (double width : {1e-5, 1.0, 1e4}) {
    const Quartic q = from_roots(1.0 / (width * width * width * width),
                                 {0.3 * width, 0.7 * width, 1.5 * width, -width});
    const std::vector<double> found = roots_of(q, width);
    ASSERT_EQ(found.size(), 2u) << width;
    EXPECT_NEAR(found[0], 0.3 * width, 1e-12 * width);
    EXPECT_NEAR(found[1], 0.7 * width, 1e-12 * width);
  }
}

TEST(InsertionSort, SortsLikeStdSort) {
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> u(0, 50);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<int> items(size_t(u(rng)));
    for (int& x : items) x = u(rng);
    std::vector<int> expected = items;
    std::sort(expected.begin(), expected.end());
    insertion_sort(std::span(items), std::less<int>());
    EXPECT_EQ(items, expected);
  }
}

}  // namespace
}  // namespace convray::implicit

namespace convray::implicit {
namespace {

// The sweep's Bernstein isolator (the fast path) against the one polynomial root finder
// (core/polynomial_roots.hpp, its exact twin): quartics with known real roots, some of them
// in [0, width], the same roots from both, to a few ulps.
TEST(QuarticFinders, TheIsolatorAgreesWithTheOnePolynomialRootFinder) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(-0.5, 1.5), scale(0.1, 10.0);
  int roots = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double r[4] = {u(rng), u(rng), u(rng), u(rng)};
    const double k = scale(rng) * (trial % 2 ? 1.0 : -1.0);
    // k (x - r0)(x - r1)(x - r2)(x - r3), expanded.
    std::vector<double> c = {k};
    for (double root : r) {
      std::vector<double> next(c.size() + 1, 0.0);
      for (size_t i = 0; i < c.size(); ++i) {
        next[i + 1] += c[i];
        next[i] -= root * c[i];
      }
      c = next;
    }
    Quartic q;
    for (size_t i = 0; i < 5; ++i) q.c[i] = c[i];
    std::vector<double> fast;
    QuarticRootOptions options;
    options.resolution = 1e-12;
    quartic_roots(q, 1.0, options, fast);
    double twin[4];
    const int n = polynomial_roots(c, 0.0, 1.0, twin, 4);
    // Roots closer than 1e-3 are left to the finders' own tests (a touch may count once).
    bool close_pair = false;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) close_pair |= std::abs(r[i] - r[j]) < 1e-3;
    }
    if (close_pair) continue;
    ASSERT_EQ(int(fast.size()), n) << "trial " << trial;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(fast[size_t(i)], twin[i], 1e-9) << "trial " << trial;
    roots += n;
  }
  EXPECT_GT(roots, 2000);
}

}  // namespace
}  // namespace convray::implicit
