#pragma once
// How far a polygonized mesh strays from the exact surface, and the extraction that keeps it
// within a requested bound (`convray polygonize --max-error E`).
#include "polygonize/polygonize.hpp"

namespace convray::polygonize {

// The distance from p to F = T, by Newton steps along the gradient (exact to first order at
// the start, converged after a few steps wherever the gradient does not vanish).
double distance_to_surface(const FieldSource& source, const Vec3& p);

// The largest distance_to_surface over the triangles' centroids, where a flat triangle between
// vertices on a curved surface departs from it the most. The vertices themselves lie on the
// surface (polygonize.hpp).
double max_centroid_distance(const FieldSource& source, const SurfaceMesh& mesh);

struct ErrorBoundedResult {
  SurfaceMesh mesh;
  double cell = 0.0;   // the spacing that met the bound
  double error = 0.0;  // its max_centroid_distance
  int passes = 0;      // extractions run
};

// Extracts with `options`, starting from `first_cell`, then again with a finer cell until the
// max_centroid_distance is at most `max_error`: the chord error shrinks as the square of the
// cell, so each pass scales the cell by sqrt(bound / error) (with a 10% margin). Throws
// std::runtime_error after 8 passes without meeting the bound (a bound the grid cannot reach).
ErrorBoundedResult polygonize_to_error(const FieldSource& source, double max_error,
                                       double first_cell, PolygonizeOptions options,
                                       PolygonizeStats* stats = nullptr);

}  // namespace convray::polygonize
