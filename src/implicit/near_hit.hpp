#pragma once
// Where a shadow ray leaves a surface, the field is known without a sample. The window march
// of a first hit samples F and its gradient a hair from the root it returns (its last Newton
// step starts there: window_march.cpp, polish_with_gradient); the shadow rays of that hit
// start at the root, and their march would begin with a sample of F at tmin, a hair further,
// where F is within a part in 10^5 of T. (The soup of scenes/soup.pov: 128,000 shadow rays
// leaving the surface, 2 to 4 samples each, the first always that one.)
//
// The bound that replaces it: every primitive's weighted field f_i has a Hessian whose
// eigenvalues lie within +-H_i = 2 Impl::bend_bound(i) (the kernel's within [-4, 8] / R^2,
// surface_impl.hpp), so f_i(x) <= f_i(p) + grad f_i(p).(x - p) + H_i |x - p|^2 / 2 for any x
// and p. Summed over the primitives whose support holds x (the others are 0 at x), with those
// whose support holds p but not x moved over by their lower bound (f_i(x) = 0 there):
//   F(x) <= F(p) + grad F(p).(x - p) + (H(p) + H(x)) |x - p|^2 / 2,
// H(y) the sum of H_i over the primitives whose support holds y. At the shadow ray's tmin,
// F(p) + grad F(p).(x - p) is T plus the slope along the ray times tmin (below T where the ray
// leaves the surface): the march starts from that bound instead of a sample, an upper bound
// that every later test reads the same way (a window below T is excluded by its chord from
// the bound as from the value).
//
// The near-hit sample is kept per thread, surface and run of coherent rays (as HitHints and
// InsideBalls are): the next shadow rays of the same pixel use it, and a picture does not
// depend on which tiles a thread traced before. A stale one is still a valid bound, only a
// loose one: it is used where the ray starts within kNearHitReach smallest radii of it.
#include "core/ray.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {

// An exact sample of F beside a first hit's root, and H there (see above); `bend` < 0: none.
struct NearHit {
  Vec3 point{0.0};
  double value = 0.0;
  Vec3 gradient{0.0};
  double bend = -1.0;
};

// The upper bound above on F at x, given H(x) (`bend_at_x`), rounding included.
double field_bound_near(const NearHit& hit, const Vec3& x, double bend_at_x);

// The window march starts from the bound only this close to the near-hit sample (in smallest
// radii): further off, the quadratic term leaves the bound above T anyway.
inline constexpr double kNearHitReach = 1e-3;

class NearHits {
 public:
  // The sample of the last first hit on `surface` in this thread's run, if any.
  static const NearHit* find(const ConvolutionSurface::Impl& surface);
  static void remember(const ConvolutionSurface::Impl& surface, const NearHit& hit);
};

}  // namespace convray::implicit
