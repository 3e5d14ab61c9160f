// Statistics checked against what is known exactly about the procedural meshes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "fixtures/defective_soups.hpp"
#include "mesh/load.hpp"
#include "mesh/procedural.hpp"
#include "mesh/stats.hpp"
#include "mesh/write.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

TriangleSoup concatenated(const TriangleSoup& a, const TriangleSoup& b) {
  TriangleSoup soup = a;
  uint32_t offset = static_cast<uint32_t>(a.vertices.size());
  soup.vertices.insert(soup.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return soup;
}

void expect_closed_and_consistent(const MeshStats& stats) {
  EXPECT_EQ(stats.boundary_edges, 0u);
  EXPECT_EQ(stats.non_manifold_edges, 0u);
  EXPECT_EQ(stats.inconsistent_edges, 0u);
  EXPECT_EQ(stats.degenerate_triangles, 0u);
}

class IcosphereStats : public ::testing::TestWithParam<int> {};

TEST_P(IcosphereStats, IsAClosedSphere) {
  int s = GetParam();
  size_t four_to_s = size_t{1} << (2 * s);
  MeshStats stats = compute_stats(icosphere(Vec3(1, -2, 3), 2.5, s));
  EXPECT_EQ(stats.triangles, 20 * four_to_s);
  EXPECT_EQ(stats.vertices, 10 * four_to_s + 2);
  EXPECT_EQ(stats.edges, 30 * four_to_s);
  EXPECT_EQ(stats.euler_characteristic(), 2);
  EXPECT_EQ(stats.connected_components, 1u);
  expect_closed_and_consistent(stats);
  if (s >= 1) {  // from the first subdivision on, there are vertices on the axes
    EXPECT_NEAR(stats.bounds.lo.x, 1 - 2.5, 1e-12);
    EXPECT_NEAR(stats.bounds.hi.z, 3 + 2.5, 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Subdivisions, IcosphereStats, ::testing::Values(0, 1, 2, 3));

TEST(Stats, IcosahedronEdgeLength) {
  // The edge of an icosahedron inscribed in a unit sphere is 4 / sqrt(10 + 2 sqrt 5).
  MeshStats stats = compute_stats(icosphere(Vec3(0.0), 1.0, 0));
  EXPECT_NEAR(stats.mean_edge_length, 4.0 / std::sqrt(10.0 + 2.0 * std::sqrt(5.0)), 1e-12);
}

TEST(Stats, TorusHasEulerCharacteristicZero) {
  MeshStats stats = compute_stats(torus(3.0, 1.0, 32, 16));
  EXPECT_EQ(stats.triangles, 2u * 32 * 16);
  EXPECT_EQ(stats.vertices, 32u * 16);
  EXPECT_EQ(stats.euler_characteristic(), 0);
  EXPECT_EQ(stats.connected_components, 1u);
  expect_closed_and_consistent(stats);
}

TEST(Stats, FlatGrid) {
  // 4 x 4 unit squares: 40 sides of length 1, 16 diagonals of length sqrt 2.
  MeshStats stats = compute_stats(flat_grid(2.0, 4));
  EXPECT_EQ(stats.triangles, 32u);
  EXPECT_EQ(stats.vertices, 25u);
  EXPECT_EQ(stats.edges, 56u);
  EXPECT_EQ(stats.boundary_edges, 16u);
  EXPECT_EQ(stats.euler_characteristic(), 1);
  EXPECT_NEAR(stats.mean_edge_length, (40.0 + 16.0 * std::sqrt(2.0)) / 56.0, 1e-12);
}

TEST(Stats, SheetWithAHole) {
  // 10 x 10 unit squares; radius 1 takes out exactly the four around the centre, whose
  // outline is 8 unit edges. Outer boundary 4 * 10. An annulus: Euler characteristic 0.
  MeshStats stats = compute_stats(sheet_with_hole(5.0, 10, 1.0));
  EXPECT_EQ(stats.triangles, 2u * (100 - 4));
  EXPECT_EQ(stats.boundary_edges, 40u + 8u);
  EXPECT_EQ(stats.non_manifold_edges, 0u);
  EXPECT_EQ(stats.connected_components, 1u);
  EXPECT_EQ(stats.euler_characteristic(), 0);
}

TEST(Stats, TwoSeparateSpheresAreTwoComponents) {
  TriangleSoup pair = concatenated(icosphere(Vec3(-3, 0, 0), 1.0, 1), icosphere(Vec3(3, 0, 0), 1.0, 1));
  MeshStats stats = compute_stats(pair);
  EXPECT_EQ(stats.connected_components, 2u);
  EXPECT_EQ(stats.euler_characteristic(), 4);
}

TEST(Stats, TouchingSpheresAreOneComponent) {
  // Components join through shared positions, not shared indices: b is a moved so that
  // its vertex 3 (opposite vertex 0) lands exactly on a's vertex 0.
  TriangleSoup a = icosphere(Vec3(0.0), 1.0, 0);
  TriangleSoup b = a;
  Vec3 shift = 2.0 * a.vertices[0];  // b's opposite vertex (index 3) lands on a's vertex 0
  for (Vec3& p : b.vertices) p += shift;
  ASSERT_EQ(b.vertices[3], a.vertices[0]);
  EXPECT_EQ(compute_stats(concatenated(a, b)).connected_components, 1u);
}

TEST(Stats, WeldsTheRepeatedCornersOfStl) {
  testing::ScratchDirectory scratch;
  TriangleSoup sphere = testing::on_float_grid(icosphere(Vec3(0.0), 8.0, 2));
  save_mesh(sphere, scratch.file("sphere.stl"));
  LoadedMesh loaded = load_mesh(scratch.file("sphere.stl"));
  EXPECT_EQ(loaded.soup.vertices.size(), 3u * 320);  // STL repeats every corner
  MeshStats stats = compute_stats(loaded.soup);
  EXPECT_EQ(stats.vertices, 162u);
  EXPECT_EQ(stats.euler_characteristic(), 2);
  expect_closed_and_consistent(stats);
}

TEST(Stats, DefectsOneAtATime) {
  SoupDefects none{.hole = false, .flipped = false, .duplicated = false, .sliver = false, .fin = false};
  MeshStats clean = compute_stats(defective_soup(none));
  expect_closed_and_consistent(clean);

  SoupDefects hole = none;
  hole.hole = true;
  MeshStats with_hole = compute_stats(defective_soup(hole));
  EXPECT_EQ(with_hole.boundary_edges, 5u);
  EXPECT_EQ(with_hole.euler_characteristic(), 1);  // a disk

  SoupDefects flipped = none;
  flipped.flipped = true;
  EXPECT_EQ(compute_stats(defective_soup(flipped)).inconsistent_edges, 3u);

  SoupDefects duplicated = none;
  duplicated.duplicated = true;
  EXPECT_EQ(compute_stats(defective_soup(duplicated)).non_manifold_edges, 3u);

  SoupDefects fin = none;
  fin.fin = true;
  MeshStats with_fin = compute_stats(defective_soup(fin));
  EXPECT_EQ(with_fin.non_manifold_edges, 1u);
  EXPECT_EQ(with_fin.boundary_edges, 2u);

  SoupDefects sliver = none;
  sliver.sliver = true;
  MeshStats with_sliver = compute_stats(defective_soup(sliver));
  EXPECT_EQ(with_sliver.triangles, clean.triangles + 2);
  expect_closed_and_consistent(with_sliver);
  EXPECT_EQ(with_sliver.euler_characteristic(), 2);
}

TEST(Stats, AllDefectsTogetherAddUp) {
  MeshStats stats = compute_stats(defective_soup());
  EXPECT_EQ(stats.triangles, 320u - 5 + 2 + 1 + 1);
  EXPECT_EQ(stats.boundary_edges, 5u + 2);
  EXPECT_EQ(stats.non_manifold_edges, 3u + 1);
  EXPECT_EQ(stats.inconsistent_edges, 3u);
  EXPECT_EQ(stats.connected_components, 1u);
}

TEST(Stats, FastOnAMillionTriangles) {
  TriangleSoup grid = flat_grid(1.0, 710);  // 1,008,200 triangles
  auto start = std::chrono::steady_clock::now();
  MeshStats stats = compute_stats(grid);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(stats.triangles, 1008200u);
  EXPECT_EQ(stats.boundary_edges, 4u * 710);
  EXPECT_EQ(stats.connected_components, 1u);
  EXPECT_LT(seconds, 10.0) << "quadratic somewhere?";  // about 0.5 s in a release build
  RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace
}  // namespace convray::mesh
