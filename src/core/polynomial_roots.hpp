#pragma once
// The one polynomial root finder: the real roots of a polynomial of small degree on an
// interval, found without closed forms (whose cancellations lose digits near double roots, or
// for tori seen from afar). The roots of the derivative split the interval into pieces where
// the polynomial is monotone; each piece whose ends differ in sign holds exactly one root
// (its bracket), refined by the one bracketed refiner (core/bracket_refine.hpp). Used by the
// shapes of geometry/ (tori, polynomial surfaces, lathes, sors, outlines); the exact twin of
// the sphere sweep's faster Bernstein isolator (implicit/quartic_roots.hpp).
#include <span>

namespace convray {

inline constexpr int kMaxPolynomialDegree = 8;

// Value of sum c[i] x^i (Horner).
double evaluate_polynomial(std::span<const double> c, double x);

// An interval holding exactly one root: the polynomial is monotone on [lo, hi] and f_lo, f_hi
// (its values there) differ in sign; or an exact zero, lo == hi with f_lo == f_hi == 0.
struct RootBracket {
  double lo = 0.0, hi = 0.0, f_lo = 0.0, f_hi = 0.0;
  bool exact() const { return lo == hi; }
};

// The brackets of the roots of sum c[i] x^i in [lo, hi], ascending, written to `out` (room for
// the degree's count, at most kMaxPolynomialDegree); returns how many. Roots of odd
// multiplicity are all bracketed; one of even multiplicity (a tangency) only where the
// polynomial is exactly zero at a critical point. Leading zero coefficients lower the degree.
// A caller may refine a bracket on another function with the same sign changes (the torus:
// its distance-like function, better conditioned than the quartic's coefficients).
int polynomial_brackets(std::span<const double> c, double lo, double hi, RootBracket* out);

// The roots themselves, each bracket refined on the polynomial; ascending, written to `out`
// (room for the degree's count); returns how many. With `max_roots` 1, the smallest alone.
int polynomial_roots(std::span<const double> c, double lo, double hi, double* out,
                     int max_roots = kMaxPolynomialDegree);

// The root in one bracket, refined on the polynomial.
double refine_polynomial_root(std::span<const double> c, const RootBracket& bracket);

// Stable roots of a t^2 + 2 half_b t + c = 0 (a = 0: the linear equation); ascending;
// returns how many (0, 1 or 2; a double root is returned twice).
int quadratic_roots(double a, double half_b, double c, double out[2]);

}  // namespace convray
