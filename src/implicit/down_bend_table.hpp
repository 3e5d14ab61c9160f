#pragma once
// The window march's most frequent certificate: how far the primitives whose support meets a
// window [a, b] may bend down there, summed (ClusterField::curvature below T). The march
// asks it for every window it weighs, over every member of the cluster, so the members'
// terms are kept here side by side, one array per term, and each member's bound is computed
// in SIMD lanes (the same formula and bits as LineCurvature::down, triangle_reach.hpp) and
// then summed in member order (the same sum as one member after the other).
#include <cstddef>
#include <vector>

#include "implicit/line_curvature.hpp"

namespace convray::implicit {

class DownBendTable {
 public:
  // Room for n members, none held yet (the arrays are sized once, never filled).
  void reset(size_t n);
  // The next member, in the cluster's order (by entry): the terms of a primitive with a
  // positive strength (LineCurvature::flipped() false). At most n after reset(n).
  void add(double enter, double exit, const LineCurvature::DownTerms& terms);
  size_t size() const { return size_; }

  // The sum of down(a, b) over the members whose support meets [a, b]; with `anywhere`, of
  // each one's bound over its whole line (LineCurvature::down_anywhere) instead. Every member
  // that enters by b must be held (the march adds members as its windows reach their entry);
  // later ones may be missing.
  double sum(double a, double b, bool anywhere) const;

 private:
  // How many members enter at or before b (they are sorted by entry).
  size_t entered_by(double b) const;
  // The first member whose support has not ended before a, given that the ones before it had
  // ended before an earlier window's start (live_from_, live_at_).
  size_t first_live(double a) const;

  size_t size_ = 0;
  mutable size_t live_from_ = 0;
  mutable size_t entered_ = 0;  // entered_by's last answer
  mutable double live_at_ = 0.0;
  std::vector<double> enter_, exit_, anywhere_;
  // The terms of triangle_down_bend; a member that is not a triangle has triangle_ 0 and
  // bends by its `anywhere_` on any window.
  std::vector<double> weight_, radius_, inverse_r2_, measure_, limit_, inverse_limit_, triangle_;
  std::vector<double> h0_, h1_, o00_, o01_, o10_, o11_, o20_, o21_, lo_, hi_;
  mutable std::vector<double> bend_;  // per member, for the ordered sum
};

}  // namespace convray::implicit
