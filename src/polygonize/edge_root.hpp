#pragma once
// The point where the surface F = T crosses one lattice edge, found on the exact field.
#include "field/sample.hpp"
#include "polygonize/field_source.hpp"
#include "util/math.hpp"

namespace convray::polygonize {

struct EdgeRoot {
  Vec3 position{0.0};
  field::FieldSample sample;  // F and grad F at `position`
  int evaluations = 0;
  bool converged = false;  // |F - T| <= tolerance * T
};

// The crossing between `a` and `b`, whose field values `fa` and `fb` lie on opposite sides of T
// (one >= T, the other < T). The one bracketed refiner (core's refine_bracket), stopped on the
// residual |F - T| <= tolerance * T: it keeps the bracket (so the point stays on the edge, which
// is what keeps the mesh free of self-intersections) and converges superlinearly on smooth
// fields. At a jump of the field (a truncated kernel) it shrinks the bracket onto the jump and
// reports not converged.
// The answer stays a hair inside the edge, so it never coincides with a lattice point that
// other edges' vertices could also sit on. The search reads F alone (FieldSource::value_at,
// which may be a fast approximation); Newton steps along the edge on FieldSource::field then
// put the answer on the exact field, whose gradient gives the normal.
EdgeRoot find_edge_root(const FieldSource& source, const Vec3& a, double fa, const Vec3& b,
                        double fb, double tolerance);

}  // namespace convray::polygonize
