#pragma once
// The paper's degree-6 fits of one primitive's field along a ray (Eqs. 13-19), generalised to
// pieces whose ends are not zeros, and the Bernstein form their sums are solved in.
//
// A fit lives on [t0, t1] in the local variable s = (t - t0) / (t1 - t0) in [0, 1]. It matches
// the value and slope at both ends and the value at s = 1/4, 1/2, 3/4 (seven conditions for
// seven coefficients). On a whole support interval the end values and slopes are zero, which
// is exactly the paper's p_i; points (and flat regions of triangles) are fitted exactly.
#include <algorithm>
#include <array>
#include <cmath>

namespace convray::implicit {

using Poly6 = std::array<double, 7>;  // power coefficients in s, constant first

struct FitConditions {
  double value0 = 0.0, slope0 = 0.0;  // at s = 0; slope is dF/dt
  double value1 = 0.0, slope1 = 0.0;  // at s = 1
  double quarter[3] = {0.0, 0.0, 0.0};  // values at s = 1/4, 1/2, 3/4
};

// Power coefficients in s of the fit on an interval of length `width` (slopes scale by it).
Poly6 fit_degree6(const FitConditions& c, double width);

inline double evaluate(const Poly6& p, double s) {
  double v = p[6];
  for (int k = 5; k >= 0; --k) v = v * s + p[k];
  return v;
}

// Bernstein coefficients on [0, 1] of the degree-6 polynomial taking `values` at s = k/6.
Poly6 bernstein_from_samples(const Poly6& values);

// The fit's error rule (docs/ray-tracing.md, "Error bound"). The error is estimated from the
// exact field at s = 1/8 and 7/8, where the interpolation error of the 7 conditions peaks,
// times a safety factor; a piece whose estimate exceeds kFitTolerance of T is split at its
// middle, at most kMaxFitSplits deep.
constexpr double kFitErrorSafety = 3.0;
constexpr double kFitTolerance = 1e-3;  // of T
constexpr int kMaxFitSplits = 4;

// Bound on |fit - exact| over the piece, from the exact values at s = 1/8 and s = 7/8.
inline double fit_error_estimate(const Poly6& fit, double exact_at_1_8, double exact_at_7_8) {
  return kFitErrorSafety * std::max(std::abs(evaluate(fit, 0.125) - exact_at_1_8),
                                    std::abs(evaluate(fit, 0.875) - exact_at_7_8));
}

// Whether a piece with this error estimate, `depth` splits deep, is split in two.
inline bool fit_needs_split(double error, double threshold, int depth) {
  return error > kFitTolerance * threshold && depth < kMaxFitSplits;
}

}  // namespace convray::implicit
