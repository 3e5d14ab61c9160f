#include "core/polynomial_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/bernstein.hpp"
#include "core/bracket_refine.hpp"

namespace convray {
namespace {

// Horner's rule on N coefficients (degree N - 1), the loop unrolled for each degree.
template <size_t N>
double horner(const std::array<double, N>& c, double x) {
  double value = c[N - 1];
  for (size_t i = N - 1; i-- > 0;) value = value * x + c[i];
  return value;
}

bool differ(double a, double b) { return (a < 0.0) != (b < 0.0); }

// The isolation's findings, ascending: exact zeros and brackets of one root each. A sink is
// full when its caller wants no more (room for the roots, or the first alone).
template <size_t N>
class RootSink {
 public:
  RootSink(const std::array<double, N>& c, double* out, int room)
      : c_(c), out_(out), room_(room) {}
  bool full() const { return count_ >= room_; }
  int count() const { return count_; }
  void exact(double x) { push(x); }
  void bracket(double a, double b, double fa, double fb) {
    if (full()) return;
    double x = refine_bracket(a, b, fa, fb, [this](double t) { return horner(c_, t); });
    // An end control point is a rounded sum where Horner's value is exactly zero (a root
    // right on hi, say), so the piece may bracket that root by a sign it does not have: a root
    // refined to within the refiner's resolution of such an end is that end, reported once.
    const double near = 8.0 * std::numeric_limits<double>::epsilon() *
                        std::max(std::abs(a), std::abs(b));
    if (x - a <= near && horner(c_, a) == 0.0) {
      x = a;
    } else if (b - x <= near && horner(c_, b) == 0.0) {
      x = b;
    }
    push(x);
  }

 private:
  void push(double x) {
    if (full() || (count_ > 0 && x <= out_[count_ - 1])) return;  // a shared end, seen already
    out_[count_++] = x;
  }

  const std::array<double, N>& c_;
  double* out_;
  int room_, count_ = 0;
};

template <size_t N>
class BracketSink {
 public:
  BracketSink(const std::array<double, N>& c, RootBracket* out, int room)
      : c_(c), out_(out), room_(room) {}
  bool full() const { return count_ >= room_; }
  int count() const { return count_; }
  void exact(double x) {
    if (full()) return;
    if (count_ > 0 && out_[count_ - 1].exact() && out_[count_ - 1].lo == x) return;  // shared
    out_[count_++] = {x, x, 0.0, 0.0};
  }
  // The power form's values at the ends where they keep the sign change (nearly always).
  void bracket(double a, double b, double fa, double fb) {
    const double at_a = horner(c_, a), at_b = horner(c_, b);
    if (at_a == 0.0) return exact(a);
    if (at_b == 0.0) return exact(b);
    if (full()) return;
    if (differ(at_a, at_b)) {
      fa = at_a;
      fb = at_b;
    }
    out_[count_++] = {a, b, fa, fb};
  }

 private:
  const std::array<double, N>& c_;
  RootBracket* out_;
  int room_, count_ = 0;
};

// Pieces are halved until their ends are adjacent doubles (or they are narrower than the
// resolution). This cap only bounds the recursion (frames of about 300 bytes) where doubles
// are dense, about zero: it is past the 1074 halvings that take a unit interval to the
// smallest double, and leaves room for intervals up to 10^100 times their roots' scale (the
// span to Cauchy's bound of a quartic whose leading coefficient is 1e-40 of the others: a ray
// nearly along an asymptotic direction of a polynomial surface).
constexpr int kMaxDepth = 1500;

// Bernstein isolation of the roots of c (N coefficients) on pieces of [lo, hi].
template <size_t N, class Sink>
class Isolator {
 public:
  using Control = std::array<double, N>;
  static constexpr size_t n = N - 1;

  // Pieces lie within [-reach, reach].
  Isolator(const Control& c, double resolution, double reach, Sink& sink)
      : c_(c), resolution_(resolution), reach_(reach), sink_(sink) {}

  // [lo, hi] with control points b (b[0] = c(lo), b[n] = c(hi)). The left part of a piece
  // is searched by a call, the right part by the loop (one call less per split).
  void search(Control b, double lo, double hi, int depth) {
    for (;;) {
      if (sink_.full()) return;
      if (b[0] == 0.0) sink_.exact(lo);
      const int variations = sign_variations(b);
      if (variations == 0) {
        if (b[n] == 0.0) sink_.exact(hi);
        return;
      }
      if (variations == 1 && b[0] != 0.0 && b[n] != 0.0) {
        sink_.bracket(lo, hi, b[0], b[n]);
        return;
      }
      double mid = 0.5 * (lo + hi);
      if (hi - lo <= resolution_ || depth >= kMaxDepth || !(mid > lo && mid < hi)) {
        unresolved(b, lo, mid, hi);
        return;
      }
      Control left, right;
      de_casteljau_halve(b, left, right);
      if (right[0] != 0.0 && std::abs(right[0]) <= noise() &&
          std::abs(right[0]) <= noise_at(mid)) {
        mid = split_beside_a_root(b, lo, hi, mid, left, right);
      }
      ++depth;
      search(left, lo, mid, depth);
      b = right;
      lo = mid;
    }
  }

