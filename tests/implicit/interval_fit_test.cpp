// The paper's degree-6 fit (interval_fit.hpp, Eqs. 13-19) against its seven conditions,
// against polynomials it must reproduce exactly (any sextic; a sphere's field along a ray;
// the plane's sextic), and Bernstein conversion against the explicit binomial formula
// (polynomial_oracle.hpp). The fit's error estimate is in fit_error_test.cpp.
#include <gtest/gtest.h>

#include <random>

#include "implicit/interval_fit.hpp"
#include "reference/polynomial_oracle.hpp"
#include "util/math.hpp"

namespace convray::implicit {
namespace {

using oracle::Coefficients;

// p'(s) of a power form, in long double.
long double power_slope(const Coefficients& a, long double s) {
  long double v = 0.0L, x = 1.0L;
  for (int k = 1; k <= 6; ++k) {
    v += k * a[k] * x;
    x *= s;
  }
  return v;
}

double magnitude(const Coefficients& a) {
  double m = 0.0;
  for (double x : a) m += std::abs(x);
  return m;
}

// The fit's conditions read off a function of t = t0 + width s, given its value and slope.
template <class F, class Slope>
FitConditions conditions_of(const F& f, const Slope& slope, double t0, double width) {
  FitConditions c;
  c.value0 = f(t0);
  c.slope0 = slope(t0);
  c.value1 = f(t0 + width);
  c.slope1 = slope(t0 + width);
  for (int j = 0; j < 3; ++j) c.quarter[j] = f(t0 + width * (j + 1) / 4.0);
  return c;
}

TEST(IntervalFit, FitMeetsItsSevenConditions) {
  std::mt19937_64 rng(1411);
  std::uniform_real_distribution<double> value(-5.0, 5.0), exponent(-3.0, 3.0);
  for (int i = 0; i < 2000; ++i) {
    FitConditions c;
    c.value0 = value(rng);
    c.slope0 = value(rng);
    c.value1 = value(rng);
    c.slope1 = value(rng);
    for (double& q : c.quarter) q = value(rng);
    if (i % 2) c.value0 = c.slope0 = c.value1 = c.slope1 = 0.0;  // a whole support interval
    const double width = std::pow(10.0, exponent(rng));
    const Poly6 fit = fit_degree6(c, width);
    const Coefficients& p = fit;  // the same array type: power coefficients, constant first
    // Slopes are dF/dt: in s they scale by the width. The inverse's entries run to about 10^3,
    // so the coefficients round to about 10^3 ulps of the conditions' size.
    double scale = std::abs(c.value0) + std::abs(c.value1) + std::abs(c.slope0 * width) +
                   std::abs(c.slope1 * width);
    for (double q : c.quarter) scale += std::abs(q);
    EXPECT_NEAR(double(oracle::power_value(p, 0.0L)), c.value0, 1e-11 * scale) << i;
    EXPECT_NEAR(double(oracle::power_value(p, 1.0L)), c.value1, 1e-11 * scale) << i;
    EXPECT_NEAR(double(power_slope(p, 0.0L)), c.slope0 * width, 1e-11 * scale) << i;
    EXPECT_NEAR(double(power_slope(p, 1.0L)), c.slope1 * width, 1e-11 * scale) << i;
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(double(oracle::power_value(p, (j + 1) / 4.0L)), c.quarter[j], 1e-11 * scale)
          << i << " quarter " << j;
    }
    for (double s : {0.1, 0.37, 0.9}) {
      EXPECT_NEAR(evaluate(fit, s), double(oracle::power_value(p, s)), 1e-11 * scale) << i;
    }
  }
}

// Seven conditions fix a sextic: any polynomial of degree <= 6 comes back coefficient by
// coefficient.
TEST(IntervalFit, ReproducesEveryPolynomialOfDegreeSix) {
  std::mt19937_64 rng(1412);
  std::uniform_real_distribution<double> coefficient(-3.0, 3.0), exponent(-2.0, 2.0);
  for (int i = 0; i < 2000; ++i) {
    Coefficients q;  // in s
    for (double& x : q) x = coefficient(rng);
    const double width = std::pow(10.0, exponent(rng));
    // The conditions read off q at s = 0, 1/4, 1/2, 3/4, 1; slopes in t are q'(s) / width.
    FitConditions c;
    c.value0 = double(oracle::power_value(q, 0.0L));
    c.value1 = double(oracle::power_value(q, 1.0L));
    c.slope0 = double(power_slope(q, 0.0L)) / width;
    c.slope1 = double(power_slope(q, 1.0L)) / width;
    for (int j = 0; j < 3; ++j) c.quarter[j] = double(oracle::power_value(q, (j + 1) / 4.0L));
    const Poly6 fit = fit_degree6(c, width);
    for (int k = 0; k <= 6; ++k) EXPECT_NEAR(fit[k], q[k], 1e-12 * magnitude(q)) << i << " " << k;
  }
}

// Eqs. 13-19 on a whole support: for a point (or blob sphere) the field along a ray at distance
// b from the centre is (1 - (b^2 + (t - tc)^2)/R^2)^2, a quartic with double zeros at the chord's
// ends. The fit from zero ends and the three quarter values is that quartic.
TEST(IntervalFit, PointFieldAlongARayIsFittedExactly) {
  std::mt19937_64 rng(1413);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double R = 0.1 + 10.0 * unit(rng), b = R * unit(rng), tc = 50.0 * unit(rng);
    const double half = std::sqrt(R * R - b * b), t0 = tc - half, width = 2.0 * half;
    const auto f = [&](double t) {
      const double k = 1.0 - (b * b + (t - tc) * (t - tc)) / (R * R);
      return k > 0.0 ? k * k : 0.0;
    };
    FitConditions c;  // zero value and slope at both ends: the paper's p_i
    for (int j = 0; j < 3; ++j) c.quarter[j] = f(t0 + width * (j + 1) / 4.0);
    const Poly6 fit = fit_degree6(c, width);
    for (int j = 0; j <= 64; ++j) {
      const double s = j / 64.0;
      EXPECT_NEAR(evaluate(fit, s), f(t0 + s * width), 1e-12) << i << " s " << s;
    }
    EXPECT_NEAR(fit[5], 0.0, 1e-10) << i;  // a quartic: no s^5, s^6 terms
    EXPECT_NEAR(fit[6], 0.0, 1e-10) << i;
  }
}

