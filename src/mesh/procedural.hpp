#pragma once
// Meshes made by code: for tests (their statistics are known exactly), for benchmarks, and
// for examples. All are counter-clockwise seen from outside (from +z for the flat ones).
// The deliberately defective soups of the tests are test fixtures: tests/fixtures/.
#include <cstddef>

#include "mesh/soup.hpp"

namespace convray::mesh {

// Icosahedron whose triangles are split in four `subdivisions` times, corners pushed onto
// the sphere: 20 * 4^s triangles, 10 * 4^s + 2 vertices, closed, one component.
TriangleSoup icosphere(const Vec3& center, double radius, int subdivisions);

// Torus around the z axis through the origin: `major` is the distance from the axis to the
// tube's centre line, `minor` the tube's radius; nu segments around the axis, nv around the
// tube. 2 * nu * nv triangles, nu * nv vertices, closed, Euler characteristic 0.
TriangleSoup torus(double major, double minor, int nu, int nv);

// Square sheet in the plane z = 0 from -half_size to +half_size in x and y, of cells x cells
// squares, each split into two triangles.
TriangleSoup flat_grid(double half_size, int cells);

// flat_grid without the squares whose centres lie within hole_radius of the origin: an
// open sheet with a round-ish hole. Its boundary runs along the outer square (4 * cells
// edges) and around the hole (the edges between removed and kept squares).
TriangleSoup sheet_with_hole(double half_size, int cells, double hole_radius);

}  // namespace convray::mesh
