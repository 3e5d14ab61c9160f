#pragma once
// Finding F = T along a ray, the paper's Section 4: gather the primitives whose support the
// ray crosses, fit each one's field on its interval with a degree-6 polynomial (Eqs. 13-19),
// bound the fit's error and subdivide where it is too large, sum the fits piecewise, isolate
// the roots of each piece by Bézier clipping against the error band, and polish every root
// on the exact field. Stretches of the ray where only spheres (points, blob spheres) reach
// need no fit: their field is exactly a quartic per piece (sphere_sweep.hpp).
#include <optional>
#include <vector>

#include "implicit/convolution_surface.hpp"

namespace convray::implicit {

enum class RootMode {
  all,    // every root in [tmin, tmax]
  first,  // the first one only
  any,    // whether there is one (shadow rays): the first one, found the same way
};

struct NearHit;  // near_hit.hpp

// A ball where F > T, certified (inside_balls.hpp); radius 0 for none.
struct InsideBall {
  Vec3 center{0.0};
  double radius = 0.0;
};

// Appends the roots in [tmin, tmax] as `mode` asks. With RootMode first and `first_gradient`,
// the exact gradient at the root is put there when the finder had it at hand (the sphere
// sweep does); it is left empty otherwise. With RootMode any and `inside`, a search that finds
// a crossing leaves there a ball inside the surface beside it where the window march can
// certify one cheaply (radius 0 otherwise). With RootMode first and `near_hit`, the window
// march's exact sample beside the root goes there (near_hit.hpp; its bend stays < 0 where
// the root came another way); with RootMode any and `start`, a shadow ray that leaves the
// surface near that sample starts from the bound it gives instead of a sample, and with
// RootMode first, a ray that passes near it (the next pixel's) refines its root from the
// sample's tangent plane (window_march.cpp, kTangentReach).
void find_roots(const ConvolutionSurface::Impl& surface, const Ray& ray, double tmin, double tmax,
                RootMode mode, std::vector<double>& out, TraceStats& stats,
                std::optional<Vec3>* first_gradient = nullptr, InsideBall* inside = nullptr,
                NearHit* near_hit = nullptr, const NearHit* start = nullptr);

}  // namespace convray::implicit
