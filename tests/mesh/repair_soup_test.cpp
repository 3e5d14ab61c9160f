// repair_soup(): its statistics against counts derived from its construction (tiles of rings
// and spokes; a disk with three holes), each defect's effect on its own, the holes' radii,
// and the shipped scenes/models/repair_soup.obj. After changing the generator, regenerate
// the file with
//     CONVRAY_REGENERATE_MODELS=1 ./test_mesh
//     --gtest_filter='RepairSoup.ShippedFileMatchesItsGenerator'
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "fixtures/defective_soups.hpp"
#include "mesh/load.hpp"
#include "mesh/stats.hpp"
#include "mesh/write.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

const std::string kShipped = std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/repair_soup.obj";

RepairDefects no_defects() {
  RepairDefects defects;
  defects.flipped = defects.duplicated = defects.slivers = 0;
  defects.fin = false;
  return defects;
}

// What the construction gives without defects, for N spokes and K rings: three holed tiles of
// N (K + 1) vertices and 2 N K triangles, a solid one of 1 + N K vertices and N + 2 N (K - 1)
// triangles (a fan, then rings); the four inner sides of M + 1 points each are shared by two
// tiles, and the sheet's centre, on all four sides, by four.
struct Expected {
  size_t triangles, vertices, boundary_edges, edges;
};
Expected expected_clean(size_t n, size_t k) {
  size_t m = n / 4;
  Expected e{};
  e.triangles = 3 * 2 * n * k + n + 2 * n * (k - 1);
  e.vertices = 3 * n * (k + 1) + 1 + n * k - 4 * (m + 1) + 1;
  e.boundary_edges = 8 * m + 3 * n;  // the sheet's outline (8 tile sides) and three holes
  e.edges = (3 * e.triangles + e.boundary_edges) / 2;  // inner edges have two triangles
  return e;
}

TEST(RepairSoup, CleanSheetIsADiskWithThreeHoles) {
  for (int spokes : {16, 48}) {
    for (int rings : {4, 8}) {
      RepairDefects options = no_defects();
      options.spokes = spokes;
      options.rings = rings;
      MeshStats stats = compute_stats(repair_soup(options));
      Expected e = expected_clean(spokes, rings);
      EXPECT_EQ(stats.triangles, e.triangles);
      EXPECT_EQ(stats.vertices, e.vertices);
      EXPECT_EQ(stats.edges, e.edges);
      EXPECT_EQ(stats.boundary_edges, e.boundary_edges);
      EXPECT_EQ(stats.non_manifold_edges, 0u);
      EXPECT_EQ(stats.inconsistent_edges, 0u);
      EXPECT_EQ(stats.degenerate_triangles, 0u);
      EXPECT_EQ(stats.connected_components, 1u);
      EXPECT_EQ(stats.euler_characteristic(), 1 - 3);  // a disk has 1; each hole takes one
    }
  }
}

TEST(RepairSoup, IsFlatAndCounterClockwiseFromAbove) {
  TriangleSoup soup = repair_soup(no_defects());
  for (size_t t = 0; t < soup.size(); ++t) {
    std::array<Vec3, 3> c = soup.corners(t);
    ASSERT_EQ(c[0].z, 0.0);
    ASSERT_GT(glm::cross(c[1] - c[0], c[2] - c[0]).z, 0.0) << "triangle " << t;
  }
  Box3 bounds = soup.bounds();
  EXPECT_EQ(bounds.lo, Vec3(-2, -2, 0));
  EXPECT_EQ(bounds.hi, Vec3(2, 2, 0));
}

// The holes are regular polygons: corners at distance a from the hole's centre (the
// circumscribed radius), edges' midpoints at a cos(pi / N) (the inscribed one), and nothing
// of the sheet nearer.
TEST(RepairSoup, HolesAreRegularPolygonsOfTheGivenRadii) {
  RepairDefects options = no_defects();
  options.hole_radii = {0.2, 0.35, 0.5};
  TriangleSoup soup = repair_soup(options);
  const Vec3 centres[3] = {{-1, 1, 0}, {1, 1, 0}, {-1, -1, 0}};
  for (int h = 0; h < 3; ++h) {
    double a = options.hole_radii[h];
    double nearest_corner = INFINITY, nearest_midpoint = INFINITY;
    for (size_t t = 0; t < soup.size(); ++t) {
      std::array<Vec3, 3> c = soup.corners(t);
      for (int i = 0; i < 3; ++i) {
        nearest_corner = std::min(nearest_corner, glm::distance(c[i], centres[h]));
        nearest_midpoint =
            std::min(nearest_midpoint, glm::distance(0.5 * (c[i] + c[(i + 1) % 3]), centres[h]));
      }
    }
    EXPECT_NEAR(nearest_corner, a, 1e-12) << "hole " << h;
    EXPECT_NEAR(nearest_midpoint, a * std::cos(kPi / options.spokes), 1e-12) << "hole " << h;
  }
}

