// The statistics of a file's segments and points, and the radius advice for each kind of
// skeleton, on files small enough to work out by hand.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "mesh/skeleton_stats.hpp"

namespace convray::mesh {
namespace {

RadiusAdvice advice_for(const std::string& text, const std::string& name) {
  const LoadedMesh mesh = load_mesh_from_memory(text, name);
  return advise_radius(compute_stats(mesh.soup), compute_skeleton_stats(mesh));
}

TEST(SkeletonStats, SegmentsAndPointsByHand) {
  // Polyline (0,0,0)-(3,0,0)-(3,4,0): lengths 3 and 4; points at x = 10, 11, 13.
  const LoadedMesh mesh = load_mesh_from_memory(
      "v 0 0 0\nv 3 0 0\nv 3 4 0\nv 10 0 0\nv 11 0 0\nv 13 0 0\nl 1 2 3\np 4 5 6\n", "mixed.obj");
  const SkeletonStats stats = compute_skeleton_stats(mesh);
  EXPECT_EQ(stats.segments, 2u);
  EXPECT_EQ(stats.mean_segment_length, 3.5);
  EXPECT_EQ(stats.points, 3u);
  EXPECT_DOUBLE_EQ(stats.mean_point_spacing, (1.0 + 1.0 + 2.0) / 3.0);
  EXPECT_EQ(stats.bounds.lo, Vec3(0, 0, 0));
  EXPECT_EQ(stats.bounds.hi, Vec3(13, 4, 0));
}

TEST(SkeletonStats, RadiusAdviceForEachKind) {
  // A point cloud on a line, 1 apart over 20: twice the spacing (2) against a tenth of 20.
  std::string points;
  for (int k = 0; k <= 20; ++k) points += "v " + std::to_string(k) + " 0 0\n";
  RadiusAdvice advice = advice_for(points, "line_of_points.obj");
  EXPECT_EQ(advice.basis, RadiusBasis::points);
  EXPECT_EQ(advice.radius, 2.0);
  // Segments of length 1 over a size of 20: the segment length.
  advice = advice_for(points + "l 1 2\nl 20 21\n", "two_segments.obj");
  EXPECT_EQ(advice.basis, RadiusBasis::segments);
  EXPECT_EQ(advice.radius, 1.0);
  // A triangle of legs 10: mean edge (10 + 10 + 10 sqrt 2) / 3 against a tenth of 10.
  advice = advice_for("v 0 0 0\nv 10 0 0\nv 0 10 0\nf 1 2 3\n", "triangle.obj");
  EXPECT_EQ(advice.basis, RadiusBasis::edges);
  EXPECT_EQ(advice.radius, 1.0);
  // One point: no spacing, no size.
  advice = advice_for("v 1 2 3\n", "one.obj");
  EXPECT_EQ(advice.basis, RadiusBasis::size);
  EXPECT_EQ(advice.radius, 1.0);
}

}  // namespace
}  // namespace convray::mesh
