// The bracketed refiners (core/bracket_refine.hpp) against roots known in closed form. The
// safeguarded refiner must end within a few ulps of the exact root for simple roots, multiple
// roots and jumps, never evaluate outside the bracket, and (being superlinear) need far fewer
// evaluations than bisection on smooth functions, fewer still from a good guess with its slope.
#include "core/bracket_refine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace convray::core {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Case {
  std::string name;
  std::function<double(double)> g;
  double lo, hi, root;  // the exact root (to double precision) inside [lo, hi]
};

std::vector<Case> cases() {
  const double sqrt2 = std::sqrt(2.0);
  return {
      {"(x - sqrt 2)(x + 3)", [=](double x) { return (x - sqrt2) * (x + 3.0); }, 0.0, 2.0, sqrt2},
      {"exp(x) - 2", [](double x) { return std::exp(x) - 2.0; }, -1.0, 3.0, std::log(2.0)},
      {"sin x near pi", [](double x) { return std::sin(x); }, 2.0, 4.5, M_PI},
      {"steep tanh", [](double x) { return std::tanh(50.0 * (x - 0.3)); }, 0.0, 1.0, 0.3},
      {"flat then steep", [](double x) { return std::pow(x, 9) - 1e-9; }, 0.0, 1.0, 0.1},
      {"triple root", [](double x) { return std::pow(x - 0.7, 3); }, 0.0, 2.0, 0.7},
      {"jump", [](double x) { return x < 0.625 ? -1.0 : 1.0; }, 0.0, 1.0, 0.625},
      {"far from zero", [](double x) { return x - 473.25005956743331; }, 472.8, 473.5,
       473.25005956743331},
      {"a field-like sextic", [](double x) { return std::pow(1.0 - x * x, 3) - 0.42; }, 0.0, 1.0,
       std::sqrt(1.0 - std::cbrt(0.42))},
  };
}

struct Outcome {
  double root;
  int evaluations;
  bool stayed_inside;
  double last_evaluated;
};

Outcome refine(const Case& c, double guess = std::nan(""), double slope = std::nan(""),
               double residual = 0.0) {
  Outcome out{0.0, 0, true, std::nan("")};
  const auto g = [&](double x) {
    ++out.evaluations;
    out.stayed_inside = out.stayed_inside && x >= c.lo && x <= c.hi;
    out.last_evaluated = x;
    return c.g(x);
  };
  out.root = residual == 0.0
                 ? refine_bracket(c.lo, c.hi, c.g(c.lo), c.g(c.hi), g, guess, slope)
                 : refine_bracket(c.lo, c.hi, c.g(c.lo), c.g(c.hi), g, guess, slope, 0.0, residual);
  return out;
}

// Where the refiner may stop: a bracket a few ulps wide (8 eps |t|), or where rounding makes g
// exactly zero first; a multiple root is only determined to where g rounds to zero.
double tolerance(const Case& c) {
  if (c.name == "triple root") return 1e-5;  // |x - r|^3 below 1e-16
  if (c.name == "flat then steep") return 1e-15;
  return 16.0 * kEps * std::max(std::abs(c.lo), std::abs(c.hi));
}

TEST(BracketRefine, EndsAtTheExactRootOfEveryKind) {
  for (const Case& c : cases()) {
    const Outcome o = refine(c);
    EXPECT_NEAR(o.root, c.root, tolerance(c)) << c.name;
    EXPECT_TRUE(o.stayed_inside) << c.name;
    EXPECT_LT(o.evaluations, 200) << c.name;
  }
}

TEST(BracketRefine, SmoothSimpleRootsTakeFarFewerEvaluationsThanBisection) {
  for (const Case& c : cases()) {
    if (c.name == "triple root" || c.name == "jump" || c.name == "steep tanh") continue;
    const Outcome o = refine(c);
    // Bisection from these brackets to a few ulps takes 48 to 52 halvings; x^9 - 1e-9 starts
    // with secants crawling along the flat part until the safeguard bisects.
    EXPECT_LE(o.evaluations, c.name == "flat then steep" ? 30 : 16) << c.name;  // x^9: slow start
  }
}

// A guess near the root with its approximate slope (as the window march's Hermite interpolant
// gives) lands within the resolution in a handful of evaluations; a wrong guess (outside the
// bracket, or with a wrong slope) still ends at the root.
TEST(BracketRefine, AGoodGuessWithItsSlopeConvergesInAFewEvaluations) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> offset(-1e-4, 1e-4), slope_error(0.9, 1.1);
  for (const Case& c : cases()) {
    if (c.name == "triple root" || c.name == "jump" || c.name == "flat then steep") continue;
    const double h = 1e-7;
    const double slope = (c.g(c.root + h) - c.g(c.root - h)) / (2.0 * h);
    for (int trial = 0; trial < 20; ++trial) {
      const double guess = c.root + offset(rng) * (c.hi - c.lo);
      const Outcome o = refine(c, guess, slope * slope_error(rng));
      EXPECT_NEAR(o.root, c.root, tolerance(c)) << c.name;
      EXPECT_LE(o.evaluations, 8) << c.name << " guess " << guess;
      const Outcome wrong = refine(c, c.hi + 1.0, -slope);
      EXPECT_NEAR(wrong.root, c.root, tolerance(c)) << c.name;
      const Outcome backwards = refine(c, guess, -slope);
      EXPECT_NEAR(backwards.root, c.root, tolerance(c)) << c.name;
      EXPECT_TRUE(backwards.stayed_inside) << c.name;
    }
  }
}

