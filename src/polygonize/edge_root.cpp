#include "polygonize/edge_root.hpp"

#include <algorithm>
#include <cmath>

namespace convray::polygonize {

EdgeRoot find_edge_root(const FieldSource& source, const Vec3& a, double fa, const Vec3& b,
                        double fb, double tolerance) {
  const double threshold = source.threshold;
  constexpr double kEdgeMargin = 1e-9;  // of the edge's length
  constexpr int kMaxSteps = 100;
  const double tolerance_abs = tolerance * threshold;
  // g(t) = F(a + t (b - a)) - T on [t0, t1] with g(t0) and g(t1) of opposite signs.
  double t0 = 0.0, g0 = fa - threshold, t1 = 1.0, g1 = fb - threshold;
  EdgeRoot root;
  double t = 0.5;
  for (int step = 0; step < kMaxSteps; ++step) {
    t = g0 == g1 ? 0.5 * (t0 + t1) : t0 - g0 * (t1 - t0) / (g1 - g0);
    // Regula falsi can stall next to an end; never step outside the bracket's interior.
    const double lo = std::min(t0, t1), hi = std::max(t0, t1);
    if (!(t > lo && t < hi)) t = 0.5 * (t0 + t1);
    t = std::clamp(t, kEdgeMargin, 1.0 - kEdgeMargin);
    root.position = a + t * (b - a);
    const double g = source.value_at(root.position) - threshold;
    ++root.evaluations;
    if (std::abs(g) <= tolerance_abs) {
      root.converged = true;
      break;
    }
    if (std::abs(t1 - t0) <= 4e-16 * std::max(1.0, std::abs(t))) break;  // a jump: give up
    if ((g < 0.0) == (g1 < 0.0)) {
      g0 *= 0.5;  // Illinois: the end that stays gets its weight halved
    } else {
      t0 = t1;
      g0 = g1;
    }
    t1 = t;
    g1 = g;
  }
  // The search may have read a fast approximation of F (FieldSource::value); the vertex must
  // sit on the exact field, so a few Newton steps along the edge finish on `field` itself.
  const Vec3 edge = b - a;
  constexpr int kPolishSteps = 4;
  for (int step = 0;; ++step) {
    root.sample = source.field(root.position);
    ++root.evaluations;
    const double g = root.sample.value - threshold;
    root.converged = std::abs(g) <= tolerance_abs;
    const double slope = glm::dot(root.sample.gradient, edge);
    if (root.converged || step == kPolishSteps || !(slope != 0.0)) break;
    const double next = std::clamp(t - g / slope, kEdgeMargin, 1.0 - kEdgeMargin);
    if (!(std::abs(next - t) <= 1e-3)) break;  // far off: a jump, not rounding
    t = next;
    root.position = a + t * edge;
  }
  return root;
}

}  // namespace convray::polygonize