TEST(RepairSoup, DefectsOneAtATime) {
  const Expected clean = expected_clean(48, 8);
  for (int count : {1, 2, 3}) {
    RepairDefects flipped = no_defects();
    flipped.flipped = count;
    MeshStats with_flipped = compute_stats(repair_soup(flipped));
    EXPECT_EQ(with_flipped.inconsistent_edges, 3u * count);
    EXPECT_EQ(with_flipped.euler_characteristic(), -2);

    RepairDefects duplicated = no_defects();
    duplicated.duplicated = count;
    MeshStats with_copies = compute_stats(repair_soup(duplicated));
    EXPECT_EQ(with_copies.non_manifold_edges, 3u * count);
    EXPECT_EQ(with_copies.triangles, clean.triangles + count);
    EXPECT_EQ(with_copies.edges, clean.edges);  // a copy adds a face and nothing else
    EXPECT_EQ(with_copies.euler_characteristic(), -2 + count);

    RepairDefects slivers = no_defects();
    slivers.slivers = count;
    MeshStats with_slivers = compute_stats(repair_soup(slivers));
    EXPECT_EQ(with_slivers.triangles, clean.triangles + 2 * count);
    EXPECT_EQ(with_slivers.vertices, clean.vertices + count);
    EXPECT_EQ(with_slivers.boundary_edges, clean.boundary_edges);
    EXPECT_EQ(with_slivers.non_manifold_edges + with_slivers.inconsistent_edges, 0u);
    EXPECT_EQ(with_slivers.euler_characteristic(), -2);
  }
  RepairDefects fin = no_defects();
  fin.fin = true;
  MeshStats with_fin = compute_stats(repair_soup(fin));
  EXPECT_EQ(with_fin.non_manifold_edges, 1u);
  EXPECT_EQ(with_fin.boundary_edges, clean.boundary_edges + 2);
  EXPECT_EQ(with_fin.euler_characteristic(), -2);
  EXPECT_GT(with_fin.bounds.hi.z, 0.05);  // it stands up, as tall as its edge
}

// A sliver is needle-thin: its height over its base edge is 1e-3 of the split triangle's.
TEST(RepairSoup, SliversAreNeedles) {
  RepairDefects slivers = no_defects();
  slivers.slivers = 2;
  TriangleSoup soup = repair_soup(slivers);
  int needles = 0;
  for (size_t t = 0; t < soup.size(); ++t) {
    std::array<Vec3, 3> c = soup.corners(t);
    double longest =
        std::max({glm::distance(c[0], c[1]), glm::distance(c[1], c[2]), glm::distance(c[2], c[0])});
    double height = glm::length(glm::cross(c[1] - c[0], c[2] - c[0])) / longest;
    if (height < 0.01 * longest) ++needles;
  }
  EXPECT_EQ(needles, 2);
}

TEST(RepairSoup, AllDefectsTogetherAddUp) {
  const Expected clean = expected_clean(48, 8);
  MeshStats stats = compute_stats(repair_soup());
  EXPECT_EQ(stats.triangles, clean.triangles + 2 + 2 * 2 + 1);
  EXPECT_EQ(stats.boundary_edges, clean.boundary_edges + 2);
  EXPECT_EQ(stats.non_manifold_edges, 3u * 2 + 1);
  EXPECT_EQ(stats.inconsistent_edges, 3u * 2);
  EXPECT_EQ(stats.connected_components, 1u);
  EXPECT_EQ(stats.euler_characteristic(), -2 + 2);
}

TEST(RepairSoup, RejectsOptionsItCannotBuild) {
  RepairDefects odd;
  odd.spokes = 20;
  EXPECT_THROW(repair_soup(odd), std::invalid_argument);
  RepairDefects wide;
  wide.hole_radii[1] = 1.0;
  EXPECT_THROW(repair_soup(wide), std::invalid_argument);
  RepairDefects crowded;
  crowded.flipped = 5;
  EXPECT_THROW(repair_soup(crowded), std::invalid_argument);
}

TEST(RepairSoup, ShippedFileMatchesItsGenerator) {
  TriangleSoup generated = repair_soup();
  if (std::getenv("CONVRAY_REGENERATE_MODELS")) save_mesh(generated, kShipped);
  LoadedMesh shipped = load_mesh(kShipped);
  ASSERT_EQ(shipped.soup.vertices.size(), generated.vertices.size())
      << kShipped << " is out of date";
  for (size_t v = 0; v < generated.vertices.size(); ++v) {
    EXPECT_NEAR(glm::distance(shipped.soup.vertices[v], generated.vertices[v]), 0.0, 1e-12)
        << "vertex " << v;
  }
  EXPECT_EQ(shipped.soup.triangles, generated.triangles) << kShipped << " is out of date";
}

}  // namespace
}  // namespace convray::mesh
