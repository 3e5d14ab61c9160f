#pragma once
// Marching tetrahedra on the Kuhn (Freudenthal) triangulation of the cube: each cell split into
// six tetrahedra around its main diagonal, the same way in every cell, so that neighbouring
// cells cut their shared faces along the same diagonal and the tetrahedra form one consistent
// triangulation of space. The surface is then the zero set of the piecewise-linear
// interpolant of (F - T) on that triangulation, with each vertex moved along its edge onto the
// exact F = T. That surface is, by construction:
// - closed and 2-manifold: a linear function on a tetrahedron crosses zero in one triangle or
//   one quadrilateral, and neighbouring tetrahedra agree on the segment across their shared
//   face (a lattice point counts as inside when F >= T, never "on" the surface);
// - free of self-intersections: each piece lies in its own tetrahedron, touching the others
//   only along those shared segments; moving a vertex along its edge keeps that true;
// - consistently oriented: every piece is turned so its normal points from inside to outside.
#include <array>
#include <cstdint>
#include <vector>

namespace convray::polygonize {

// A tetrahedron edge as two cube corners (bit 0: +x, bit 1: +y, bit 2: +z), `low` a subset of
// `high`: every edge of the Kuhn triangulation joins such corners, so (grid point of `low`,
// direction high ^ low) names each lattice edge once, whichever cell sees it.
struct CubeEdge {
  uint8_t low = 0, high = 0;
};

// The surface pieces in one cell for one assignment of inside corners (bit c of `inside` set
// when corner c has F >= T): triangles and quadrilaterals, each corner a CubeEdge crossed by
// the surface, counter-clockwise seen from outside. A quadrilateral's corners run around it, so
// either diagonal splits it into two outward-facing triangles.
struct CellPieces {
  std::vector<std::array<CubeEdge, 3>> triangles;
  std::vector<std::array<CubeEdge, 4>> quads;
};

// The pieces for each of the 256 corner assignments, computed once.
const std::array<CellPieces, 256>& cell_pieces();

}  // namespace convray::polygonize
