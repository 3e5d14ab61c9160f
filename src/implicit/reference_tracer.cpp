#include "implicit/reference_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/bracket_refine.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {
namespace {

// Bounds on |grad F| of one primitive with strength 1, anywhere:
//  - kernels of distance (points, blob components): max |f'(r)| = 8 / (3 sqrt(3) R);
//  - segments and arcs: max |f'| times the longest piece of skeleton inside a ball of radius R
//    (2R for a segment; for an arc, its length, at most 2 pi R);
//  - triangles: the integral of |f'| over a whole plane, 2 pi * integral of |f'(r)| r dr
//    = 16 pi R / 15.
constexpr double kKernelSlope = 8.0 / (3.0 * 1.7320508075688772);

double lipschitz(const ConvolutionSurface::Impl& s, uint32_t id) {
  if (id < s.capsule_base) return std::abs(s.sphere_strengths[id]) * kKernelSlope / s.sphere_radii[id];
  if (id < s.arc_base) {
    const uint32_t i = id - s.capsule_base;
    const double r = s.capsule_radii[i];
    const double per_length = s.capsule_is_blob[i] ? 1.0 / r : 2.0;
    return std::abs(s.capsule_strengths[i]) * kKernelSlope * per_length;
  }
  if (id < s.triangle_base) {
    const uint32_t i = id - s.arc_base;
    const double r = s.arc_radii[i];
    const double length = std::min(s.arcs[i].angle * s.arcs[i].radius, 2.0 * kPi * r);
    return std::abs(s.arc_strengths[i]) * kKernelSlope * length / r;
  }
  const auto& g = s.group_of(id - s.triangle_base);
  return std::abs(g.strength) * 16.0 * kPi * g.radius / 15.0;
}

// Bisection of a sign change of the exact field down to adjacent doubles (at most 200 halvings).
double bisect(const ConvolutionSurface& surface, const Ray& ray, double lo, double hi, double g_lo,
              TraceStats& stats) {
  const double threshold = surface.threshold();
  const bool lo_inside = g_lo >= 0.0;
  return bisect_to_rounding(
      lo, hi,
      [&](double t) {
        ++stats.field_evaluations;
        return (surface.field(ray.at(t)).value - threshold >= 0.0) == lo_inside;
      },
      200);
}

}  // namespace

// Marches the exact field along the ray: from t, no crossing fits in a step shorter than
// |F - T| / L, where L bounds |dF/dt| over the supports the step overlaps. Steps are at least
// 1e-4 of the smallest radius (a pair of crossings closer than that can be missed: the field
// then barely touches T) and at most a quarter of it.
void reference_roots(const ConvolutionSurface& surface, const Ray& ray, double tmin, double tmax,
                     std::vector<double>& out, TraceStats& stats) {
  const ConvolutionSurface::Impl& s = surface.impl();
  std::vector<accel::SupportInterval> intervals;
  ++stats.rays;
  s.index->intersect(ray.origin, ray.direction, tmin, tmax, intervals);
  stats.primitives += intervals.size();
  if (intervals.empty()) return;
  std::sort(intervals.begin(), intervals.end(),
            [](const auto& a, const auto& b) { return a.enter < b.enter; });
  std::vector<double> slope(intervals.size());
  double end = tmin;
  for (size_t i = 0; i < intervals.size(); ++i) {
    slope[i] = lipschitz(s, intervals[i].primitive);
    end = std::max(end, intervals[i].exit);
  }
  end = std::min(end, tmax);
  const double h_min = 1e-4 * s.min_radius, h_max = 0.25 * s.min_radius;
  const double threshold = surface.threshold();
  auto g_at = [&](double t) {
    ++stats.field_evaluations;
    return surface.field(ray.at(t)).value - threshold;
  };

  double t = std::max(tmin, intervals.front().enter);
  double g = g_at(t);
  while (t < end) {
    double bound = 0.0, next_enter = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < intervals.size(); ++i) {
      const auto& iv = intervals[i];
      if (iv.exit < t) continue;
      if (iv.enter > t + h_max) {
        next_enter = std::min(next_enter, iv.enter);
        continue;
      }
      bound += slope[i];
    }
    double t1;
    if (bound == 0.0) {  // a gap between supports: F = 0 < T, jump to the next one
      if (!std::isfinite(next_enter)) break;
      t1 = std::min(next_enter, end);
    } else {
      t1 = std::min(t + std::clamp(std::abs(g) / bound, h_min, h_max), end);
    }
    const double g1 = g_at(t1);
    if ((g >= 0.0) != (g1 >= 0.0)) out.push_back(bisect(surface, ray, t, t1, g, stats));
    t = t1;
    g = g1;
  }
  stats.roots += out.size();
}

std::optional<SurfaceHit> reference_first_hit(const ConvolutionSurface& surface, const Ray& ray,
                                              double tmin, double tmax, TraceStats& stats) {
  std::vector<double> roots;
  reference_roots(surface, ray, tmin, tmax, roots, stats);
  if (roots.empty()) return std::nullopt;
  return make_surface_hit(surface, ray, roots.front());
}

}  // namespace convray::implicit
