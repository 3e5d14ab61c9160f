#include "implicit/down_bend_table.hpp"

#include <algorithm>

namespace convray::implicit {

void DownBendTable::reset(size_t n) {
  size_ = 0;
  for (auto* v : {&enter_, &exit_, &anywhere_, &weight_, &radius_, &r2_, &measure_, &limit_,
                  &triangle_, &h0_, &h1_, &o00_, &o01_, &o10_, &o11_, &o20_, &o21_}) {
    v->resize(n);
  }
}

void DownBendTable::add(double enter, double exit, const LineCurvature::DownTerms& t) {
  const size_t k = size_++;
  enter_[k] = enter;
  exit_[k] = exit;
  anywhere_[k] = t.anywhere;
  weight_[k] = t.weight;
  radius_[k] = t.radius;
  r2_[k] = t.r2;
  measure_[k] = t.measure;
  limit_[k] = t.limit;
  triangle_[k] = t.triangle ? 1.0 : 0.0;
  h0_[k] = t.reach.height[0];
  h1_[k] = t.reach.height[1];
  o00_[k] = t.reach.outside[0][0];
  o01_[k] = t.reach.outside[0][1];
  o10_[k] = t.reach.outside[1][0];
  o11_[k] = t.reach.outside[1][1];
  o20_[k] = t.reach.outside[2][0];
  o21_[k] = t.reach.outside[2][1];
}

size_t DownBendTable::entered_by(double b) const {
  return size_t(std::upper_bound(enter_.begin(), enter_.begin() + size_, b) - enter_.begin());
}

double DownBendTable::sum(double a, double b, bool anywhere) const {
  const size_t n = entered_by(b);
  const double* exit = exit_.data();
  double total = 0.0;
  if (anywhere) {
    for (size_t k = 0; k < n; ++k) total += exit[k] < a ? 0.0 : anywhere_[k];
    return total;
  }
  bend_.resize(std::max(bend_.size(), n));
  double* bend = bend_.data();
  // Named pointers: the vectorizer does not see through the members.
  const double *weight = weight_.data(), *radius = radius_.data(), *r2 = r2_.data();
  const double *measure = measure_.data(), *limit = limit_.data(), *triangle = triangle_.data();
  const double *h0 = h0_.data(), *h1 = h1_.data(), *any = anywhere_.data();
  const double *o00 = o00_.data(), *o01 = o01_.data(), *o10 = o10_.data(), *o11 = o11_.data();
  const double *o20 = o20_.data(), *o21 = o21_.data();
#pragma omp simd
  for (size_t k = 0; k < n; ++k) {
    const double own = triangle_down_bend(weight[k], radius[k], r2[k], measure[k], limit[k],
                                          h0[k], h1[k], o00[k], o01[k], o10[k], o11[k], o20[k],
                                          o21[k], a, b);
    bend[k] = triangle[k] != 0.0 ? own : any[k];
  }
  for (size_t k = 0; k < n; ++k) total += exit[k] < a ? 0.0 : bend[k];
  return total;
}

}  // namespace convray::implicit
