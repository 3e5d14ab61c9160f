#pragma once
// Quartics in power form, q(v) = c0 + c1 v + c2 v^2 + c3 v^3 + c4 v^4: the field of blob
// spheres (and skeleton points) along a ray is exactly one between consecutive support ends.
// What the sphere sweep needs of them: a sphere's term, evaluation, a change of origin, and
// the Bernstein control points over an interval (whose hull bounds q there).
#include <array>

#include "core/bernstein.hpp"

namespace convray::implicit {

struct Quartic {
  std::array<double, 5> c{};  // constant first

  double operator()(double v) const {
    return (((c[4] * v + c[3]) * v + c[2]) * v + c[1]) * v + c[0];
  }
  double slope(double v) const {
    return ((4.0 * c[4] * v + 3.0 * c[3]) * v + 2.0 * c[2]) * v + c[1];
  }
  Quartic& operator+=(const Quartic& o) {
    for (int k = 0; k < 5; ++k) c[k] += o.c[k];
    return *this;
  }
  Quartic& operator-=(const Quartic& o) {
    for (int k = 0; k < 5; ++k) c[k] -= o.c[k];
    return *this;
  }
};

// One sphere's field along the ray, k (h2 - (v - vc)^2)^2 with k = strength / radius^4, h2 the
// squared half chord and vc the closest approach, in the variable v (valid on the chord only).
// Written with m = vc^2 - h2 so the constant and linear terms are single products.
inline Quartic sphere_term(double k, double h2, double vc) {
  const double m = vc * vc - h2;
  return {{k * m * m, -4.0 * k * vc * m, k * (4.0 * vc * vc + 2.0 * m), -4.0 * k * vc, k}};
}

// The same quartic in w = v - d: q(w + d) (core/bernstein.hpp's Taylor shift).
inline Quartic shifted(const Quartic& q, double d) { return {shift_power_form(q.c, d)}; }

// Bernstein control points of q over [0, width] (core/bernstein.hpp): q(width s) =
// sum b_j C(4,j) s^j (1-s)^(4-j). The polynomial lies in their convex hull; b0 and b4 are the
// end values.
inline std::array<double, 5> bernstein(const Quartic& q, double width) {
  return bernstein_from_power(q.c, width);
}

}  // namespace convray::implicit
