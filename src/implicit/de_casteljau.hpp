#pragma once
// De Casteljau's split of a polynomial in Bernstein form on [0, 1]: the control points of the
// same polynomial over [0, s] and over [s, 1]. The one split of the Bernstein solvers
// (bezier_clip's clipping and subdivision, quartic_roots' isolation).
//
// de_casteljau_split interpolates x + s (y - x); de_casteljau_halve splits at s = 1/2 with the
// midpoint 0.5 (x + y), which rounds once (exactly half the rounded sum) where the general
// form rounds twice, so halving stays the exact average the quartic isolation was built on.
#include <array>
#include <cstddef>
#include <type_traits>

namespace convray::implicit {

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

}  // namespace convray::implicit
