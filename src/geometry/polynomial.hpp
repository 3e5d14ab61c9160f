#pragma once
// Real roots of small polynomials on an interval, found without closed forms: the roots of
// the derivative split the interval into pieces where the polynomial is monotone, and each
// piece whose ends differ in sign holds exactly one root, refined in that bracket by the one
// bracketed refiner (core/bracket_refine.hpp). Robust where the quartic formula loses digits
// (tori seen from afar, nearly double roots).
#include <span>

namespace convray::geometry {

inline constexpr int kMaxPolynomialDegree = 8;

// Value of sum c[i] x^i (Horner).
double evaluate_polynomial(std::span<const double> c, double x);

// Roots of sum c[i] x^i in [lo, hi], ascending, written to `out` (room for the degree's
// count, at most kMaxPolynomialDegree); returns how many. Roots of odd multiplicity are all
// found; one of even multiplicity (a tangency) only where the polynomial is exactly zero at
// a critical point. Leading zero coefficients lower the degree.
int polynomial_roots(std::span<const double> c, double lo, double hi, double* out);

// Stable roots of a t^2 + 2 half_b t + c = 0 (a = 0: the linear equation); ascending;
// returns how many (0, 1 or 2; a double root is returned twice).
int quadratic_roots(double a, double half_b, double c, double out[2]);

}  // namespace convray::geometry
