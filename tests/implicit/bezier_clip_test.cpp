// Bézier clipping of degree-6 Bernstein polynomials (bezier_clip.hpp) against polynomials
// built from known roots and converted to Bernstein form by the explicit binomial formula
// (polynomial_oracle.hpp), and against dense sampling of the band |p| <= band in long double.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "implicit/bezier_clip.hpp"
#include "reference/polynomial_oracle.hpp"

namespace convray::implicit {
namespace {

using oracle::Coefficients;

double largest_magnitude(const Coefficients& c) {
  double m = 0.0;
  for (double x : c) m = std::max(m, std::abs(x));
  return m;
}

std::vector<Region> isolate(const Coefficients& b, double band, double resolution,
                            bool first_only = false) {
  std::vector<Region> out;
  isolate_band(b, band, resolution, first_only, out);
  return out;
}

// Regions come back inside [0, 1], ascending, each non-empty, and apart (touching ones merge).
void expect_well_formed(const std::vector<Region>& regions, int seed) {
  for (size_t i = 0; i < regions.size(); ++i) {
    EXPECT_LE(0.0, regions[i].lo) << seed;
    EXPECT_LE(regions[i].lo, regions[i].hi) << seed;
    EXPECT_LE(regions[i].hi, 1.0) << seed;
    if (i > 0) EXPECT_LT(regions[i - 1].hi, regions[i].lo) << seed;
  }
}

TEST(BezierClip, RestrictionIsTheSamePolynomialOnTheSubinterval) {
  std::mt19937_64 rng(1401);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coefficient(-10.0, 10.0);
  for (int i = 0; i < 1000; ++i) {
    Coefficients power;
    for (double& c : power) c = coefficient(rng);
    const Coefficients b = oracle::bernstein_from_power(power);
    double a = unit(rng), c = unit(rng);
    if (a > c) std::swap(a, c);
    if (i % 10 == 0) a = 0.0;  // the ends of the interval
    if (i % 10 == 1) c = 1.0;
    const Coefficients restricted = bernstein_restrict(b, a, c);
    double scale = 0.0;
    for (double x : power) scale += std::abs(x);
    for (int j = 0; j <= 20; ++j) {
      const double u = j / 20.0;
      EXPECT_NEAR(double(oracle::bernstein_value(restricted, u)),
                  double(oracle::power_value(power, a + (c - a) * (long double)u)), 1e-12 * scale)
          << i << " " << a << " " << c << " " << u;
    }
  }
  // The whole interval is the identity.
  const Coefficients b{1, -2, 3, -4, 5, -6, 7};
  const Coefficients same = bernstein_restrict(b, 0.0, 1.0);
  for (int k = 0; k <= 6; ++k) EXPECT_EQ(same[k], b[k]);
}

// Simple roots at least 0.01 apart in [0, 1] (sometimes exactly on an end), the other factors
// real roots outside [0, 1] or complex pairs: with a band at rounding level, one region per
// root, holding it, no wider than the resolution allows.
TEST(BezierClip, EachKnownRootLiesInItsOwnNarrowRegion) {
  std::mt19937_64 rng(1402);
  std::uniform_real_distribution<double> unit(0.0, 1.0), exponent(-3.0, 3.0);
  std::uniform_int_distribution<int> count(0, 4);
  constexpr double kResolution = 1e-7;
  int roots_checked = 0, end_roots = 0;
  for (int i = 0; i < 3000; ++i) {
    std::vector<double> inside;
    const int n = count(rng);
    while (int(inside.size()) < n) {
      const double r = unit(rng);
      if (std::all_of(inside.begin(), inside.end(),
                      [&](double x) { return std::abs(x - r) > 0.01; })) {
        inside.push_back(r);
      }
    }
    if (i % 7 == 0 && !inside.empty()) {  // a root exactly on an end
      inside[0] = i % 2 ? 0.0 : 1.0;
      if (std::count_if(inside.begin(), inside.end(),
                        [&](double x) { return std::abs(x - inside[0]) <= 0.01; }) > 1) {
        inside.erase(inside.begin() + 1, inside.end());
      }
      ++end_roots;
    }
    std::sort(inside.begin(), inside.end());
    std::vector<double> all = inside;
    const int pairs = (6 - n) / 2 * (i % 3 == 0);  // some cases with complex pairs
    while (int(all.size()) < 6 - 2 * pairs) {
      all.push_back(unit(rng) < 0.5 ? -0.05 - unit(rng) : 1.05 + unit(rng));
    }
    const double scale = (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    Coefficients power = oracle::power_from_roots(all, scale);
    for (int k = 0; k < pairs; ++k) {
      power = oracle::times_complex_pair(power, unit(rng), 0.05 + unit(rng));
    }
    const Coefficients b = oracle::bernstein_from_power(power);
    const std::vector<Region> regions = isolate(b, 1e-12 * largest_magnitude(b), kResolution);
    expect_well_formed(regions, i);
    ASSERT_EQ(regions.size(), inside.size()) << i;
    for (size_t k = 0; k < inside.size(); ++k) {
      EXPECT_LE(regions[k].lo, inside[k]) << i << " root " << inside[k];
      EXPECT_GE(regions[k].hi, inside[k]) << i << " root " << inside[k];
      // Touching regions merge: a root on a split point can take two of them.
      EXPECT_LE(regions[k].hi - regions[k].lo, 2.0 * kResolution) << i;
      ++roots_checked;
    }
  }
  EXPECT_GT(roots_checked, 4000);
  EXPECT_GT(end_roots, 300);
}

// A double root (the polynomial touches zero) and a pair 1e-4 apart: regions in the band
// hold them; a polynomial whose minimum misses the band by a margin gives none.
TEST(BezierClip, TouchingAndClusteredRootsAreKept) {
  std::mt19937_64 rng(1403);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double r = 0.05 + 0.9 * unit(rng);
    const double scale = i % 2 ? 1.0 : -3.0;
    // scale (s - r)^2 (s - x1)(s - x2) ((s - re)^2 + im^2), x1, x2 outside [0, 1].
    Coefficients power = oracle::power_from_roots({r, r, -0.5 - unit(rng), 1.5 + unit(rng)}, scale);
    power = oracle::times_complex_pair(power, unit(rng), 0.2 + unit(rng));
    Coefficients b = oracle::bernstein_from_power(power);
    const double band = 1e-9 * largest_magnitude(b);
    std::vector<Region> regions = isolate(b, band, 1e-7);
    expect_well_formed(regions, i);
    ASSERT_FALSE(regions.empty()) << i;
    EXPECT_TRUE(std::any_of(regions.begin(), regions.end(),
                            [&](const Region& g) { return g.lo <= r && r <= g.hi; }))
        << i << " double root " << r;

    // Lifted away from zero by 10 bands (towards the side the polynomial stays on): nothing.
    Coefficients lifted = b;
    const double side = oracle::power_value(power, r + 0.5 * (r < 0.5 ? 1.0 : -1.0)) > 0 ? 1 : -1;
    for (double& x : lifted) x += side * 10.0 * band;
    EXPECT_TRUE(isolate(lifted, band, 1e-7).empty()) << i;

    // Two roots 1e-4 apart: both inside regions.
    const double close[2] = {r, r + 1e-4 * (r < 0.5 ? 1.0 : -1.0)};
    power = oracle::power_from_roots({close[0], close[1], -0.5, 1.5, 2.5, -1.5}, scale);
    b = oracle::bernstein_from_power(power);
    regions = isolate(b, 1e-12 * largest_magnitude(b), 1e-7);
    expect_well_formed(regions, i);
    for (double root : close) {
      EXPECT_TRUE(std::any_of(regions.begin(), regions.end(),
                              [&](const Region& g) { return g.lo <= root && root <= g.hi; }))
          << i << " root " << root;
    }
  }
}

// Random polynomials and bands: every s where |p(s)| is inside the band (in long double, with
// a margin for rounding) lies in a region, and every sample inside a region has |p| within the
// band plus what the polynomial can change over one resolution.
TEST(BezierClip, RegionsCoverTheBandAndLittleElse) {
  std::mt19937_64 rng(1404);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), unit(0.0, 1.0);
  constexpr double kResolution = 1e-6;
  constexpr int kSamples = 4000;
  long long band_points = 0, region_points = 0;
  for (int i = 0; i < 1500; ++i) {
    Coefficients b;
    const double offset = 0.5 * coefficient(rng);
    for (double& x : b) x = coefficient(rng) + offset;
    const double band = std::pow(10.0, -6.0 + 5.5 * unit(rng));
    const std::vector<Region> regions = isolate(b, band, kResolution);
    expect_well_formed(regions, i);
    const double rounding = 1e-13;
    const double slack = oracle::slope_bound(b) * kResolution + rounding;
    size_t next = 0;
    for (int j = 0; j <= kSamples; ++j) {
      const double s = double(j) / kSamples;
      while (next < regions.size() && regions[next].hi < s) ++next;
      const bool in_region = next < regions.size() && regions[next].lo <= s;
      const double value = std::abs(double(oracle::bernstein_value(b, s)));
      if (value <= band - rounding) {
        ++band_points;
        EXPECT_TRUE(in_region) << i << " s " << s << " |p| " << value << " band " << band;
      }
      if (in_region) {
        ++region_points;
        EXPECT_LE(value, band + slack) << i << " s " << s << " band " << band;
      }
    }
  }
  EXPECT_GT(band_points, 100000);
  EXPECT_GE(region_points, band_points);
}

// first_only: the first region of the full answer (or the start of it, when the full run
// merged it with the next), and nothing more.
TEST(BezierClip, FirstOnlyGivesTheFirstRegion) {
  std::mt19937_64 rng(1405);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), unit(0.0, 1.0);
  int found = 0;
  for (int i = 0; i < 2000; ++i) {
    Coefficients b;
    for (double& x : b) x = coefficient(rng);
    const double band = std::pow(10.0, -8.0 + 7.0 * unit(rng));
    const std::vector<Region> all = isolate(b, band, 1e-7);
    const std::vector<Region> first = isolate(b, band, 1e-7, true);
    ASSERT_EQ(first.size(), all.empty() ? 0u : 1u) << i;
    if (all.empty()) continue;
    ++found;
    EXPECT_EQ(first[0].lo, all[0].lo) << i;
    EXPECT_LE(first[0].hi, all[0].hi) << i;
  }
  EXPECT_GT(found, 1000);
}

TEST(BezierClip, APolynomialInsideTheBandIsOneRegion) {
  const Coefficients b{0.1, -0.2, 0.05, 0.3, -0.1, 0.0, 0.2};
  const std::vector<Region> regions = isolate(b, 0.3, 1e-6);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].lo, 0.0);
  EXPECT_EQ(regions[0].hi, 1.0);
  // Entirely above the band: nothing, without any subdivision to speak of.
  EXPECT_TRUE(isolate({1.0, 2.0, 0.5, 3.0, 1.0, 0.4, 2.0}, 0.3, 1e-6).empty());
}

}  // namespace
}  // namespace convray::implicit
