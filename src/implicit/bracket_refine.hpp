#pragma once
// The safeguarded bracketed refiner of the ray tracers: Illinois regula falsi on a
// sign-changing bracket, with a bisection step every fourth iteration and whenever the secant
// leaves the bracket, until the bracket is a few ulps wide or the function is exactly zero.
// `g(t)` is the exact function (the field minus T); g_lo = g(lo) and g_hi = g(hi) differ in
// sign. Returns the end of the final bracket where |g| is smaller (or the exact zero).
#include <algorithm>
#include <cmath>
#include <limits>

namespace convray::implicit {

template <class Function>
double refine_bracket(double lo, double hi, double g_lo, double g_hi, Function&& g) {
  int side = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double width = hi - lo;
    const double ulps =
        8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi));
    if (width <= ulps) break;
    double t = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (iteration % 4 == 3 || !(t > lo && t < hi)) t = 0.5 * (lo + hi);
    const double value = g(t);
    if (value == 0.0) return t;
    if ((value < 0.0) == (g_lo < 0.0)) {
      lo = t;
      g_lo = value;
      if (side == -1) g_hi *= 0.5;  // Illinois: the end that stays gets its weight halved
      side = -1;
    } else {
      hi = t;
      g_hi = value;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  return std::abs(g_lo) < std::abs(g_hi) ? lo : hi;
}

}  // namespace convray::implicit
