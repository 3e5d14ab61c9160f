#include "implicit/interval_fit.hpp"

#include <cmath>

namespace convray::implicit {
namespace {

using Matrix7 = std::array<std::array<double, 7>, 7>;

// Inverts a 7x7 matrix by Gauss-Jordan elimination with partial pivoting (only used once per
// matrix, at start-up, on small well-conditioned systems).
Matrix7 invert(Matrix7 a) {
  Matrix7 inv{};
  for (int i = 0; i < 7; ++i) inv[i][i] = 1.0;
  for (int col = 0; col < 7; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 7; ++r) {
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    }
    std::swap(a[col], a[pivot]);
    std::swap(inv[col], inv[pivot]);
    const double d = a[col][col];
    for (int k = 0; k < 7; ++k) {
      a[col][k] /= d;
      inv[col][k] /= d;
    }
    for (int r = 0; r < 7; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int k = 0; k < 7; ++k) {
        a[r][k] -= f * a[col][k];
        inv[r][k] -= f * inv[col][k];
      }
    }
  }
  return inv;
}

// Rows: the conditions (value at 0, slope at 0, value at 1, slope at 1, values at 1/4, 1/2,
// 3/4) applied to the monomials s^k; its inverse maps conditions to coefficients.
Matrix7 fit_inverse() {
  Matrix7 m{};
  const double nodes[3] = {0.25, 0.5, 0.75};
  for (int k = 0; k < 7; ++k) {
    m[0][k] = k == 0 ? 1.0 : 0.0;
    m[1][k] = k == 1 ? 1.0 : 0.0;
    m[2][k] = 1.0;
    m[3][k] = double(k);
    for (int j = 0; j < 3; ++j) m[4 + j][k] = std::pow(nodes[j], k);
  }
  return invert(m);
}

// Rows: Bernstein basis functions B_k,6 at s = j/6; its inverse maps samples to coefficients.
Matrix7 bernstein_inverse() {
  Matrix7 m{};
  const double binomial[7] = {1, 6, 15, 20, 15, 6, 1};
  for (int j = 0; j < 7; ++j) {
    const double s = j / 6.0;
    for (int k = 0; k < 7; ++k) m[j][k] = binomial[k] * std::pow(s, k) * std::pow(1.0 - s, 6 - k);
  }
  return invert(m);
}

Poly6 multiply(const Matrix7& m, const Poly6& v) {
  Poly6 out{};
  for (int i = 0; i < 7; ++i) {
    double sum = 0.0;
    for (int k = 0; k < 7; ++k) sum += m[i][k] * v[k];
    out[i] = sum;
  }
  return out;
}

}  // namespace

Poly6 fit_degree6(const FitConditions& c, double width) {
  static const Matrix7 inverse = fit_inverse();
  const Poly6 rhs{c.value0,    c.slope0 * width, c.value1,   c.slope1 * width,
                  c.quarter[0], c.quarter[1],    c.quarter[2]};
  return multiply(inverse, rhs);
}

Poly6 bernstein_from_samples(const Poly6& values) {
  static const Matrix7 inverse = bernstein_inverse();
  return multiply(inverse, values);
}

}  // namespace convray::implicit
