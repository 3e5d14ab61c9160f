#pragma once
// What the classic primitives share: the surface description every crossing points at, and
// the rule for which crossings a query keeps.
#include <memory>

#include "geometry/shape.hpp"

namespace convray::geometry {

using SurfaceInfoPtr = std::shared_ptr<const SurfaceInfo>;

// Appends the crossing at t when it lies in the open interval (tmin, tmax).
inline void add_crossing(double t, const Vec3& normal, const SurfaceInfo* surface, double tmin,
                         double tmax, std::vector<Crossing>& out) {
  if (t > tmin && t < tmax) out.push_back({t, normal, surface});
}

}  // namespace convray::geometry
