#pragma once
// Meshes made by code: for tests (their statistics are known exactly), for benchmarks, and
// for examples. All are counter-clockwise seen from outside (from +z for the flat ones).
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

// A deliberately bad soup built from an icosphere (radius 1 at the origin), one defect per
// option, each with an exactly known effect on compute_stats():
struct SoupDefects {
  int subdivisions = 2;            // of the icosphere: 320 triangles at 2
  bool hole = true;                // removes the 5 triangles around vertex 0: +5 boundary edges
  bool flipped = true;             // reverses one triangle far from the hole: +3 inconsistent edges
  bool duplicated = true;          // appends a copy of another triangle: its 3 edges become non-manifold
  bool sliver = true;              // splits one triangle in three around a point just off one of its
                                   // edges: one needle-thin triangle; topology unchanged
  bool fin = true;                 // adds a triangle standing on an existing edge: +1 non-manifold,
                                   // +2 boundary edges
  bool zero_area = false;          // appends a triangle of three collinear new vertices (a loader drops it)
  bool repeated_vertex = false;    // appends a triangle naming one vertex twice (a loader drops it)
};
TriangleSoup defective_soup(const SoupDefects& defects = {});

}  // namespace convray::mesh
