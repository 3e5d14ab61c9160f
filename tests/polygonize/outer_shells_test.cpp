// --outer: which shells border the unbounded outside, on nested analytic shells whose
// answer is known, and the winding number against solid-angle values known in closed form.
#include "polygonize/outer_shells.hpp"

#include <gtest/gtest.h>

#include "analytic_fields.hpp"
#include "mesh/procedural.hpp"
#include "mesh_expectations.hpp"

namespace convray::polygonize {
namespace {

using testing::cube;
using testing::KernelSum;

std::vector<uint32_t> all_triangles(const mesh::TriangleSoup& soup) {
  std::vector<uint32_t> t(soup.triangles.size());
  for (size_t n = 0; n < t.size(); ++n) t[n] = uint32_t(n);
  return t;
}

TEST(WindingNumber, IsOneInsideAndZeroOutsideAClosedSphere) {
  const mesh::TriangleSoup sphere = mesh::icosphere(Vec3(0.0), 1.0, 2);
  const auto triangles = all_triangles(sphere);
  EXPECT_NEAR(winding_number(sphere, triangles, Vec3(0.0)), 1.0, 1e-12);
  EXPECT_NEAR(winding_number(sphere, triangles, Vec3(0.3, -0.2, 0.5)), 1.0, 1e-12);
  EXPECT_NEAR(winding_number(sphere, triangles, Vec3(1.5, 0.0, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(sphere, triangles, Vec3(0.0, 7.0, -3.0)), 0.0, 1e-12);
}

TEST(WindingNumber, OneFlatTriangleSeenFromAboveItsCornerSubtendsAnOctant) {
  // The triangle (1,0,0), (0,1,0), (0,0,1) from the origin... seen through the unit-cube
  // corner triangle: one eighth of the sphere.
  mesh::TriangleSoup soup;
  soup.vertices = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  soup.triangles = {{0, 1, 2}};
  // Counter-clockwise seen from outside (away from the origin): the origin sees its back.
  EXPECT_NEAR(winding_number(soup, {0}, Vec3(0.0)), 1.0 / 8.0, 1e-12);
}

TEST(OuterShells, KeepsTheOuterShellOfAThickenedSphere) {
  const testing::ToSphere shell(1.0);
  KernelSum sum{{{&shell, 1.0, 0.4, cube(Vec3(0.0), 1.4)}}};
  SurfaceMesh m = polygonize(sum.source(0.3), {.cell = 0.08});
  EXPECT_EQ(keep_outer_shells(m), 1u);
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 1u);
  const double outer = 1.0 + testing::level_distance(0.4, 0.3);
  for (const Vec3& p : m.soup.vertices) EXPECT_NEAR(glm::length(p), outer, 1e-6);
}

TEST(OuterShells, DropsAnIslandInsideAHollowAndKeepsSeparateOuterBodies) {
  // A hollow ball with a small ball inside it, and a second ball beside it.
  const testing::ToSphere hollow(1.0);
  const testing::ToPoint island(Vec3(0.1, 0.0, 0.0)), beside(Vec3(3.0, 0.0, 0.0));
  KernelSum sum{{{&hollow, 1.0, 0.4, cube(Vec3(0.0), 1.4)},
                 {&island, 1.0, 0.4, cube(island.center, 0.4)},
                 {&beside, 1.0, 0.6, cube(beside.center, 0.6)}}};
  SurfaceMesh m = polygonize(sum.source(0.3), {.cell = 0.06});
  EXPECT_EQ(mesh::compute_stats(m.soup).connected_components, 4u);
  EXPECT_EQ(keep_outer_shells(m), 2u);
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 2u);
  const double outer = 1.0 + testing::level_distance(0.4, 0.3);
  const double beside_radius = testing::level_distance(0.6, 0.3);
  for (const Vec3& p : m.soup.vertices) {
    const bool on_outer = std::abs(glm::length(p) - outer) < 1e-6;
    const bool on_beside = std::abs(glm::length(p - beside.center) - beside_radius) < 1e-6;
    EXPECT_TRUE(on_outer || on_beside) << p.x << " " << p.y << " " << p.z;
  }
}

}  // namespace
}  // namespace convray::polygonize
