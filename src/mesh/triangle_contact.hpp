#pragma once
// Exact contact tests between triangles in space, built only on the exact orientation
// predicates (mesh/exact_predicates.hpp): no tolerance anywhere, so touching counts as meeting
// and a gap of one unit in the last place counts as a gap. Triangles must not be flat (three
// collinear corners, see is_flat); segments must have two distinct ends.
#include <array>

#include "util/math.hpp"

namespace convray::mesh {

using Corners = std::array<Vec3, 3>;

// Whether the three corners are collinear (or two coincide): such a triangle has no plane.
bool is_flat(const Corners& t);

// Whether the closed segment [s0, s1] and the closed triangle t have a point in common.
bool segment_meets_triangle(const Vec3& s0, const Vec3& s1, const Corners& t);

// Whether the closed triangles p and q have a point in common.
bool triangles_meet(const Corners& p, const Corners& q);

// Whether two faces of one mesh intersect where a mesh may not: beyond the corners they share,
// corners being shared when their positions are equal. With no shared corner, any common
// point; with one, a common point other than it; with two (a common edge), any overlap beyond
// that edge, which only coplanar faces folded onto each other have; with three, always (the
// same face twice).
bool faces_intersect(const Corners& p, const Corners& q);

}  // namespace convray::mesh
