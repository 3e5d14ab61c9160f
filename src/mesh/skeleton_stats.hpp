#pragma once
// Facts about a file's segments and points, and the kernel radius to start from for the
// whole skeleton (`convray info`, and the default of `quick` and `polygonize`). The
// triangles' own facts are in stats.hpp.
#include <cstddef>

#include "mesh/load.hpp"
#include "mesh/stats.hpp"

namespace convray::mesh {

struct SkeletonStats {
  size_t segments = 0;
  double mean_segment_length = 0.0;
  size_t points = 0;
  double mean_point_spacing = 0.0;  // see point_spacing.hpp
  Box3 bounds;                      // of everything rendered: triangles, segments, points
};

SkeletonStats compute_skeleton_stats(const LoadedMesh& mesh);

// The radius advice and what it rests on: with triangles, advised_radius (the smaller of the
// mean edge length and a tenth of the largest dimension); without, the same with the mean
// segment length or, for points alone, twice the mean point spacing (so that neighbouring
// points' supports overlap well and their spheres merge into one surface).
enum class RadiusBasis { edges, segments, points, size };
struct RadiusAdvice {
  double radius = 1.0;
  RadiusBasis basis = RadiusBasis::size;
  double measure = 0.0;  // the mean edge or segment length, or twice the mean point spacing
  double largest = 0.0;  // the largest dimension of the bounds
};
RadiusAdvice advise_radius(const MeshStats& triangles, const SkeletonStats& skeleton);

}  // namespace convray::mesh
