#include "implicit/bezier_clip.hpp"

#include <algorithm>
#include <cmath>

#include "core/bernstein.hpp"

namespace convray::implicit {
namespace {

constexpr int kDegree = 6;
constexpr int kMaxDepth = 60;

// The s-range where the convex hull of the control points (k/6, b_k) meets |y| <= band. The
// hull's edges are among the segments between control points, and segments inside the hull do
// not reach beyond it, so the range over all pairs is the hull's.
bool hull_band_range(const Poly6& b, double band, double& lo, double& hi) {
  lo = 2.0;
  hi = -1.0;
  for (int i = 0; i <= kDegree; ++i) {
    for (int j = i; j <= kDegree; ++j) {
      const double si = double(i) / kDegree, sj = double(j) / kDegree;
      double l0 = 0.0, l1 = 1.0;  // fraction along the segment from i to j
      const double dy = b[j] - b[i];
      if (dy == 0.0) {
        if (std::abs(b[i]) > band) continue;
      } else {
        double a = (-band - b[i]) / dy, c = (band - b[i]) / dy;
        if (a > c) std::swap(a, c);
        l0 = std::max(l0, a);
        l1 = std::min(l1, c);
        if (l0 > l1) continue;
      }
      lo = std::min(lo, si + l0 * (sj - si));
      hi = std::max(hi, si + l1 * (sj - si));
    }
  }
  return lo <= hi;
}

struct Isolator {
  double band, resolution;
  bool first_only;
  std::vector<Region>& out;

  void emit(double lo, double hi) {
    if (!out.empty() && lo <= out.back().hi) {
      out.back().hi = std::max(out.back().hi, hi);
    } else {
      out.push_back({lo, hi});
    }
  }

  // Returns false once the caller should stop (first_only and a region found).
  bool run(const Poly6& b, double lo, double hi, int depth) {
    const auto [min_it, max_it] = std::minmax_element(b.begin(), b.end());
    if (*min_it > band || *max_it < -band) return true;
    if ((*min_it >= -band && *max_it <= band) || hi - lo <= resolution || depth >= kMaxDepth) {
      emit(lo, hi);
      return !first_only;
    }
    double a = 0.0, c = 1.0;
    if (!hull_band_range(b, band, a, c)) return true;
    a = std::clamp(a, 0.0, 1.0);
    c = std::clamp(c, 0.0, 1.0);
    const double width = hi - lo;
    if (c - a > 0.8) {  // clipping stalls: two roots (or a wide band); halve
      Poly6 left, right;
      de_casteljau_split(b, 0.5, &left, &right);
      const double mid = lo + 0.5 * width;
      return run(left, lo, mid, depth + 1) && run(right, mid, hi, depth + 1);
    }
    return run(bernstein_restrict(b, a, c), lo + a * width, lo + c * width, depth + 1);
  }
};

}  // namespace

Poly6 bernstein_restrict(const Poly6& b, double a, double c) {
  Poly6 head;
  de_casteljau_split(b, c, &head, nullptr);
  if (c <= 0.0) return head;
  Poly6 tail;
  de_casteljau_split(head, a / c, nullptr, &tail);
  return tail;
}

void isolate_band(const Poly6& b, double band, double resolution, bool first_only,
                  std::vector<Region>& out) {
  Isolator isolator{band, resolution, first_only, out};
  isolator.run(b, 0.0, 1.0, 0);
}

}  // namespace convray::implicit
