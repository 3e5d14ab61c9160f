#include "polygonize/edge_root.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/bracket_refine.hpp"

namespace convray::polygonize {

EdgeRoot find_edge_root(const FieldSource& source, const Vec3& a, double fa, const Vec3& b,
                        double fb, double tolerance) {
  const double threshold = source.threshold;
  constexpr double kEdgeMargin = 1e-9;  // of the edge's length
  const double tolerance_abs = tolerance * threshold;
  const Vec3 edge = b - a;
  EdgeRoot root;
  // g(t) = F(a + t (b - a)) - T changes sign on [0, 1]. The one refiner stops on the residual
  // (the mesh's contract), or, at a jump, on a bracket a few ulps wide around it.
  const auto g = [&](double t) {
    ++root.evaluations;
    return source.value_at(a + t * edge) - threshold;
  };
  double t = refine_bracket(0.0, 1.0, fa - threshold, fb - threshold, g,
                            std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN(), 0.0, tolerance_abs);
  // Never on a lattice point itself, where other edges' vertices could also sit.
  t = std::clamp(t, kEdgeMargin, 1.0 - kEdgeMargin);
  root.position = a + t * edge;
  // The search may have read a fast approximation of F (FieldSource::value); the vertex must
  // sit on the exact field, so a few Newton steps along the edge finish on `field` itself.
  constexpr int kPolishSteps = 4;
  for (int step = 0;; ++step) {
    root.sample = source.field(root.position);
    ++root.evaluations;
    const double residual = root.sample.value - threshold;
    root.converged = std::abs(residual) <= tolerance_abs;
    const double slope = glm::dot(root.sample.gradient, edge);
    if (root.converged || step == kPolishSteps || !(slope != 0.0)) break;
    const double next = std::clamp(t - residual / slope, kEdgeMargin, 1.0 - kEdgeMargin);
    if (!(std::abs(next - t) <= 1e-3)) break;  // far off: a jump, not rounding
    t = next;
    root.position = a + t * edge;
  }
  return root;
}

}  // namespace convray::polygonize