// The textbook secant method from a guess and the bracket's nearer end, to a step below
// `tolerance` (no safeguards: smooth simple roots only): the order-1.618 baseline the
// refiner's inverse quadratic steps (order 1.84, through its last three points) improve on.
int secant_evaluations(const Case& c, double guess, double tolerance) {
  double x0 = std::abs(guess - c.lo) < std::abs(c.hi - guess) ? c.lo : c.hi, g0 = c.g(x0);
  double x1 = guess, g1 = c.g(x1);
  int evaluations = 1;
  while (std::abs(x1 - x0) > tolerance && g1 != g0 && evaluations < 100) {
    const double x2 = x1 - g1 * (x1 - x0) / (g1 - g0);
    x0 = x1, g0 = g1;
    x1 = x2, g1 = c.g(x1);
    ++evaluations;
  }
  return evaluations;
}

// From a guess a few percent of the bracket off the root, the refiner steps by inverse
// quadratic interpolation through its last three points (the bracket's nearer end standing in
// for the third at first): on smooth simple roots it lands within the tolerance in no more
// evaluations than plain secants from the same guess, and in fewer over all the guesses.
TEST(BracketRefine, InverseQuadraticStepsNeedNoMoreEvaluationsThanSecants) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> offset(-0.05, 0.05);
  int refiner_total = 0, secant_total = 0;
  for (const Case& c : cases()) {
    if (c.name == "triple root" || c.name == "jump" || c.name == "flat then steep" ||
        c.name == "steep tanh") {
      continue;
    }
    const double tolerance = 1e-10 * (c.hi - c.lo);
    for (int trial = 0; trial < 20; ++trial) {
      const double guess = c.root + offset(rng) * (c.hi - c.lo);
      int evaluations = 0;
      const double root = refine_bracket(
          c.lo, c.hi, c.g(c.lo), c.g(c.hi), [&](double x) { return ++evaluations, c.g(x); },
          guess, std::nan(""), tolerance, 0.0, false);
      EXPECT_NEAR(root, c.root, tolerance) << c.name << " guess " << guess;
      const int secants = secant_evaluations(c, guess, tolerance);
      EXPECT_LE(evaluations, secants) << c.name << " guess " << guess;
      refiner_total += evaluations;
      secant_total += secants;
    }
  }
  EXPECT_LT(refiner_total, secant_total);
  std::printf("evaluations: refiner %d, secants %d\n", refiner_total, secant_total);
}

// The steps depend on g's values only through their ratios: a function scaled by 1e200 or
// 1e-160 (a convolution of strength 1e200 minus its threshold) is refined along the same
// points to rounding, to the same root, in as many evaluations; products of the values
// themselves would overflow or underflow there.
TEST(BracketRefine, ScalingTheFunctionChangesNothing) {
  for (const Case& c : cases()) {
    if (c.name == "jump") continue;
    const Outcome plain = refine(c);
    for (double scale : {1e200, 1e-160}) {
      Case scaled = c;
      scaled.g = [&, scale](double x) { return scale * c.g(x); };
      const Outcome o = refine(scaled);
      EXPECT_NEAR(o.root, c.root, tolerance(c)) << c.name << " scaled by " << scale;
      EXPECT_NEAR(o.evaluations, plain.evaluations, 1) << c.name << " scaled by " << scale;
    }
  }
}

// Left open (`close_bracket` false, for a caller that evaluates the root itself): on a smooth
// simple root the point returned is within the tolerance of the exact root, it was not
// evaluated (the caller's evaluation replaces the one that closes the bracket), and the
// refiner took at least one evaluation fewer than with the bracket closed (more where a
// secant step shrank fast enough to land within the tolerance unchecked).
TEST(BracketRefine, LeftOpenItReturnsItsLastStepUnevaluatedWithinTheTolerance) {
  for (const Case& c : cases()) {
    if (c.name == "triple root" || c.name == "jump" || c.name == "flat then steep") continue;
    for (double tolerance : {1e-10, 1e-7}) {
      const std::string what = c.name + " tolerance " + std::to_string(tolerance);
      int closed_evaluations = 0, open_evaluations = 0;
      double last_open = std::nan("");
      const double closed = refine_bracket(
          c.lo, c.hi, c.g(c.lo), c.g(c.hi),
          [&](double x) { ++closed_evaluations; return c.g(x); }, std::nan(""), std::nan(""),
          tolerance);
      const double open = refine_bracket(
          c.lo, c.hi, c.g(c.lo), c.g(c.hi),
          [&](double x) { ++open_evaluations; last_open = x; return c.g(x); }, std::nan(""),
          std::nan(""), tolerance, 0.0, false);
      EXPECT_NEAR(open, c.root, tolerance) << what;
      EXPECT_NEAR(closed, c.root, tolerance) << what;
      EXPECT_GE(open, c.lo) << what;
      EXPECT_LE(open, c.hi) << what;
      EXPECT_LE(open_evaluations, closed_evaluations) << what;
      if (open != last_open) EXPECT_LE(open_evaluations + 1, closed_evaluations) << what;
    }
  }
}

