#pragma once
// The first crossing of an implicit shape in the open interval (tmin, tmax), shared by the
// convolution shapes of both kernels (ImplicitShape, CauchyShape): their surfaces search the
// closed interval, so a root on one of its ends sends us to the full list for the next one.
#include <optional>
#include <vector>

#include "geometry/shape.hpp"
#include "implicit/ray_box.hpp"

namespace convray::geometry {

template <typename ImplicitLikeShape, typename Surface>
std::optional<Crossing> first_open_crossing(const ImplicitLikeShape& shape, const Surface& surface,
                                            const Ray& ray, double tmin, double tmax,
                                            TraceStats& stats) {
  double t0 = tmin, t1 = tmax;
  if (!implicit::clip_to_box(ray, surface.bounds(), t0, t1)) return std::nullopt;
  const auto hit = surface.first_hit(ray, t0, t1, stats);
  if (!hit) return std::nullopt;
  if (hit->t > tmin && hit->t < tmax) {
    return Crossing{hit->t, hit->normal, shape.surface_at(hit->point)};
  }
  std::vector<Crossing> all;
  shape.crossings(ray, tmin, tmax, all, stats);
  if (all.empty()) return std::nullopt;
  return all.front();
}

}  // namespace convray::geometry
