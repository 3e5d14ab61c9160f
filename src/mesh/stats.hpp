#pragma once
// Facts about a triangle soup that help decide how to render it (`convray info`).
//
// Topology is computed on welded vertices: positions that are exactly equal count as one
// vertex, because STL, and many soups, repeat a position instead of sharing an index.
// Everything is sorting, O(n log n): a million triangles take well under a second.
#include <cstddef>

#include "mesh/soup.hpp"

namespace convray::mesh {

struct MeshStats {
  size_t triangles = 0;
  size_t vertices = 0;                 // distinct positions used by the triangles
  Box3 bounds;                         // of the triangles' corners
  double mean_edge_length = 0.0;       // over distinct edges (between distinct positions)
  size_t edges = 0;                    // distinct edges
  size_t boundary_edges = 0;           // edges of exactly one triangle
  size_t non_manifold_edges = 0;       // edges of three or more triangles
  size_t inconsistent_edges = 0;       // edges of two triangles that run along it the same way
                                       // (one of the two is flipped)
  size_t degenerate_triangles = 0;     // triangles with two corners at the same position
  size_t connected_components = 0;     // groups of triangles connected through shared positions

  // V - E + F over the welded mesh: 2 for a closed sphere-like surface, 0 for a torus.
  long euler_characteristic() const {
    return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(triangles);
  }
};

// The soup's indices must be in range (as load_mesh and the generators guarantee).
MeshStats compute_stats(const TriangleSoup& soup);

// The kernel radius to start from. R sets how far each triangle's influence reaches: about an
// edge length keeps the surface close to the triangles, while a sizeable fraction of the model
// melts it into a blob. So: the smaller of the mean edge length and a tenth of the largest
// dimension of the bounds.
double advised_radius(const MeshStats& stats);

}  // namespace convray::mesh
