#pragma once
// Front to back along a cluster of overlapping supports, on the summed exact field: the fast
// path of ConvolutionSurface for rays (docs/ray-tracing.md, "Window march").
//
// The field F of the primitives whose support the ray crosses is sampled by value only
// (about half the cost of a sample with its gradient), every triangle of a mesh through the
// SIMD batch at once. Between two samples on the same side of T, certified one-sided bounds
// on F'' (each primitive's own over the window, summed over those whose support meets it:
// line_curvature.hpp) bound how far F can leave its chord: below T, F'' >= -D gives
// F <= chord + D s (h - s) / 2, a parabola whose peak is found exactly (above T the mirror
// image with the upward bound U). A window whose parabola stays off T holds no pair of
// crossings; one whose parabola reaches T is halved. Each next window is the longest over
// which that bound would still hold if F ended it where it started; the sum of each
// primitive's bound over its whole line (cheap) is tried before the window's own.
// A sign change between samples brackets a root, refined on the exact field
// (core/bracket_refine.hpp) from the root of the parabola through the bracket and the
// sample before it.
//
// Windows narrower than 10^-3 of the smallest radius are not halved further: there the field
// only touches T, as the fitted path and the reference tracer also accept.
#include <optional>
#include <span>
#include <vector>

#include "accel/support_index.hpp"
#include "accel/triangle_line.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/surface_roots.hpp"

namespace convray::implicit {

// Appends the roots of F = T in [tmin, tmax] that `mode` asks for. `cluster` holds the
// supports crossing the ray there, sorted by entry (every primitive whose support meets the
// ray in [tmin, tmax]); `lines` holds the rows their `terms` name, which every triangle's
// interval must have (SupportIndex::intersect with a TriangleLineTable). With RootMode::first
// and `first_gradient`, the exact gradient at the root is put there. RootMode::any appends a
// point past the first sign change, unrefined; with `inside`, the largest ball certified
// inside the surface (inside_balls.hpp) around a few points from the first sample found
// inside on, within [tmin, tmax]. `near_hit` and `start`: as find_roots takes them.
void march_cluster(const ConvolutionSurface::Impl& surface, const Ray& ray,
                   std::span<const accel::SupportInterval> cluster,
                   const accel::TriangleLineTable& lines, double tmin, double tmax,
                   RootMode mode, std::vector<double>& out, TraceStats& stats,
                   std::optional<Vec3>* first_gradient, InsideBall* inside = nullptr,
                   NearHit* near_hit = nullptr, const NearHit* start = nullptr);

}  // namespace convray::implicit
