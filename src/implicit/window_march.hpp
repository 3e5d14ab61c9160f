#pragma once
// Front to back along a cluster of overlapping supports, on the summed exact field: the fast
// path of ConvolutionSurface for rays (docs/ray-tracing.md, "Window march").
//
// The field F of the primitives whose support the ray crosses is sampled with its slope,
// F(t) and F'(t), every triangle of a mesh through the SIMD batch at once. Between samples
// certified one-sided bounds on F'' (each primitive's own over the window, summed over those
// whose support meets it: line_curvature.hpp) say where F cannot reach T. Below T only how
// far F may bend up counts (U), above T only how far down (D); with M the one that counts:
//   - from one sample, F stays on its side of T for a step h with
//     |F(a) - T| > |F'(a)| h + M h^2 / 2 (the step the march takes, where it is not tiny);
//   - between two samples on the same side of T, the two Taylor envelopes
//     F(a) + F'(a) s +- M s^2 / 2 and F(b) - F'(b) s' +- M s'^2 / 2 bound F; a window where
//     neither can reach T holds no pair of crossings, and one where they can is halved.
// A sign change between samples brackets a root, which is refined on the exact field
// (core/bracket_refine.hpp).
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

}  // namespace convray::implicit
