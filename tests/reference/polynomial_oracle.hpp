#pragma once
// Degree-6 polynomials written out independently of src/implicit: built from their roots,
// converted between power and Bernstein form by the explicit binomial formula (not by solving
// a system or by de Casteljau, as the code under test does), and evaluated in long double.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace convray::implicit::oracle {

using Coefficients = std::array<double, 7>;  // constant first

inline double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

// scale * prod (s - root), padded with zeros up to degree 6 (at most six roots).
inline Coefficients power_from_roots(const std::vector<double>& roots, double scale) {
  Coefficients p{};
  p[0] = scale;
  int degree = 0;
  for (double r : roots) {
    for (int k = degree + 1; k >= 1; --k) p[k] = p[k - 1] - r * p[k];
    p[0] = -r * p[0];
    ++degree;
  }
  return p;
}

// Multiplies a power form by the quadratic (s - re)^2 + im^2, which has no real root.
inline Coefficients times_complex_pair(const Coefficients& p, double re, double im) {
  const double q[3] = {re * re + im * im, -2.0 * re, 1.0};
  Coefficients out{};
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 3 && i + j < 7; ++j) out[i + j] += p[i] * q[j];
  }
  return out;
}

// s^k = sum_{j >= k} [C(j, k) / C(6, k)] B_{j,6}(s): the Bernstein coefficients of a power form.
inline Coefficients bernstein_from_power(const Coefficients& a) {
  Coefficients b{};
  for (int j = 0; j <= 6; ++j) {
    long double sum = 0.0L;
    for (int k = 0; k <= j; ++k) sum += (long double)(binomial(j, k) / binomial(6, k)) * a[k];
    b[j] = double(sum);
  }
  return b;
}

inline long double power_value(const Coefficients& a, long double s) {
  long double v = 0.0L, x = 1.0L;
  for (double c : a) {
    v += c * x;
    x *= s;
  }
  return v;
}

// sum_k b_k C(6, k) s^k (1 - s)^(6 - k), term by term.
inline long double bernstein_value(const Coefficients& b, long double s) {
  long double up[7], down[7];  // s^k and (1 - s)^k
  up[0] = down[0] = 1.0L;
  for (int k = 1; k <= 6; ++k) {
    up[k] = up[k - 1] * s;
    down[k] = down[k - 1] * (1.0L - s);
  }
  long double v = 0.0L;
  for (int k = 0; k <= 6; ++k) v += b[k] * (long double)binomial(6, k) * up[k] * down[6 - k];
  return v;
}

// max |p'| on [0, 1] is at most 6 max |b_{k+1} - b_k| (the derivative's Bernstein form).
inline double slope_bound(const Coefficients& b) {
  double m = 0.0;
  for (int k = 0; k < 6; ++k) m = std::max(m, 6.0 * std::abs(b[k + 1] - b[k]));
  return m;
}

}  // namespace convray::implicit::oracle
