#pragma once
// The bracketed root refiners every layer shares (implicit's tracers, geometry's shapes,
// polygonize's edge crossings): the safeguarded interpolating refiner and plain bisection to
// adjacent doubles.
//
// refine_bracket: the safeguarded bracketed refiner of the ray tracers. On a sign-changing bracket
// it steps by inverse quadratic interpolation through the last three points evaluated (the
// bracket's end nearer the first point standing in for the third at first; order 1.84 near a
// simple root, against the secants' 1.62), by a secant where two of their values coincide,
// falling back to regula falsi of the bracket for the first step and to bisection whenever a step
// leaves the bracket or the steps stop shrinking; once a step is below the resolution, it lands
// just past the root's side of the last point, so the bracket closes around the root. It stops when
// the bracket is a few ulps wide or the function is exactly zero.
//
// `g(t)` is the exact function (the field minus T); g_lo = g(lo) and g_hi = g(hi) differ in
// sign. `guess`, when inside the bracket, is evaluated first, and the first step is Newton's
// with `guess_slope` when that is given (the window march passes the root of the cubic Hermite
// interpolant of its samples, accurate to O(h^4), and the interpolant's slope there). Returns
// the end of the final bracket where |g| is smaller (or the exact zero).
//
// `tolerance` (absolute, in t) widens the resolution: the bracket may stop that wide, still
// closed around the root. The tracers ask for a fraction of the kernel's radius far below what
// a picture or their tests can see (the last secant steps to a few ulps cost one or two exact
// evaluations of every primitive near the ray per root).
//
// `residual` (absolute, in g) stops at the first point evaluated where |g(t)| <= residual and
// returns that t (the ends given are not tested: the caller has their values). The polygonizer
// asks for it: its contract is a vertex with |F - T| <= tolerance * T, not a narrow bracket,
// and the steps after that point would only move every vertex within the tolerance. The
// points evaluated are the same as without it up to the stop, so it never costs evaluations;
// 0 (the default) stops only on an exact zero, as the tracers want.
//
// `close_bracket` false: once a step falls below the resolution, or a step shrank so
// fast that the point it lands on should lie well within the resolution (its error about
// step^2 / previous step, kLandingFraction of the resolution at most), return that step's
// point without evaluating it. For a caller that evaluates the root anyway, value and
// gradient, and checks it: the window march's first hit, whose normal needs the gradient
// there, spends that evaluation on a last Newton step (accepted only if it is within the
// tolerance, else the bracket is closed after all) instead of on the evaluations that close
// the bracket. On the dragon at R = 1 its roots took 3.4 evaluations instead of 3.9, one in
// 10,000 closing the bracket after the Newton check. `landing` (absolute, in t) lands
// earlier, once the next point's predicted error is below it: for a caller whose Newton step
// squares that error (the window march's first hit, kLanding there).
#include <algorithm>
#include <cmath>
#include <limits>

namespace convray {

// How far below the resolution the predicted error of a left-open refiner's last step must be.
inline constexpr double kLandingFraction = 0.1;

template <class Function>
double refine_bracket(double lo, double hi, double g_lo, double g_hi, Function&& g,
                      double guess = std::numeric_limits<double>::quiet_NaN(),
                      double guess_slope = std::numeric_limits<double>::quiet_NaN(),
                      double tolerance = 0.0, double residual = 0.0,
                      bool close_bracket = true, double landing = 0.0) {
  const bool lo_negative = g_lo < 0.0;
  double t = guess > lo && guess < hi ? guess : (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
  double last_t = 0.0, last_g = 0.0;  // the previous point evaluated, for the interpolation
  // The one before it; before the second point, the end of the bracket nearer the first.
  double older_t = std::abs(t - lo) < std::abs(hi - t) ? lo : hi;
  double older_g = older_t == lo ? g_lo : g_hi;
  bool have_last = false;
  double previous_step = hi - lo;
  int slow = 0;  // steps in a row that did not halve
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double resolution = std::max(
        tolerance,
        8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi)));
    if (hi - lo <= resolution) break;
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    const double value = g(t);
    if (std::abs(value) <= residual) return t;  // with residual 0: value == 0
    const bool root_above = (value < 0.0) == lo_negative;
    if (root_above) {
      lo = t;
      g_lo = value;
    } else {
      hi = t;
      g_hi = value;
    }
    if (hi - lo <= resolution) break;
    double next = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);  // regula falsi of the bracket
    if (have_last && value != last_g && value != older_g && last_g != older_g) {
      // Lagrange's form in the values' ratios to the newest one: products of the values
      // themselves overflow or underflow where g is scaled far from 1 (a strength of 1e200).
      const double a = last_g / value, b = older_g / value;
      next = t * a * b / ((1.0 - a) * (1.0 - b)) + last_t * b / ((a - 1.0) * (a - b)) +
             older_t * a / ((b - 1.0) * (b - a));
    } else if (have_last && value != last_g) {
      next = t - value * (t - last_t) / (value - last_g);
    } else if (!have_last && guess_slope != 0.0 && std::isfinite(guess_slope)) {
      next = t - value / guess_slope;  // Newton from the guess, with its slope
    }
    const double step = std::abs(next - t);
    slow = step > 0.5 * previous_step ? slow + 1 : 0;
    // Left open, a step that shrank fast enough is taken as landing within the
    // resolution: with superlinear convergence the next point's error is about
    // step * (step / previous_step) (see the comment at the top).
    const bool lands_within =
        !close_bracket && have_last && step < previous_step &&
        step * step < std::max(kLandingFraction * resolution, landing) * previous_step;
    if (step < 0.5 * resolution || lands_within) {
      if (!close_bracket) return std::clamp(next, lo, hi);
      // Converged to within the resolution: close the bracket on the root's side of t (a
      // point always inside it, since it is wider than the resolution).
      next = root_above ? t + 0.5 * resolution : t - 0.5 * resolution;
    } else if (!(next > lo && next < hi) || slow >= 3) {
      next = 0.5 * (lo + hi);
      slow = 0;
    }
    previous_step = std::abs(next - t);
    if (have_last) {
      older_t = last_t;
      older_g = last_g;
    }
    last_t = t;
    last_g = value;
    have_last = true;
    t = next;
  }
  return std::abs(g_lo) < std::abs(g_hi) ? lo : hi;
}

// bisect_to_rounding: bisection of a bracket [lo, hi] down to adjacent doubles (or at most
// `max_halvings` halvings), for references and shapes that want a crossing to rounding level
// with no assumption on the function's smoothness. `on_lo_side(t)` tells whether t lies on lo's
// side of the crossing; it is called only on points strictly inside the bracket. Returns the
// midpoint of the final bracket.
template <class Predicate>
double bisect_to_rounding(double lo, double hi, Predicate&& on_lo_side,
                          int max_halvings = std::numeric_limits<int>::max()) {
  for (int i = 0; i < max_halvings; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (on_lo_side(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace convray
