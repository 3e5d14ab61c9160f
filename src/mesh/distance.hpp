#pragma once
// How far apart two triangle soups are (`convray distance`): the one-sided and symmetric
// Hausdorff distances and the mean distance, as Metro (Cignoni et al. 1998) measures them.
//
// The distance from soup A to soup B is the largest, over points p of A, of the distance from
// p to the nearest point of B's triangles. It is measured on A's vertices plus a dense,
// deterministic set of surface samples (sample_surface below); the distance from each point to
// B is exact (closest point on each triangle), found through a bounding-volume hierarchy over
// B. The sampled maximum can only fall short of the true one: by at most the spacing of the
// samples, since the distance to B is 1-Lipschitz in p.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "mesh/soup.hpp"

namespace convray::mesh {

// Distance from p to the nearest point of the triangle abc (its closest point, not its
// plane); degenerate triangles count as their longest side.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Points spread evenly over a soup's surface, each standing for a piece of its area.
struct SurfaceSamples {
  std::vector<Vec3> points;
  std::vector<double> areas;  // the piece each point stands for; they add up to the soup's area
};

// About `count` points (at least one per triangle with area), in proportion to area: triangle
// t with area A_t is cut into L^2 equal triangles by L = ceil(sqrt(count * A_t / total area))
// cuts along each side, and their centroids are the samples. Deterministic.
SurfaceSamples sample_surface(const TriangleSoup& soup, size_t count);

struct DistanceOptions {
  size_t samples = 200000;  // surface samples of each soup, besides its vertices
};

// One direction, from the points of one soup to the triangles of the other.
struct OneSidedDistance {
  double max = 0.0;    // over the vertices and the samples: the one-sided Hausdorff distance
  double mean = 0.0;   // over the surface samples, weighted by the area each stands for
  size_t points = 0;   // vertices and samples measured
  Vec3 farthest{0.0};  // the point where `max` was found
};

struct HausdorffDistance {
  OneSidedDistance a_to_b, b_to_a;
  double symmetric() const { return std::max(a_to_b.max, b_to_a.max); }
  double mean() const { return 0.5 * (a_to_b.mean + b_to_a.mean); }
};

// From `from`'s vertices (those its triangles use) and surface samples to `to`'s triangles.
// Both soups need at least one triangle; their indices must be in range.
OneSidedDistance one_sided_distance(const TriangleSoup& from, const TriangleSoup& to,
                                    const DistanceOptions& options = {});

// Both directions.
HausdorffDistance hausdorff_distance(const TriangleSoup& a, const TriangleSoup& b,
                                     const DistanceOptions& options = {});

}  // namespace convray::mesh
