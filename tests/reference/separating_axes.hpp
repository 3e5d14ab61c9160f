#pragma once
// Whether two convex polytopes with integer corners (points, segments, triangles, quads) have
// a point in common, by the separating axis theorem in exact integer arithmetic: an
// independent oracle for the exact triangle contact tests (which use floating-point
// expansions and case analysis instead).
#include <cstdint>
#include <vector>

namespace convray::reference {

struct IntPoint {
  int64_t x, y, z;
};

// Two closed convex hulls of a few points each (at most 4; coordinates within 2^20 in
// magnitude) meet unless some axis separates them strictly. The candidate axes are every
// difference of two corners of one hull, every cross product of two such differences (face
// normals, edge-edge directions) and every cross product of one of those with a difference
// (directions within a common plane), which covers the flat and collinear cases too.
bool convex_hulls_meet(const std::vector<IntPoint>& a, const std::vector<IntPoint>& b);

}  // namespace convray::reference
