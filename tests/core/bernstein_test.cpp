// The Bernstein operations (core/bernstein.hpp) against polynomials built from known roots:
// de Casteljau's split (the halves' control points, evaluated by the Bernstein basis summed
// directly, must give the original polynomial, evaluated from its roots, at the matching
// points, and their end control points are its values at 0, s and 1), the control points from
// the power form over an interval, the change of origin, and the sign variations.
#include "core/bernstein.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace convray {
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
    check_split<5>(rng);  // quartics, as the sphere sweep isolates
    check_split<7>(rng);  // degree 6, as bezier_clip clips
    check_split<9>(rng);  // degree 8, the root finder's largest
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

// The control points over [0, width] from the power form are the direct binomial formula's
// (bernstein_of, on the polynomial scaled to [0, 1]) to rounding, for every degree the root
// finder takes; their ends are the polynomial's values at 0 and width.
template <size_t N>
void check_conversion(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> root(-0.5, 1.5), unit(0.0, 1.0);
  std::array<double, N - 1> roots;
  for (double& r : roots) r = root(rng);
  const double width = std::exp(20.0 * unit(rng) - 10.0);  // 4.5e-5 .. 2.2e4
  std::array<double, N - 1> scaled_roots = roots;
  for (double& r : scaled_roots) r *= width;
  // c(x) = prod (x - width r_k), and c(width s) = width^n prod (s - r_k).
  const std::array<double, N> c = from_roots<N>(1.0, scaled_roots);
  const std::array<double, N> b = bernstein_from_power(c, width);
  std::array<double, N> expected = bernstein_of(from_roots<N>(1.0, roots));
  double size = 0.0;
  for (double& e : expected) {
    e *= std::pow(width, double(N - 1));
    size = std::max(size, std::abs(e));
  }
  for (size_t k = 0; k < N; ++k) EXPECT_NEAR(b[k], expected[k], 1e-12 * size) << k;
  EXPECT_EQ(b[0], c[0]);
  EXPECT_NEAR(b[N - 1], from_roots_value<N>(1.0, scaled_roots, width), 1e-12 * size);
}

TEST(Bernstein, ControlPointsFromThePowerFormOverAnInterval) {
  std::mt19937_64 rng(15);
  for (int trial = 0; trial < 50; ++trial) {
    check_conversion<3>(rng);
    check_conversion<5>(rng);
    check_conversion<7>(rng);
    check_conversion<9>(rng);
  }
  // The weights 1, 1/2, 1/4 and 3/4 cost no rounding: x^k over [0, 1] has the exact control
  // points C(j,k) / C(n,k) where those are dyadic.
  const std::array<double, 5> x = {0.0, 1.0, 0.0, 0.0, 0.0};
  const std::array<double, 5> bx = bernstein_from_power(x, 1.0);
  EXPECT_EQ(bx, (std::array<double, 5>{0.0, 0.25, 0.5, 0.75, 1.0}));
}

TEST(Bernstein, ShiftedPowerFormIsThePolynomialAboutTheNewOrigin) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 100; ++trial) {
    std::array<double, 8> roots;
    for (double& r : roots) r = u(rng);
    const std::array<double, 9> c = from_roots<9>(u(rng), roots);
    const double d = u(rng);
    const std::array<double, 9> moved = shift_power_form(c, d);
    for (int i = 0; i <= 10; ++i) {
      const double w = u(rng);
      double value = 0.0;
      for (size_t k = 9; k-- > 0;) value = value * w + moved[k];
      const double direct = from_roots_value<9>(c[8], roots, w + d);
      EXPECT_NEAR(value, direct, 1e-11 * (1.0 + std::abs(direct)) * std::pow(4.0, 8.0));
    }
  }
}

TEST(Bernstein, SignVariationsSkipZeros) {
  EXPECT_EQ(sign_variations(std::array<double, 5>{1.0, 2.0, 3.0, 4.0, 5.0}), 0);
  EXPECT_EQ(sign_variations(std::array<double, 5>{1.0, -2.0, 3.0, -4.0, 5.0}), 4);
  EXPECT_EQ(sign_variations(std::array<double, 5>{1.0, 0.0, 0.0, -4.0, 0.0}), 1);
  EXPECT_EQ(sign_variations(std::array<double, 5>{0.0, 0.0, 0.0, 0.0, 0.0}), 0);
  EXPECT_EQ(sign_variations(std::array<double, 3>{-1.0, 0.0, -1.0}), 0);
}

// Halving never adds sign variations (what bounds the root finder's work): the halves'
// variations sum to at most the whole's, for random control points of every sign pattern.
TEST(Bernstein, HalvingNeverAddsSignVariations) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 10000; ++trial) {
    std::array<double, 9> b;
    for (double& x : b) x = u(rng) * std::pow(10.0, 10.0 * u(rng));
    std::array<double, 9> left, right;
    de_casteljau_halve(b, left, right);
    EXPECT_LE(sign_variations(left) + sign_variations(right), sign_variations(b)) << trial;
  }
}

}  // namespace
}  // namespace convray
