// The one polynomial root finder (core/polynomial_roots.hpp) on quartics built from known
// roots: distinct, close pairs, double roots, none, and roots exactly on the ends of the
// interval; every case with the settings of both kinds of callers (the sphere sweep's
// resolution for near-double roots, and the shapes' none), which must agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "core/polynomial_roots.hpp"

namespace convray {
namespace {

using Quartic = std::array<double, 5>;  // constant first

// a (v - r0)(v - r1)(v - r2)(v - r3), expanded.
Quartic from_roots(double a, const std::array<double, 4>& r) {
  Quartic q = {a, 0.0, 0.0, 0.0, 0.0};
  int degree = 0;
  for (double root : r) {  // multiply by (v - root)
    for (int k = degree + 1; k >= 1; --k) q[k] = q[k - 1] - root * q[k];
    q[0] = -root * q[0];
    ++degree;
  }
  return q;
}

double value(const Quartic& q, double v) { return evaluate_polynomial(q, v); }
double slope(const Quartic& q, double v) {
  return ((4.0 * q[4] * v + 3.0 * q[3]) * v + 2.0 * q[2]) * v + q[1];
}

// The callers' settings: the sphere sweep's resolution (as its tests gave its former
// isolator), and the shapes' (none: halving to the rounding limit).
enum class Caller { sphere_sweep, shapes };

std::vector<double> roots_with(Caller caller, const Quartic& q, double width, bool first_only) {
  const double resolution = caller == Caller::sphere_sweep ? 1e-12 : 0.0;
  std::vector<double> out(4);
  out.resize(size_t(polynomial_roots(q, 0.0, width, out.data(), first_only ? 1 : 4, resolution)));
  return out;
}

// Each root-finding test runs with both callers' settings.
class QuarticRoots : public testing::TestWithParam<Caller> {
 protected:
  std::vector<double> roots_of(const Quartic& q, double width, bool first_only = false) const {
    return roots_with(GetParam(), q, width, first_only);
  }
};
INSTANTIATE_TEST_SUITE_P(BothCallers, QuarticRoots,
                         testing::Values(Caller::sphere_sweep, Caller::shapes));

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
      for (double c : q) size += std::abs(c);
      return 1e-15 * size / std::abs(slope(q, root)) + 1e-15;
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
  miss[0] -= 1e-9;  // the factor (v + 1)(v - 3) is negative on [0, 1]
  EXPECT_TRUE(roots_of(miss, 1.0).empty());
  // Pushed slightly through zero: two roots about sqrt(1e-9 / 3.75) either side.
  Quartic cross = touch;
  cross[0] += 1e-9;
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


// The sphere sweep's settings (a resolution for near-double roots) against the shapes' (none):
// quartics with known real roots, some of them in [0, 1], the same roots from both, to a few
// ulps, and as many as the known roots in [0, 1].
TEST(QuarticRootsOfBothCallers, AgreeWithEachOtherAndWithTheKnownRoots) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(-0.5, 1.5), scale(0.1, 10.0);
  int roots = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const std::array<double, 4> r = {u(rng), u(rng), u(rng), u(rng)};
    const double k = scale(rng) * (trial % 2 ? 1.0 : -1.0);
    const Quartic q = from_roots(k, r);
    const std::vector<double> sweep = roots_with(Caller::sphere_sweep, q, 1.0, false);
    const std::vector<double> shapes = roots_with(Caller::shapes, q, 1.0, false);
    // Roots closer than 1e-3 are left to the cases above (a touch may count once).
    bool close_pair = false;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) close_pair |= std::abs(r[i] - r[j]) < 1e-3;
    }
    if (close_pair) continue;
    const auto inside =
        std::count_if(r.begin(), r.end(), [](double x) { return x >= 0.0 && x <= 1.0; });
    ASSERT_EQ(int(sweep.size()), int(inside)) << "trial " << trial;
    ASSERT_EQ(sweep.size(), shapes.size()) << "trial " << trial;
    for (size_t i = 0; i < sweep.size(); ++i) {
      EXPECT_NEAR(sweep[i], shapes[i], 1e-9) << "trial " << trial;
    }
    roots += int(sweep.size());
  }
  EXPECT_GT(roots, 2000);
}

}  // namespace
}  // namespace convray
