#pragma once
// Polynomials in Bernstein form, the one place of their operations: control points from the
// power form over an interval, their sign variations (Descartes' rule), and de Casteljau's
// split. Used by the one polynomial root finder (core/polynomial_roots), the sphere sweep's
// hull test, and Bezier clipping of the implicit tracer's fits (implicit/bezier_clip).
//
// A polynomial of degree n over [0, 1] is sum b_j C(n,j) s^j (1-s)^(n-j); it lies in the convex
// hull of its control points b_j, b_0 and b_n are its end values, and it has at most V roots
// in (0, 1), V the sign changes along b_0..b_n (exactly one when V = 1).
//
// de_casteljau_split interpolates x + s (y - x); de_casteljau_halve splits at s = 1/2 with the
// midpoint 0.5 (x + y), which rounds once (exactly half the rounded sum) where the general
// form rounds twice, so halving stays the exact average the root isolation was built on, and
// keeps the signs of its inputs: halving never adds sign variations.
#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace convray {

// The same polynomial about another origin: c(x + d), by repeated synthetic division
// (Taylor's shift); c holds the power coefficients, constant first.
template <size_t N>
std::array<double, N> shift_power_form(std::array<double, N> c, double d) {
  for (size_t i = 0; i + 1 < N; ++i) {
    for (size_t k = N - 1; k-- > i;) c[k] += d * c[k + 1];
  }
  return c;
}

namespace bernstein_detail {

constexpr long long choose(long long n, long long k) {
  long long c = 1;
  for (long long i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

constexpr long long gcd(long long a, long long b) { return b == 0 ? a : gcd(b, a % b); }

// p C(j,i) / C(n,i), the fraction reduced and known at compile time: weights 1, 1/2, 1/4
// and 3/4 cost no rounding, and no operation is spent on a factor 1.
template <size_t n, size_t j, size_t i>
double weighted(double p) {
  constexpr long long a = choose(j, i), b = choose(n, i), g = gcd(a, b);
  constexpr double num = double(a / g), den = double(b / g);
  if constexpr (num != 1.0) p = p * num;
  if constexpr (den != 1.0) p = p / den;
  return p;
}

// x width^k, a product at a time.
template <size_t k>
double times_power(double x, double width) {
  for (size_t m = 0; m < k; ++m) x = x * width;
  return x;
}

// b_j = p_0 + sum_{1 <= i <= j} p_i C(j,i) / C(n,i), summed in that order.
template <size_t n, size_t j, size_t... I>
double control_point(const std::array<double, n + 1>& p, std::index_sequence<I...>) {
  double sum = p[0];
  ((sum = sum + weighted<n, j, I + 1>(p[I + 1])), ...);
  return sum;
}

template <size_t N, size_t... J>
std::array<double, N> control_points(const std::array<double, N>& c, double width,
                                     std::index_sequence<J...>) {
  const std::array<double, N> p = {times_power<J>(c[J], width)...};
  return {control_point<N - 1, J>(p, std::make_index_sequence<J>())...};
}

}  // namespace bernstein_detail

// Control points over [0, width] of sum c_i x^i: with p_i = c_i width^i,
// b_j = sum_{i <= j} p_i C(j,i) / C(n,i). Every weight is positive: each b_j carries at most a
// few roundings of sum |p_i|, the polynomial's own size on the interval (conditioning stays
// that of the power form about 0).
template <size_t N>
std::array<double, N> bernstein_from_power(const std::array<double, N>& c, double width) {
  return bernstein_detail::control_points(c, width, std::make_index_sequence<N>());
}

// Sign changes along the control points, zeros skipped (Descartes' convention).
template <size_t N>
int sign_variations(const std::array<double, N>& b) {
  int count = 0;
  double last = 0.0;
  for (double x : b) {
    if (x == 0.0) continue;
    if (last != 0.0 && (x < 0.0) != (last < 0.0)) ++count;
    last = x;
  }
  return count;
}

// The triangle of repeated interpolations: left[k] and right[n - k] are its edges.
template <size_t N, class Interpolate>
void de_casteljau(const std::array<double, N>& b, Interpolate&& interpolate,
                  std::type_identity_t<std::array<double, N>>* left,
                  std::type_identity_t<std::array<double, N>>* right) {
  constexpr int kDegree = int(N) - 1;
  std::array<double, N> work = b, l{}, r{};
  for (int level = 0; level <= kDegree; ++level) {
    l[level] = work[0];
    r[kDegree - level] = work[kDegree - level];
    for (int k = 0; k < kDegree - level; ++k) work[k] = interpolate(work[k], work[k + 1]);
  }
  if (left) *left = l;
  if (right) *right = r;
}

// Splits at s: the coefficients over [0, s] (left) and [s, 1] (right); either may be null.
// (N is deduced from b alone, so either output may be passed as nullptr.)
template <size_t N>
void de_casteljau_split(const std::array<double, N>& b, double s,
                        std::type_identity_t<std::array<double, N>>* left,
                        std::type_identity_t<std::array<double, N>>* right) {
  de_casteljau(b, [s](double x, double y) { return x + s * (y - x); }, left, right);
}

// Splits at the middle.
template <size_t N>
void de_casteljau_halve(const std::array<double, N>& b, std::array<double, N>& left,
                        std::array<double, N>& right) {
  de_casteljau(b, [](double x, double y) { return 0.5 * (x + y); }, &left, &right);
}

}  // namespace convray