// A residual stop (the polygonizer's |F - T| <= tolerance * T) ends at the first point where
// |g| is within it: that point itself, inside the bracket, after no more evaluations than the
// refiner takes to a few ulps, and (for a simple root) within residual / |g'| of the exact
// root.
TEST(BracketRefine, AResidualStopsAtTheFirstPointWithinIt) {
  for (const Case& c : cases()) {
    if (c.name == "jump") continue;  // never within a residual below 1: the next test
    const Outcome to_ulps = refine(c);
    for (double residual : {1e-3, 1e-8, 1e-12}) {
      const Outcome o = refine(c, std::nan(""), std::nan(""), residual);
      const std::string what = c.name + " residual " + std::to_string(residual);
      EXPECT_LE(std::abs(c.g(o.root)), residual) << what;
      EXPECT_EQ(o.root, o.last_evaluated) << what;  // the point that met it, not an end
      EXPECT_TRUE(o.stayed_inside) << what;
      EXPECT_GT(o.root, c.lo) << what;
      EXPECT_LT(o.root, c.hi) << what;
      EXPECT_LE(o.evaluations, to_ulps.evaluations) << what;
      if (c.name == "triple root" || c.name == "flat then steep") continue;
      const double h = 1e-7, slope = (c.g(c.root + h) - c.g(c.root - h)) / (2.0 * h);
      EXPECT_NEAR(o.root, c.root, 2.0 * residual / std::abs(slope) + tolerance(c)) << what;
    }
  }
}

// A residual the function never comes within (the jump's |g| = 1) changes nothing.
TEST(BracketRefine, AResidualNeverReachedChangesNothing) {
  for (const Case& c : cases()) {
    if (c.name != "jump") continue;
    const Outcome to_ulps = refine(c), o = refine(c, std::nan(""), std::nan(""), 0.5);
    EXPECT_EQ(o.root, to_ulps.root);
    EXPECT_EQ(o.evaluations, to_ulps.evaluations);
  }
}

// Residual 0, given explicitly, is the default: the same points, the same answer, bit for bit.
TEST(BracketRefine, AResidualOfZeroIsTheDefault) {
  for (const Case& c : cases()) {
    const Outcome by_default = refine(c);
    int evaluations = 0;
    const double zero = refine_bracket(
        c.lo, c.hi, c.g(c.lo), c.g(c.hi), [&](double x) { return ++evaluations, c.g(x); },
        std::nan(""), std::nan(""), 0.0, 0.0);
    EXPECT_EQ(zero, by_default.root) << c.name;
    EXPECT_EQ(evaluations, by_default.evaluations) << c.name;
  }
}

// Bisection to rounding: the crossing of a predicate, located to adjacent doubles, never asking
// outside the open bracket. Oracles: a step at a known double (the answer is that double's
// neighbourhood, one ulp), cbrt(2) for x^3 - 2, and the width (hi - lo) / 2^k after k halvings.
TEST(BisectToRounding, EndsBetweenAdjacentDoublesAroundTheCrossing) {
  const double step = 0.3;
  int outside = 0;
  const double at = bisect_to_rounding(-1.0, 2.0, [&](double t) {
    outside += !(t > -1.0 && t < 2.0);
    return t < step;
  });
  EXPECT_LE(std::abs(at - step), std::nextafter(step, 1.0) - step);
  EXPECT_EQ(outside, 0);
  const double cube_root = bisect_to_rounding(1.0, 2.0, [](double t) { return t * t * t < 2.0; });
  EXPECT_NEAR(cube_root, std::cbrt(2.0), 2.0 * kEps * std::cbrt(2.0));
}

TEST(BisectToRounding, StopsAfterTheGivenNumberOfHalvings) {
  int calls = 0;
  const double at = bisect_to_rounding(
      0.0, 1.0, [&](double t) { return ++calls, t < 1.0 / 3.0; }, 10);
  EXPECT_EQ(calls, 10);
  EXPECT_LE(std::abs(at - 1.0 / 3.0), std::ldexp(1.0, -11));  // half the last width, 2^-10
}

}  // namespace
}  // namespace convray::core
