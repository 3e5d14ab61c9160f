#include "polygonize/surface_error.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace convray::polygonize {

double distance_to_surface(const FieldSource& source, const Vec3& p) {
  constexpr int kMaxSteps = 8;
  Vec3 q = p;
  for (int step = 0; step < kMaxSteps; ++step) {
    const field::FieldSample s = source.field(q);
    const double g2 = glm::dot(s.gradient, s.gradient);
    const double excess = s.value - source.threshold;
    if (!(g2 > 0.0) || std::abs(excess) <= 1e-12 * source.threshold) break;
    q -= (excess / g2) * s.gradient;
  }
  return glm::distance(p, q);
}

double max_centroid_distance(const FieldSource& source, const SurfaceMesh& mesh) {
  const mesh::TriangleSoup& soup = mesh.soup;
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, soup.triangles.size(), 256), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double worst) {
        for (size_t t = r.begin(); t < r.end(); ++t) {
          const auto [a, b, c] = soup.corners(t);
          worst = std::max(worst, distance_to_surface(source, (a + b + c) / 3.0));
        }
        return worst;
      },
      [](double x, double y) { return std::max(x, y); });
}

ErrorBoundedResult polygonize_to_error(const FieldSource& source, double max_error,
                                       double first_cell, PolygonizeOptions options,
                                       PolygonizeStats* stats) {
  if (!(max_error > 0.0)) throw std::invalid_argument("the max error must be > 0");
  constexpr int kMaxPasses = 8;
  ErrorBoundedResult result;
  options.cell = first_cell;
  for (result.passes = 1; result.passes <= kMaxPasses; ++result.passes) {
    result.mesh = polygonize(source, options, stats);
    result.cell = options.cell;
    result.error = max_centroid_distance(source, result.mesh);
    if (result.error <= max_error) return result;
    // Chord error ~ cell^2 * curvature: aim 10% under the bound; refine by at least 10% and
    // at most 4x per pass (the error estimate is rough on coarse meshes).
    if (options.on_predicted_cell) {
      options.on_predicted_cell(0.9 * options.cell * std::sqrt(max_error / result.error));
    }
    const double scale = std::clamp(0.9 * std::sqrt(max_error / result.error), 0.25, 0.9);
    options.cell *= scale;
  }
  std::ostringstream message;
  message << "could not reach a max error of " << max_error << " in " << kMaxPasses
          << " passes (last: cell " << result.cell << ", error " << result.error
          << "); pass --cell instead";
  throw std::runtime_error(message.str());
}

}  // namespace convray::polygonize
