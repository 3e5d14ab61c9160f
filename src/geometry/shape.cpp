#include "geometry/shape.hpp"

namespace convray::geometry {

std::optional<Crossing> Shape::first_crossing(const Ray& ray, double tmin, double tmax,
                                              TraceStats& stats) const {
  std::vector<Crossing> all;
  crossings(ray, tmin, tmax, all, stats);
  if (all.empty()) return std::nullopt;
  return all.front();
}

}  // namespace convray::geometry
