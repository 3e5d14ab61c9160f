#pragma once
// Root isolation of a degree-6 polynomial in Bernstein form by Bézier clipping (Sederberg and
// Nishita): the curve lies in the convex hull of its control points, so clip the parameter
// range to where that hull meets the x-axis, subdivide when clipping stalls, repeat.
//
// Our polynomials are fits with a known error bound, so we clip against a band |y| <= band
// instead of the axis: every region that comes back may hold a root of the exact function,
// and no root of the exact function lies outside them.
#include <vector>

#include "implicit/interval_fit.hpp"

namespace convray::implicit {

struct Region {
  double lo = 0.0, hi = 0.0;  // in the polynomial's parameter s in [0, 1]
};

// Appends, in ascending order, regions of [0, 1] where the polynomial with Bernstein
// coefficients `b` may lie within `band` of zero: each is narrower than `resolution`, or the
// whole polynomial stays inside the band over it. Touching regions are merged. With
// `first_only` it stops after the first region.
void isolate_band(const Poly6& b, double band, double resolution, bool first_only,
                  std::vector<Region>& out);

// De Casteljau: the Bernstein coefficients of the same polynomial over [a, c] within [0, 1].
Poly6 bernstein_restrict(const Poly6& b, double a, double c);

}  // namespace convray::implicit
