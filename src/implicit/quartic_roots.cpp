#include "implicit/quartic_roots.hpp"

#include "core/bernstein.hpp"
#include "core/bracket_refine.hpp"

namespace convray::implicit {
namespace {

using Control = std::array<double, 5>;

bool differ(double a, double b) { return (a < 0.0) != (b < 0.0); }

class Isolator {
 public:
  Isolator(const Quartic& q, const QuarticRootOptions& options, std::vector<double>& out)
      : q_(q), options_(options), out_(out) {}

  int found() const { return found_; }

  // [lo, hi] with control points b (b[0] = q(lo), b[4] = q(hi)).
  void search(const Control& b, double lo, double hi, int depth) {
    if (done()) return;
    if (b[0] == 0.0) push(lo);
    const int variations = sign_variations(b);
    if (variations == 0) {
      if (b[4] == 0.0) push(hi);
      return;
    }
    if (variations == 1 && b[0] != 0.0 && b[4] != 0.0) {
      push(polish(lo, hi, b[0], b[4]));
      return;
    }
    const double mid = 0.5 * (lo + hi);
    if (hi - lo <= options_.resolution || depth >= 64 || !(mid > lo && mid < hi)) {
      unresolved(b, lo, mid, hi);
      return;
    }
    Control left, right;
    de_casteljau_halve(b, left, right);
    search(left, lo, mid, depth + 1);
    search(right, mid, hi, depth + 1);
  }

 private:
  bool done() const { return options_.first_only && found_ > 0; }

  void push(double v) {
    if (done() || (found_ > 0 && v <= out_.back())) return;  // a shared end, seen already
    out_.push_back(v);
    ++found_;
  }

  // Roots closer together than the resolution: an odd count crosses once; an even count
  // crosses twice where the middle has the other sign, or only touches zero.
  void unresolved(const Control& b, double lo, double mid, double hi) {
    if (b[0] == 0.0 || b[4] == 0.0) {
      if (b[4] == 0.0) push(hi);
      return;
    }
    if (differ(b[0], b[4])) {
      push(polish(lo, hi, b[0], b[4]));
      return;
    }
    const double at_mid = q_(mid);
    if (!differ(at_mid, b[0])) return;
    push(polish(lo, mid, b[0], at_mid));
    push(polish(mid, hi, at_mid, b[4]));
  }

  // The one root in [a, b], over which q changes sign.
  double polish(double a, double b, double fa, double fb) const {
    return refine_bracket(a, b, fa, fb, q_);
  }

  const Quartic& q_;
  const QuarticRootOptions& options_;
  std::vector<double>& out_;
  int found_ = 0;
};

}  // namespace

int quartic_roots(const Quartic& q, double width, const QuarticRootOptions& options,
                  std::vector<double>& out) {
  if (!(width > 0.0)) return 0;
  Isolator isolator(q, options, out);
  isolator.search(bernstein(q, width), 0.0, width, 0);
  return isolator.found();
}

}  // namespace convray::implicit
