#pragma once
// Front to back along a cluster of overlapping supports, on the summed exact field: the fast
// path of ConvolutionSurface for rays (docs/ray-tracing.md, "Window march").
//
// The field F of the primitives whose support the ray crosses is sampled with its slope,
// F(t) and F'(t), every triangle of a mesh through the SIMD batch at once. Between samples
// a certified bound M on |F''| (each primitive's own, summed over those whose support meets
// the window) says where F cannot reach T:
//   - from one sample, F stays on its side of T for a step h with
//     |F(a) - T| > |F'(a)| h + M h^2 / 2 (the step the march takes, where it is not tiny);
//   - between two samples on the same side of T, the two Taylor envelopes
//     F(a) + F'(a) s +- M s^2 / 2 and F(b) - F'(b) s' +- M s'^2 / 2 bound F; a window where
//     neither can reach T holds no pair of crossings, and one where they can is halved.
// A sign change between samples brackets a root, which is refined on the exact field
// (core/bracket_refine.hpp). The bound on |F''| follows from the kernel K(r) = (1 - r^2/R^2)^2,
// whose second derivative along any line is at most 8/R^2 in size: a triangle contributes at
// most 8/R^2 times its area, and at most 4 pi (the Hessian integrated over the disk where its
// plane meets the ball; window_march.cpp), a segment 8/R^2 times its length
// within it (at most 2R), a point 8/R^2 (curvature_bound).
//
// Windows narrower than 10^-3 of the smallest radius are not halved further: there the field
// only touches T, as the fitted path and the reference tracer also accept.
#include <optional>
#include <span>
#include <vector>

#include "accel/support_index.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/surface_roots.hpp"

namespace convray::implicit {

// Appends the roots of F = T in [tmin, tmax] that `mode` asks for. `cluster` holds the
// supports crossing the ray there, sorted by entry (every primitive whose support meets the
// ray in [tmin, tmax]). With RootMode::first and `first_gradient`, the exact gradient at the
// root is put there. RootMode::any appends a point past the first sign change, unrefined.
void march_cluster(const ConvolutionSurface::Impl& surface, const Ray& ray,
                   std::span<const accel::SupportInterval> cluster, double tmin, double tmax,
                   RootMode mode, std::vector<double>& out, TraceStats& stats,
                   std::optional<Vec3>* first_gradient);

// A bound on |d^2 f / dt^2| along any unit-speed line for primitive `id`, strength included.
double curvature_bound(const ConvolutionSurface::Impl& surface, uint32_t id);

}  // namespace convray::implicit