// The field of an infinite plane at height h, (pi/3) R^2 (1 - h^2/R^2)^3, is a sextic along
// any ray crossing the slab |h| < R: fitted exactly, also on a piece whose ends are not zeros
// (a split).
TEST(IntervalFit, PlaneFieldAlongARayIsFittedExactly) {
  std::mt19937_64 rng(1414);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double R = 0.1 + 5.0 * unit(rng), cosine = 0.05 + 0.95 * unit(rng);
    // h(t) = R - cosine t: the ray enters the slab at t = 0 and leaves it at 2R / cosine.
    const auto f = [&](double t) {
      const double h = R - cosine * t, k = 1.0 - h * h / (R * R);
      return k > 0.0 ? kPi / 3.0 * R * R * k * k * k : 0.0;
    };
    const auto slope = [&](double t) {
      const double h = R - cosine * t, k = 1.0 - h * h / (R * R);
      return k > 0.0 ? kPi / 3.0 * R * R * 3.0 * k * k * (2.0 * h * cosine / (R * R)) : 0.0;
    };
    const double whole = 2.0 * R / cosine;
    const double t0 = i % 2 ? 0.5 * whole * unit(rng) : 0.0;
    const double width = i % 2 ? (whole - t0) * (0.1 + 0.9 * unit(rng)) : whole;
    const Poly6 fit = fit_degree6(conditions_of(f, slope, t0, width), width);
    const double peak = kPi / 3.0 * R * R;
    for (int j = 0; j <= 64; ++j) {
      const double s = j / 64.0;
      EXPECT_NEAR(evaluate(fit, s), f(t0 + s * width), 1e-11 * peak) << i << " s " << s;
    }
  }
}

TEST(IntervalFit, BernsteinFromSamplesMatchesTheBinomialConversion) {
  std::mt19937_64 rng(1415);
  std::uniform_real_distribution<double> coefficient(-10.0, 10.0);
  for (int i = 0; i < 2000; ++i) {
    Coefficients q;
    for (double& x : q) x = coefficient(rng);
    Poly6 samples;
    for (int k = 0; k <= 6; ++k) samples[k] = double(oracle::power_value(q, k / 6.0L));
    const Poly6 b = bernstein_from_samples(samples);
    const Coefficients expected = oracle::bernstein_from_power(q);
    for (int k = 0; k <= 6; ++k) EXPECT_NEAR(b[k], expected[k], 1e-12 * magnitude(q)) << i;
    // The end coefficients are the end values.
    EXPECT_NEAR(b[0], samples[0], 1e-12 * magnitude(q));
    EXPECT_NEAR(b[6], samples[6], 1e-12 * magnitude(q));
  }
}

}  // namespace
}  // namespace convray::implicit
