#pragma once
// Balls known to lie inside a convolution surface, for its shadow rays. Where every strength
// is positive, each primitive's field is >= 0, so at any q the field is at least the sum of
// the fields of the primitives whose support holds a point p; that sum bends down by at most
// the sum of their bend bounds B (Impl::bend_bound), so F(q) >= F(p) - |grad F(p)| d - B d^2/2
// at distance d, and F > T on the ball around p where that stays above T.
//
// A shadow ray that finds the surface in its way (Surface::occluded) leaves such a ball on its
// thread, around the deepest of a few points past where its window march found F > T (with
// the march's members at hand, a sample each: window_march.cpp); the next shadow rays
// of the same run of coherent rays (core/coherent_rays.hpp: a tile's pixels), whose segments
// pass near the same place, are settled by a segment-ball test instead of a search. A segment
// through a point with F > T crosses the surface where one of its ends has F < T; the test is
// used only where the segment's far end lies on the supports' bounding box (F = 0 there: the
// light is outside it). The answer is the search's either way, so pictures do not depend on
// which rays came before.
#include "core/ray.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/surface_roots.hpp"

namespace convray::implicit {

// The radius of the ball around p where F > T, given F(p) (`value`), |grad F(p)| (`slope`),
// and the sum of Impl::bend_bound over the primitives whose support holds p (`bend`): where
// F(q) >= F(p) - slope d - bend d^2 / 2 at distance d stays above T. 0 where F(p) <= T.
double inside_radius(double value, double threshold, double slope, double bend);

class InsideBalls {
 public:
  // Whether a ball of this thread's run certifies that the segment [tmin, tmax] of `ray`
  // crosses `surface` (see above).
  static bool settle(const ConvolutionSurface::Impl& surface, const Ray& ray, double tmin,
                     double tmax);
  // Whether the search of a shadow ray that settle() left open should look for a ball where
  // it finds the ray blocked (inside_balls.cpp: only while the balls pay for the looking).
  static bool worth_looking(const ConvolutionSurface::Impl& surface);
  // After a search found the ray blocked: keeps `ball` (certified inside `surface`, or null
  // where the search did not look) for the next rays of this thread's run.
  static void remember(const ConvolutionSurface::Impl& surface, const InsideBall* ball);
};

}  // namespace convray::implicit
