#include "implicit/down_bend_table.hpp"

#include <algorithm>

#include "util/simd_width.hpp"

namespace convray::implicit {

// The arrays only grow: resizing them down and up again for every cluster filled the new
// rows with zeros each time.
void DownBendTable::reset(size_t n) {
  size_ = 0;
  live_from_ = 0;
  live_at_ = -kInfinity;
  entered_ = 0;
  n += kSimdWidth - 1;  // room for sum()'s last SIMD width, from any first live row
  if (n <= enter_.size()) return;
  for (auto* v : {&enter_, &exit_, &anywhere_, &weight_, &radius_, &inverse_r2_, &measure_,
                  &limit_, &inverse_limit_, &triangle_, &h0_, &h1_, &o00_, &o01_, &o10_, &o11_,
                  &o20_, &o21_, &lo_, &hi_, &bend_}) {
    v->resize(n);
  }
}

// The march's windows move forward: members at the front of the table whose support ended
// before a add nothing to any later window either, and are skipped from then on (a window
// that starts further back, as none does today, starts over from the first member).
size_t DownBendTable::first_live(double a) const {
  if (a < live_at_) live_from_ = 0;
  live_at_ = a;
  while (live_from_ < size_ && exit_[live_from_] < a) ++live_from_;
  return live_from_;
}

void DownBendTable::add(double enter, double exit, const LineCurvature::DownTerms& t) {
  const size_t k = size_++;
  enter_[k] = enter;
  exit_[k] = exit;
  anywhere_[k] = t.anywhere;
  weight_[k] = t.weight;
  radius_[k] = t.radius;
  inverse_r2_[k] = 1.0 / t.r2;
  measure_[k] = t.measure;
  limit_[k] = t.limit;
  inverse_limit_[k] = inverse_limit(t.limit);
  triangle_[k] = t.triangle ? 1.0 : 0.0;
  h0_[k] = t.reach.height[0];
  h1_[k] = t.reach.height[1];
  o00_[k] = t.reach.outside[0][0];
  o01_[k] = t.reach.outside[0][1];
  o10_[k] = t.reach.outside[1][0];
  o11_[k] = t.reach.outside[1][1];
  o20_[k] = t.reach.outside[2][0];
  o21_[k] = t.reach.outside[2][1];
  lo_[k] = t.reach.along[0];
  hi_[k] = t.reach.along[1];
}

// From the last answer, a step at a time: the march's windows end near where the last one
// did (a binary search over the whole table cost more, on the short tables of most rays).
size_t DownBendTable::entered_by(double b) const {
  entered_ = std::min(entered_, size_);
  while (entered_ < size_ && enter_[entered_] <= b) ++entered_;
  while (entered_ > 0 && enter_[entered_ - 1] > b) --entered_;
  return entered_;
}

double DownBendTable::sum(double a, double b, bool anywhere) const {
  const size_t n = entered_by(b);
  const size_t first = std::min(first_live(a), n);
  const double* exit = exit_.data();
  double total = 0.0;
  double* bend = bend_.data();  // sized with the table by reset()
  // Each member's bound lands in bend[] (0 where its support ended before a), and is summed
  // in the members' order after: the same sum, to the bit, as one term at a time, and no
  // load inside a select (those became masked loads, vmaskmovpd, 14 % of the loop's time).
  const auto ordered_sum = [&] {
    for (size_t k = first; k < n; ++k) total += bend[k];
    return total;
  };
  if (anywhere) {
    const double* any = anywhere_.data();
#pragma omp simd
    for (size_t k = first; k < n; ++k) {
      const double bound = any[k];
      bend[k] = exit[k] < a ? 0.0 : bound;
    }
    return ordered_sum();
  }
  // Named pointers: the vectorizer does not see through the members.
  const double *weight = weight_.data(), *radius = radius_.data();
  const double* inverse_r2 = inverse_r2_.data();
  const double *measure = measure_.data(), *limit = limit_.data(), *triangle = triangle_.data();
  const double* inverse_limit = inverse_limit_.data();
  const double *h0 = h0_.data(), *h1 = h1_.data(), *any = anywhere_.data();
  const double *o00 = o00_.data(), *o01 = o01_.data(), *o10 = o10_.data(), *o11 = o11_.data();
  const double *o20 = o20_.data(), *o21 = o21_.data(), *lo = lo_.data(), *hi = hi_.data();
  // Whole SIMD widths (the rows past n are spare: reset() made room): a scalar remainder
  // of up to three rows cost about as much as the vector loop on the march's short tables.
  const size_t end = first + whole_simd_widths(n - first);
#pragma omp simd
  for (size_t k = first; k < end; ++k) {
    const double own = triangle_down_bend(weight[k], radius[k], inverse_r2[k], measure[k], limit[k],
                                          inverse_limit[k],
                                          h0[k], h1[k], o00[k], o01[k], o10[k], o11[k], o20[k],
                                          o21[k], lo[k], hi[k], a, b);
    // The ended members masked by a product, not a select: GCC sank a load into the select
    // and made it masked again. (The bounds are finite and >= 0: times 1 or 0, the same sum.)
    const double anywhere = any[k], live = exit[k] < a ? 0.0 : 1.0;
    bend[k] = (triangle[k] != 0.0 ? own : anywhere) * live;
  }
  return ordered_sum();
}

}  // namespace convray::implicit
