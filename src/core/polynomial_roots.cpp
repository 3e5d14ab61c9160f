#include "core/polynomial_roots.hpp"

#include <algorithm>
#include <cmath>

#include "core/bracket_refine.hpp"

namespace convray {
namespace {

int brackets_of_degree(std::span<const double> c, double lo, double hi, RootBracket* out) {
  int degree = int(c.size()) - 1;
  while (degree > 0 && c[size_t(degree)] == 0.0) --degree;
  if (degree <= 0) return 0;
  c = c.first(size_t(degree) + 1);
  if (degree == 1) {
    const double x = -c[0] / c[1];
    if (x >= lo && x <= hi) {
      out[0] = {x, x, 0.0, 0.0};  // a linear root is exact as one division rounds it
      return 1;
    }
    return 0;
  }
  // Critical points: the derivative's roots split [lo, hi] into monotone pieces.
  double slope[kMaxPolynomialDegree];
  for (int i = 1; i <= degree; ++i) slope[i - 1] = double(i) * c[size_t(i)];
  double ends[kMaxPolynomialDegree + 1];
  int end_count = 0;
  ends[end_count++] = lo;
  end_count += polynomial_roots(std::span<const double>(slope, size_t(degree)), lo, hi,
                                ends + end_count);
  ends[end_count++] = hi;

  // One root at most per monotone piece; exact zeros at the pieces' ends count once. (The
  // count never exceeds the degree, even if rounding makes more ends exactly zero.)
  int count = 0;
  auto add = [&](const RootBracket& bracket) {
    if (count == degree) return;
    if (bracket.exact() && count > 0 && out[count - 1].exact() && out[count - 1].lo == bracket.lo) {
      return;  // a zero shared by two pieces' ends
    }
    out[count++] = bracket;
  };
  double f_left = evaluate_polynomial(c, lo);
  for (int k = 0; k + 1 < end_count; ++k) {
    const double a = ends[k], b = ends[k + 1];
    const double f_right = evaluate_polynomial(c, b);
    if (f_left == 0.0) {
      add({a, a, 0.0, 0.0});
    } else if (f_right != 0.0 && (f_left < 0.0) != (f_right < 0.0) && b > a) {
      add({a, b, f_left, f_right});
    }
    f_left = f_right;
  }
  if (f_left == 0.0) add({hi, hi, 0.0, 0.0});
  return count;
}

}  // namespace

double evaluate_polynomial(std::span<const double> c, double x) {
  double value = 0.0;
  for (size_t i = c.size(); i-- > 0;) value = value * x + c[i];
  return value;
}

int polynomial_brackets(std::span<const double> c, double lo, double hi, RootBracket* out) {
  if (c.size() > size_t(kMaxPolynomialDegree) + 1 || !(lo <= hi)) return 0;
  return brackets_of_degree(c, lo, hi, out);
}

double refine_polynomial_root(std::span<const double> c, const RootBracket& bracket) {
  if (bracket.exact()) return bracket.lo;
  return refine_bracket(bracket.lo, bracket.hi, bracket.f_lo, bracket.f_hi,
                        [c](double x) { return evaluate_polynomial(c, x); });
}

int polynomial_roots(std::span<const double> c, double lo, double hi, double* out,
                     int max_roots) {
  RootBracket brackets[kMaxPolynomialDegree];
  const int bracket_count = polynomial_brackets(c, lo, hi, brackets);
  int count = 0;
  for (int k = 0; k < bracket_count && count < max_roots; ++k) {
    const double x = refine_polynomial_root(c, brackets[k]);
    if (count == 0 || out[count - 1] != x) out[count++] = x;  // a root on a shared end
  }
  return count;
}

int quadratic_roots(double a, double half_b, double c, double out[2]) {
  if (a == 0.0) {
    if (half_b == 0.0) return 0;
    out[0] = -c / (2.0 * half_b);
    return 1;
  }
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0.0) return 0;
  // q has the sign of half_b so that no digits cancel; the roots are q / a and c / q.
  const double q = -(half_b + std::copysign(std::sqrt(discriminant), half_b));
  if (q == 0.0) {
    out[0] = out[1] = 0.0;  // half_b = c = 0: the double root 0
    return 2;
  }
  const double r0 = q / a, r1 = c / q;
  out[0] = std::min(r0, r1);
  out[1] = std::max(r0, r1);
  return 2;
}

}  // namespace convray
