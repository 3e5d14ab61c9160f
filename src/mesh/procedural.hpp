#pragma once
// Meshes made by code: for tests (their statistics are known exactly), for benchmarks, and
// for examples. All are counter-clockwise seen from outside (from +z for the flat ones).
#include <array>
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

// The soup of the repair tests and docs (docs/repair.md; scenes/models/repair_soup.obj): a
// flat sheet in the plane z = 0 over [-2, 2] x [-2, 2], made of four tiles of 2 x 2 centred
// at (-1, 1), (1, 1), (-1, -1) and (1, -1). Each of the first three has a round hole at its
// centre; the fourth is solid and carries the defects, so the holes see clean sheet around
// them. A tile is `rings` rings of `spokes` quads (two triangles each) between the hole's
// outline and the tile's square border; the solid tile's innermost ring is a fan around its
// centre. Tiles share their borders' vertices exactly, so the sheet is one piece.
//
// The hole of radius a is the regular polygon of `spokes` corners on the circle of radius a
// (a corner at -45 degrees): circumscribed radius a, inscribed radius a cos(pi / spokes)
// (0.9979 a at 48 spokes). The convolution surface at offset D closes the hole when a <= D:
// the field at the centre of a round hole of radius a equals the plane's field at distance a.
//
// Clean (no defects), with N = spokes, K = rings, M = N / 4 edges per tile side: a disk with
// three holes, Euler characteristic -2; 8M + 3N boundary edges. Each defect sits on its own
// triangle of the solid tile's middle ring, none touching another, so their effects add up:
struct RepairDefects {
  std::array<double, 3> hole_radii = {0.15, 0.3, 0.45};  // each below 1 (the tile's half size)
  int spokes = 48;     // corners of each hole, a multiple of 8 (at least 16)
  int rings = 8;       // at least 4
  int flipped = 2;     // reversed triangles: +3 inconsistent edges each
  int duplicated = 2;  // appended copies: +3 non-manifold edges and +1 Euler characteristic each
  int slivers = 2;     // triangles split in three around a point just inside an edge, one of the
                       // three needle-thin: +2 triangles each, topology unchanged
  bool fin = true;     // a triangle standing upright on an inner edge: +1 non-manifold edge,
                       // +2 boundary edges, Euler characteristic unchanged
};
TriangleSoup repair_soup(const RepairDefects& defects = {});

}  // namespace convray::mesh
