#pragma once
// Orientation predicates whose sign is exact for any finite double input: the determinant is
// first evaluated in plain double arithmetic with a bound on its rounding error, and only when
// the bound cannot decide the sign is it evaluated again exactly, as a floating-point
// expansion (a sum of non-overlapping doubles, Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997). Exact unless an intermediate
// product overflows or underflows, which needs coordinates beyond about 1e75 or below 1e-75.
//
// Why: whether two nearly touching triangles cross cannot be decided with a tolerance; a
// self-intersection check built on one flags slivers that only come within rounding of each
// other (see docs/polygonization.md).
#include "util/math.hpp"

namespace convray::mesh {

// Sign of det[b - a, c - a]: +1 when a, b, c turn counter-clockwise, -1 clockwise, 0 collinear.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

// Sign of det[b - a, c - a, d - a]: +1 when d lies on the side of the plane (a, b, c) that
// the normal (b - a) x (c - a) points to, -1 on the other side, 0 when the four are coplanar.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The same two determinants evaluated exactly, without the floating-point filter: the slow
// twin the tests compare the filtered predicates with.
int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c);
int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace convray::mesh
