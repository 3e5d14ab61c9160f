#pragma once
// The one polynomial root finder: the real roots of a polynomial of degree <= 8 on an
// interval, found without closed forms (whose cancellations lose digits near double roots, or
// for tori seen from afar). Bernstein isolation (core/bernstein.hpp): the control points over
// [lo, hi] change sign V times; V = 0: no root; V = 1 and nonzero ends: exactly one, and the
// piece is its bracket; V >= 2: halve the piece (de Casteljau) and look again (beside the
// middle where that is a root to rounding, so that no bracket starts on a root it does not
// hold). Halving never adds variations, so at most degree / 2 pieces are halved at each
// depth. The control points are taken about the point of [lo, hi] nearest 0 (0 itself where
// the interval holds it, as two pieces), so that the change of origin rounds no more than
// Horner's rule does anywhere on the interval. Each bracket is refined by the one bracketed
// refiner (core/bracket_refine.hpp) on the power form, to a few ulps of the root. Most
// pieces of a ray hold no root, and the signs of a handful of control points say so at once.
// Used by the shapes of geometry/ (tori, polynomial surfaces, lathes, sors, outlines) and
// the sphere sweep of blob spheres (implicit/sphere_sweep).
#include <span>

namespace convray {

inline constexpr int kMaxPolynomialDegree = 8;

// Value of sum c[i] x^i (Horner).
double evaluate_polynomial(std::span<const double> c, double x);

// An interval holding exactly one root: f_lo and f_hi (the polynomial's values at lo and hi)
// differ in sign; or an exact zero, lo == hi with f_lo == f_hi == 0.
struct RootBracket {
  double lo = 0.0, hi = 0.0, f_lo = 0.0, f_hi = 0.0;
  bool exact() const { return lo == hi; }
};

// What is reported, for both calls below (c holds sum c[i] x^i, constant first, at most
// kMaxPolynomialDegree + 1 coefficients; leading zero coefficients lower the degree):
// - every root of odd multiplicity in [lo, hi] (every sign change), once, ascending;
// - a root of even multiplicity (a touch) where the polynomial is exactly zero at an end of a
//   piece (lo, hi, 0, and the halving points), or where a pair of roots closer than
//   `resolution` crosses zero: a piece narrower than `resolution` (or at the rounding limit of
//   its ends) is not halved any more; its ends' signs differ: one root; they agree: two roots
//   where the middle has the other sign, none where it has the same (it only touches zero);
// - nothing for lo >= hi, and nothing where the interval is so wide, or the coefficients so
//   large, that the control points overflow even over the interval clipped to the roots'
//   bound.

// The brackets of the roots in [lo, hi], ascending, written to `out` (room for the degree's
// count); returns how many. f_lo and f_hi are the values of the power form at the ends
// (Horner's), unless rounding makes those fail to differ in sign (a root within rounding of
// an end), where they are the Bernstein form's. A caller may refine a bracket on another
// function with the same sign changes (the torus: its distance-like function, better
// conditioned than the quartic's coefficients).
int polynomial_brackets(std::span<const double> c, double lo, double hi, RootBracket* out,
                        double resolution = 0.0);

// The roots themselves, each bracket refined on the polynomial; ascending, written to `out`
// (room for the degree's count, or max_roots when fewer); returns how many. With `max_roots`
// 1, the smallest alone (the isolation stops there).
int polynomial_roots(std::span<const double> c, double lo, double hi, double* out,
                     int max_roots = kMaxPolynomialDegree, double resolution = 0.0);

// The root in one bracket, refined on the polynomial.
double refine_polynomial_root(std::span<const double> c, const RootBracket& bracket);

// Stable roots of a t^2 + 2 half_b t + c = 0 (a = 0: the linear equation); ascending;
// returns how many (0, 1 or 2; a double root is returned twice).
int quadratic_roots(double a, double half_b, double c, double out[2]);

}  // namespace convray