 private:
  // Roots closer together than the resolution: an odd count crosses once; an even count
  // crosses twice where the middle has the other sign, or only touches zero.
  void unresolved(const Control& b, double lo, double mid, double hi) {
    if (b[0] == 0.0 || b[n] == 0.0) {
      if (b[n] == 0.0) sink_.exact(hi);
      return;
    }
    if (differ(b[0], b[n])) {
      sink_.bracket(lo, hi, b[0], b[n]);
      return;
    }
    if (!(mid > lo && mid < hi)) return;  // ends at adjacent doubles: no middle to ask
    const double at_mid = horner(c_, mid);
    if (!differ(at_mid, b[0])) return;
    sink_.bracket(lo, mid, b[0], at_mid);
    sink_.bracket(mid, hi, at_mid, b[n]);
  }

  // The middle is a root to rounding: as a piece's end, its value's sign would be noise,
  // and a bracket starting there could lead the refiner to that root instead of the one the
  // piece holds. Split at 3/8 or 5/8 instead, where the value is further from zero; returns
  // the split point (the middle where neither is inside the piece).
  double split_beside_a_root(const Control& b, double lo, double hi, double mid, Control& left,
                             Control& right) const {
    Control left_a, right_a, left_b, right_b;
    de_casteljau_split(b, 0.375, &left_a, &right_a);
    de_casteljau_split(b, 0.625, &left_b, &right_b);
    const bool a_further = std::abs(left_a[n]) >= std::abs(left_b[n]);
    const double split = lo + (a_further ? 0.375 : 0.625) * (hi - lo);
    if (!(split > lo && split < hi)) return mid;
    left = a_further ? left_a : left_b;
    right = a_further ? right_a : right_b;
    return split;
  }

  // How far from zero rounding may put the polynomial's value at x, in Horner's rule or in
  // the control points (whose rounding, carried to x by the Bernstein basis, is eps times
  // that of the power form of sum |c_i| x^i): a few eps of sum |c_i x^i|.
  double noise_at(double x) const {
    double size = 0.0;
    for (size_t i = N; i-- > 0;) size = size * std::abs(x) + std::abs(c_[i]);
    return 16.0 * double(N) * std::numeric_limits<double>::epsilon() * size;
  }

  // The same bound over the whole interval (pieces lie within [-reach, reach]), computed at
  // the first split that asks: a cheap first test before noise_at.
  double noise() {
    if (noise_ < 0.0) noise_ = noise_at(reach_);
    return noise_;
  }

