#pragma once
// The paper's degree-6 fits of one primitive's field along a ray (Eqs. 13-19), generalised to
// pieces whose ends are not zeros, and the Bernstein form their sums are solved in.
//
// A fit lives on [t0, t1] in the local variable s = (t - t0) / (t1 - t0) in [0, 1]. It matches
// the value and slope at both ends and the value at s = 1/4, 1/2, 3/4 (seven conditions for
// seven coefficients). On a whole support interval the end values and slopes are zero, which
// is exactly the paper's p_i; points (and flat regions of triangles) are fitted exactly.
#include <array>

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

}  // namespace convray::implicit
