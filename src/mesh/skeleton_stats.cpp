#include "mesh/skeleton_stats.hpp"

#include <algorithm>

#include "mesh/point_spacing.hpp"

namespace convray::mesh {

SkeletonStats compute_skeleton_stats(const LoadedMesh& mesh) {
  SkeletonStats stats;
  stats.bounds = mesh.bounds();
  stats.segments = mesh.segments.size();
  double total = 0.0;
  for (const Segment& s : mesh.segments) total += glm::length(mesh.soup.vertices[s[1]] - mesh.soup.vertices[s[0]]);
  if (stats.segments > 0) stats.mean_segment_length = total / static_cast<double>(stats.segments);
  stats.points = mesh.points.size();
  std::vector<Vec3> points;
  points.reserve(mesh.points.size());
  for (uint32_t p : mesh.points) points.push_back(mesh.soup.vertices[p]);
  stats.mean_point_spacing = mean_point_spacing(points);
  return stats;
}

RadiusAdvice advise_radius(const MeshStats& triangles, const SkeletonStats& skeleton) {
  RadiusAdvice advice;
  const Vec3 size = skeleton.bounds.extent();  // the triangles' bounds, for a file of triangles alone
  advice.largest = std::max({size.x, size.y, size.z});
  if (triangles.triangles > 0) {
    advice.basis = RadiusBasis::edges;
    advice.measure = triangles.mean_edge_length;
  } else if (skeleton.segments > 0) {
    advice.basis = RadiusBasis::segments;
    advice.measure = skeleton.mean_segment_length;
  } else if (skeleton.mean_point_spacing > 0.0) {
    advice.basis = RadiusBasis::points;
    advice.measure = 2.0 * skeleton.mean_point_spacing;
  }
  // One point (or one position) has no spacing and no size: any radius draws a sphere.
  if (advice.basis == RadiusBasis::size) advice.radius = advice.largest > 0.0 ? advice.largest / 10.0 : 1.0;
  else advice.radius = std::min(advice.measure, advice.largest / 10.0);
  return advice;
}

}  // namespace convray::mesh
