#pragma once
// Shared vocabulary of bench/polygonizer_libraries: the problem every polygonizer gets (the
// convolution field of a soup, its threshold, a cell size), what it hands back (a triangle
// soup plus its wall time), and the quality measures applied to every output alike.
// Evaluation code for docs/polygonization-libraries.md, not part of convray.
#include <string>
#include <vector>

#include "implicit/mesh_field.hpp"
#include "mesh/soup.hpp"

namespace convray::bench {

// The surface F = T of a soup's convolution field, to be meshed at resolution `cell`.
struct Problem {
  const implicit::MeshField* field = nullptr;
  double threshold = 0.0;
  double offset = 0.0;  // the D that gave the threshold: the flat-region distance to the soup
  double cell = 1.0;
  Box3 soup_bounds;  // of the soup's triangles; the surface lies within radius of it
  const mesh::TriangleSoup* soup = nullptr;
};

struct PolygonizerOutput {
  mesh::TriangleSoup mesh;
  double seconds = 0.0;  // wall clock of the polygonizer alone (no quality measures)
  std::string note;      // parameters and what ran in parallel, for the report
};

// Every method orients its triangles counter-clockwise seen from outside (F < T).
PolygonizerOutput polygonize_dual_contouring(const Problem& problem);
PolygonizerOutput polygonize_openvdb(const Problem& problem, double adaptivity);
PolygonizerOutput polygonize_cgal(const Problem& problem);

// The repair comparison: OpenVDB's unsigned distance field of the soup (voxel size `cell`),
// meshed at isovalue `offset`. Outward-facing like the others.
PolygonizerOutput openvdb_soup_offset(const Problem& problem, double offset);

struct Quality {
  size_t triangles = 0, vertices = 0;
  size_t boundary_edges = 0, non_manifold_edges = 0, inconsistent_edges = 0;
  size_t components = 0;
  long euler = 0;
  size_t degenerate_triangles = 0;
  size_t self_intersecting_pairs = 0;  // pairs of faces meeting beyond shared corners (exact)
  double max_field_error = 0.0;        // max over vertices of |F - T| / T
  double mean_field_error = 0.0;
  double min_angle_degrees = 0.0;
  double small_angle_fraction = 0.0;   // of triangles whose smallest angle is below 10 degrees
  double max_centroid_distance = 0.0;  // centroid to the surface, by Newton projection
  double mean_centroid_distance = 0.0;
  size_t unprojected_centroids = 0;  // Newton did not converge: left out of the two above
  double outward_fraction = 0.0;     // triangles whose normal agrees with -grad F
  double max_offset_error = 0.0;     // max over vertices of |distance to the soup - D|
  double mean_offset_error = 0.0;
};

// Measures `mesh` against the problem's surface. Runs on the TBB threads allowed.
Quality measure_quality(const Problem& problem, const mesh::TriangleSoup& mesh);

}  // namespace convray::bench
