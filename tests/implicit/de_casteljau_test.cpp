// De Casteljau's split (implicit/de_casteljau.hpp) against polynomials built from known
// roots: the halves' control points, evaluated by the Bernstein basis summed directly, must
// give the original polynomial (evaluated from its roots) at the matching points, and their
// end control points are the polynomial's values at 0, s and 1.
#include "implicit/de_casteljau.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace convray::implicit {
namespace {

// Power coefficients of c (s - r_1) ... (s - r_n), constant first.
template <size_t N>
std::array<double, N> from_roots(double c, const std::array<double, N - 1>& roots) {
  std::array<double, N> a{};
  a[0] = c;
  for (size_t k = 0; k + 1 < N; ++k) {
    for (size_t i = k + 1; i > 0; --i) a[i] = a[i - 1] - roots[k] * a[i];
    a[0] = -roots[k] * a[0];
  }
  return a;
}

double binomial(int n, int k) {
  double v = 1.0;
  for (int i = 1; i <= k; ++i) v = v * double(n - k + i) / double(i);
  return v;
}

// Bernstein coefficients on [0, 1] from power coefficients: b_k = sum_i C(k,i)/C(n,i) a_i.
template <size_t N>
std::array<double, N> bernstein_of(const std::array<double, N>& a) {
  const int n = int(N) - 1;
  std::array<double, N> b{};
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= k; ++i) b[k] += binomial(k, i) / binomial(n, i) * a[i];
  }
  return b;
}

template <size_t N>
double bernstein_value(const std::array<double, N>& b, double s) {
  const int n = int(N) - 1;
  double v = 0.0;
  for (int k = 0; k <= n; ++k) v += b[k] * binomial(n, k) * std::pow(s, k) * std::pow(1 - s, n - k);
  return v;
}

template <size_t N>
double from_roots_value(double c, const std::array<double, N - 1>& roots, double s) {
  double v = c;
  for (double r : roots) v *= s - r;
  return v;
}

template <size_t N>
void check_split(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> root(-0.5, 1.5), unit(0.0, 1.0);
  std::array<double, N - 1> roots;
  for (double& r : roots) r = root(rng);
  const double c = 2.0 * unit(rng) - 1.0;
  const std::array<double, N> b = bernstein_of(from_roots<N>(c, roots));
  const double s = unit(rng);
  std::array<double, N> left, right, half_left, half_right;
  de_casteljau_split(b, s, &left, &right);
  de_casteljau_halve(b, half_left, half_right);
  const double tolerance = 1e-12;
  EXPECT_NEAR(left.front(), from_roots_value<N>(c, roots, 0.0), tolerance);
  EXPECT_NEAR(left.back(), from_roots_value<N>(c, roots, s), tolerance);
  EXPECT_NEAR(right.front(), from_roots_value<N>(c, roots, s), tolerance);
  EXPECT_NEAR(right.back(), from_roots_value<N>(c, roots, 1.0), tolerance);
  for (int i = 0; i <= 10; ++i) {
    const double u = i / 10.0;
    EXPECT_NEAR(bernstein_value(left, u), from_roots_value<N>(c, roots, s * u), tolerance);
    EXPECT_NEAR(bernstein_value(right, u), from_roots_value<N>(c, roots, s + (1 - s) * u),
                tolerance);
    EXPECT_NEAR(bernstein_value(half_left, u), from_roots_value<N>(c, roots, 0.5 * u), tolerance);
    EXPECT_NEAR(bernstein_value(half_right, u), from_roots_value<N>(c, roots, 0.5 + 0.5 * u),
                tolerance);
  }
}

TEST(DeCasteljau, HalvesAreThePolynomialOnEachSideOfTheSplit) {
  std::mt19937_64 rng(14);
  for (int trial = 0; trial < 50; ++trial) {
    check_split<5>(rng);  // quartics, as quartic_roots isolates
    check_split<7>(rng);  // degree 6, as bezier_clip clips
  }
}

// Halving by midpoints is the exact average: both halves meet at the same middle value, and
// the split at s = 1/2 agrees with it to rounding.
TEST(DeCasteljau, HalvingAgreesWithTheSplitAtOneHalf) {
  const std::array<double, 5> b = {1.0, -3.0, 2.5, 0.25, -1.0};
  std::array<double, 5> left, right, split_left, split_right;
  de_casteljau_halve(b, left, right);
  de_casteljau_split(b, 0.5, &split_left, &split_right);
  EXPECT_EQ(left.back(), right.front());
  for (size_t k = 0; k < b.size(); ++k) {
    EXPECT_NEAR(left[k], split_left[k], 1e-15);
    EXPECT_NEAR(right[k], split_right[k], 1e-15);
  }
}

}  // namespace
}  // namespace convray::implicit