  const Control& c_;
  const double resolution_, reach_;
  double noise_ = -1.0;
  Sink& sink_;
};

template <size_t N>
bool all_finite(const std::array<double, N>& b) {
  bool finite = true;
  for (double x : b) finite = finite && std::isfinite(x);
  return finite;
}

// Every real root x has |x| <= 2 max_i |c_(n-i) / c_n|^(1/i) (Fujiwara's bound).
template <size_t N>
double root_bound(const std::array<double, N>& c) {
  double bound = 0.0;
  for (size_t i = 1; i < N; ++i) {
    bound = std::max(bound, std::pow(std::abs(c[N - 1 - i] / c[N - 1]), 1.0 / double(i)));
  }
  return 2.0 * bound;
}

template <size_t N>
std::array<double, N> reversed(std::array<double, N> b) {
  std::reverse(b.begin(), b.end());
  return b;
}

// Control points about the end of [lo, hi] nearer zero (the other end reached by a negative
// width, the points then reversed), or over [lo, 0] and [0, hi] when the interval holds zero:
// the power form is never moved away from its origin, where its coefficients are exact, so
// the control points are as well conditioned as Horner's values anywhere on the interval.
// Searches the pieces in order; false, with nothing searched, if a control point overflows.
template <size_t N, class Sink>
bool isolate_pieces(const std::array<double, N>& c, double lo, double hi, double resolution,
                    Sink& sink) {
  Isolator<N, Sink> isolator(c, resolution, std::max(-lo, hi), sink);
  if (lo == 0.0) {  // most callers' intervals, [0, width]: the sphere sweep's every piece
    const auto b = bernstein_from_power(c, hi);
    if (!all_finite(b)) return false;
    isolator.search(b, lo, hi, 0);
    return true;
  }
  if (lo > 0.0 || hi <= 0.0) {
    const bool from_lo = lo >= 0.0;
    const double origin = from_lo ? lo : hi;
    const std::array<double, N> about = origin == 0.0 ? c : shift_power_form(c, origin);
    const auto b = from_lo ? bernstein_from_power(about, hi - lo)
                           : reversed(bernstein_from_power(about, lo - hi));
    if (!all_finite(b)) return false;
    isolator.search(b, lo, hi, 0);
    return true;
  }
  const auto left = reversed(bernstein_from_power(c, lo)), right = bernstein_from_power(c, hi);
  if (!all_finite(left) || !all_finite(right)) return false;
  isolator.search(left, lo, 0.0, 0);
  isolator.search(right, 0.0, hi, 0);
  return true;
}

template <size_t N, class Sink>
void isolate(const std::array<double, N>& c, double lo, double hi, double resolution,
             Sink& sink) {
  if (isolate_pieces(c, lo, hi, resolution, sink)) return;
  // Control points overflow (an interval reaching far out, or huge coefficients): clip the
  // interval to where roots may be, and try once more.
  const double bound = root_bound(c);
  lo = std::max(lo, -bound);
  hi = std::min(hi, bound);
  if (lo < hi) isolate_pieces(c, lo, hi, resolution, sink);
}

template <size_t N, template <size_t> class Sink, class Out>
int isolate_degree(std::span<const double> c, double lo, double hi, double resolution,
                   Out* out, int room) {
  std::array<double, N> a;
  std::copy_n(c.begin(), N, a.begin());
  Sink<N> sink(a, out, room);
  isolate(a, lo, hi, resolution, sink);
  return sink.count();
}

// The degree once leading zeros are dropped; -1 for input this finder does not take.
int degree_of(std::span<const double> c, double lo, double hi) {
  if (c.size() > size_t(kMaxPolynomialDegree) + 1 || !(lo < hi)) return -1;
  int degree = int(c.size()) - 1;
  while (degree > 0 && c[size_t(degree)] == 0.0) --degree;
  return degree;
}

// A linear root is exact as one division rounds it.
bool linear_root(std::span<const double> c, double lo, double hi, double& x) {
  x = -c[0] / c[1];
  return x >= lo && x <= hi;
}

template <template <size_t> class Sink, class Out>
int isolate_any(std::span<const double> c, int degree, double lo, double hi, double resolution,
                Out* out, int room) {
  switch (degree) {
    case 2: return isolate_degree<3, Sink>(c, lo, hi, resolution, out, room);
    case 3: return isolate_degree<4, Sink>(c, lo, hi, resolution, out, room);
    case 4: return isolate_degree<5, Sink>(c, lo, hi, resolution, out, room);
    case 5: return isolate_degree<6, Sink>(c, lo, hi, resolution, out, room);
    case 6: return isolate_degree<7, Sink>(c, lo, hi, resolution, out, room);
    case 7: return isolate_degree<8, Sink>(c, lo, hi, resolution, out, room);
    case 8: return isolate_degree<9, Sink>(c, lo, hi, resolution, out, room);
    default: return 0;
  }
}

}  // namespace

double evaluate_polynomial(std::span<const double> c, double x) {
  double value = 0.0;
  for (size_t i = c.size(); i-- > 0;) value = value * x + c[i];
  return value;
}

int polynomial_brackets(std::span<const double> c, double lo, double hi, RootBracket* out,
                        double resolution) {
  const int degree = degree_of(c, lo, hi);
  if (degree <= 0) return 0;
  if (degree == 1) {
    double x;
    if (!linear_root(c, lo, hi, x)) return 0;
    out[0] = {x, x, 0.0, 0.0};
    return 1;
  }
  return isolate_any<BracketSink>(c.first(size_t(degree) + 1), degree, lo, hi, resolution, out,
                                  degree);
}

int polynomial_roots(std::span<const double> c, double lo, double hi, double* out,
                     int max_roots, double resolution) {
  const int degree = degree_of(c, lo, hi);
  if (degree <= 0 || max_roots <= 0) return 0;
  if (degree == 1) return linear_root(c, lo, hi, out[0]) ? 1 : 0;
  return isolate_any<RootSink>(c.first(size_t(degree) + 1), degree, lo, hi, resolution, out,
                               std::min(max_roots, degree));
}

double refine_polynomial_root(std::span<const double> c, const RootBracket& bracket) {
  if (bracket.exact()) return bracket.lo;
  return refine_bracket(bracket.lo, bracket.hi, bracket.f_lo, bracket.f_hi,
                        [c](double x) { return evaluate_polynomial(c, x); });
}

int quadratic_roots(double a, double half_b, double c, double out[2]) {
  if (a == 0.0) {
    if (half_b == 0.0) return 0;
    out[0] = -c / (2.0 * half_b);
    return 1;
  }
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0.0) return 0;
  // q has the sign of half_b so that no digits cancel; the roots are q / a and c / q.
  const double q = -(half_b + std::copysign(std::sqrt(discriminant), half_b));
  if (q == 0.0) {
    out[0] = out[1] = 0.0;  // half_b = c = 0: the double root 0
    return 2;
  }
  const double r0 = q / a, r1 = c / q;
  out[0] = std::min(r0, r1);
  out[1] = std::max(r0, r1);
  return 2;
}

}  // namespace convray
