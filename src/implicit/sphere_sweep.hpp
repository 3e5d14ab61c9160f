#pragma once
// The exact path for clusters of sphere supports only (POV-Ray blob spheres and skeleton
// points, both s (1 - d^2/r^2)^2): along a ray each is exactly a quartic in t on its chord,
// so between consecutive chord ends the field is one quartic, with no fit and no error band.
//
// The sweep visits the chord ends in order and keeps the sum's power coefficients up to date
// as spheres enter and leave, O(1) per event. On each piece the Bernstein hull of that
// running sum (widened by a bound on its rounding) rules out a crossing almost everywhere;
// where it cannot, the quartic is summed afresh around the piece from the active spheres'
// own terms and its roots isolated and polished on it (the one polynomial root finder,
// core/polynomial_roots.hpp). POV-Ray does the same per interval, solving every piece with a
// closed form.
#include <optional>
#include <span>
#include <vector>

#include "accel/support_index.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/surface_roots.hpp"

namespace convray::implicit {

// Whether every support in the cluster is a sphere's (the sweep below applies).
bool only_spheres(const ConvolutionSurface::Impl& surface,
                  std::span<const accel::SupportInterval> cluster);

struct SphereSweepRequest {
  const Ray& ray;
  RootMode mode = RootMode::all;
  // With RootMode first: where to put the exact gradient at the root, from the spheres that
  // the sweep has at hand there (no point query needed); may be null.
  std::optional<Vec3>* gradient = nullptr;
  // With RootMode any: where to leave a ball inside the surface (find_roots); may be null.
  InsideBall* inside = nullptr;
  // The window march's near-hit sample, out (RootMode first) and in (RootMode any); the
  // sphere sweep has no use for them (find_roots).
  NearHit* near_hit = nullptr;
  const NearHit* start = nullptr;
};

// Appends the roots in [tmin, tmax] of the field of sphere supports, ascending; with RootMode
// first or any, only the first. The supports may come in any order (they are reordered here)
// and need not overlap: between them the field is zero.
void sweep_spheres(const ConvolutionSurface::Impl& surface, const SphereSweepRequest& request,
                   std::span<accel::SupportInterval> supports, double tmin, double tmax,
                   std::vector<double>& out, TraceStats& stats);

}  // namespace convray::implicit
