// The polygonizer on fields whose surfaces are known exactly (analytic_fields.hpp): spheres,
// a torus, separate and nested shells, and random sums of kernels that exercise every case
// of the tetrahedra.
#include "polygonize/polygonize.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

#include "analytic_fields.hpp"
#include "mesh_expectations.hpp"

namespace convray::polygonize {
namespace {

using testing::cube;
using testing::KernelSum;

TEST(Polygonize, SphereIsClosedWithEveryVertexOnTheExactSurface) {
  const testing::ToPoint center(Vec3(0.1, -0.2, 0.3));
  KernelSum sum{{{&center, 1.0, 1.0, cube(center.center, 1.0)}}};
  const double threshold = 0.3;
  const FieldSource source = sum.source(threshold);
  PolygonizeStats stats;
  const SurfaceMesh m = polygonize(source, {.cell = 0.07}, &stats);
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 1u);
  EXPECT_EQ(topology.euler_characteristic(), 2);
  const double r0 = testing::level_distance(1.0, threshold);
  for (size_t v = 0; v < m.soup.vertices.size(); ++v) {
    const Vec3 d = m.soup.vertices[v] - center.center;
    // |F - T| <= 1e-6 T, and F's slope at the surface turns that into a tiny distance.
    EXPECT_NEAR(glm::length(d), r0, 1e-6) << v;
    EXPECT_NEAR(glm::dot(m.normals[v], glm::normalize(d)), 1.0, 1e-9) << v;
    EXPECT_LE(std::abs(source.field(m.soup.vertices[v]).value - threshold), 1e-6 * threshold);
  }
  EXPECT_LE(stats.max_residual, 1e-6);
  EXPECT_EQ(stats.unconverged, 0u);
  // The enclosed volume approaches the ball's from below (every vertex on the sphere).
  const double ball = 4.0 / 3.0 * kPi * r0 * r0 * r0;
  const double volume = reference::enclosed_volume(testing::indexed(m.soup));
  EXPECT_LT(volume, ball);
  EXPECT_GT(volume, 0.97 * ball);
}

TEST(Polygonize, TorusHasEulerCharacteristicZero) {
  const testing::ToCircle circle(1.0);
  KernelSum sum{{{&circle, 1.0, 0.5, Box3{Vec3(-1.5, -1.5, -0.5), Vec3(1.5, 1.5, 0.5)}}}};
  const SurfaceMesh m = polygonize(sum.source(0.25), {.cell = 0.06});
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 1u);
  EXPECT_EQ(topology.euler_characteristic(), 0);
  const double tube = testing::level_distance(0.5, 0.25);
  for (const Vec3& p : m.soup.vertices) {
    EXPECT_NEAR(std::hypot(std::hypot(p.x, p.y) - 1.0, p.z), tube, 1e-6);
  }
}

TEST(Polygonize, SeparateSpheresAreSeparateComponents) {
  const testing::ToPoint a(Vec3(0.0)), b(Vec3(3.0, 0.0, 0.0));
  KernelSum sum{{{&a, 1.0, 1.0, cube(a.center, 1.0)}, {&b, 1.0, 1.0, cube(b.center, 1.0)}}};
  const mesh::MeshStats topology =
      testing::expect_closed_manifold(polygonize(sum.source(0.4), {.cell = 0.1}));
  EXPECT_EQ(topology.connected_components, 2u);
  EXPECT_EQ(topology.euler_characteristic(), 4);
}

TEST(Polygonize, ThickenedSphereGivesAnOuterAndAnInnerShell) {
  const testing::ToSphere shell(1.0);
  KernelSum sum{{{&shell, 1.0, 0.4, cube(Vec3(0.0), 1.4)}}};
  const SurfaceMesh m = polygonize(sum.source(0.3), {.cell = 0.08});
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 2u);
  EXPECT_EQ(topology.euler_characteristic(), 4);
  // Outer shell outward, inner shell facing the hollow: the volumes subtract.
  const double d = testing::level_distance(0.4, 0.3);
  const double solid = 4.0 / 3.0 * kPi * (std::pow(1.0 + d, 3) - std::pow(1.0 - d, 3));
  EXPECT_NEAR(reference::enclosed_volume(testing::indexed(m.soup)), solid, 0.05 * solid);
}

TEST(Polygonize, LatticeValuesExactlyAtTheThresholdCountAsInside) {
  // T = 1 at a point kernel's centre only: the lattice point there is F = T exactly. Shifted
  // so that the centre is a lattice point, the surface shrinks to nothing or to a tiny closed
  // surface, never to an open one.
  const testing::ToPoint center(Vec3(0.0));
  KernelSum sum{{{&center, 1.0, 1.0, cube(Vec3(0.0), 1.0)}}};
  const SurfaceMesh m = polygonize(sum.source(1.0), {.cell = 0.125});
  if (!m.soup.triangles.empty()) testing::expect_closed_manifold(m);
  for (const Vec3& p : m.soup.vertices) EXPECT_GT(glm::length(p), 0.0);
}

// Random sums of kernels, positive and negative, with radii near the cell: saddles, thin
// necks and tiny islands everywhere, so every assignment of inside corners occurs.
TEST(Polygonize, RandomKernelSumsGiveClosedManifoldMeshes) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<testing::ToPoint> points;
    const int count = 5 + int(unit(random) * 40);
    for (int n = 0; n < count; ++n) {
      points.emplace_back(Vec3(unit(random), unit(random), unit(random)) * 2.0 - 1.0);
    }
    const double cell = 0.04 + 0.08 * unit(random);
    KernelSum sum;
    for (const testing::ToPoint& p : points) {
      const double radius = cell * (0.8 + 6.0 * unit(random));
      const double strength = unit(random) < 0.2 ? -0.5 : 0.5 + unit(random);
      sum.terms.push_back({&p, strength, radius, cube(p.center, radius)});
    }
    const double threshold = 0.1 + 0.5 * unit(random);
    const FieldSource source = sum.source(threshold);
    PolygonizeStats stats;
    const SurfaceMesh m = polygonize(source, {.cell = cell}, &stats);
    SCOPED_TRACE("trial " + std::to_string(trial));
    if (m.soup.triangles.empty()) continue;
    testing::expect_closed_manifold(m);
    EXPECT_LE(stats.max_residual, 1e-6);
    for (const Vec3& p : m.soup.vertices) {
      EXPECT_LE(std::abs(source.field(p).value - threshold), 1e-6 * threshold);
    }
  }
}

TEST(Polygonize, OutputDoesNotDependOnTheNumberOfThreads) {
  const testing::ToPoint a(Vec3(0.0)), b(Vec3(0.9, 0.2, 0.0));
  KernelSum sum{{{&a, 1.0, 1.0, cube(a.center, 1.0)}, {&b, 1.0, 0.8, cube(b.center, 0.8)}}};
  const FieldSource source = sum.source(0.35);
  SurfaceMesh one, many;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = polygonize(source, {.cell = 0.05});
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 8);
    many = polygonize(source, {.cell = 0.05});
  }
  ASSERT_EQ(one.soup.vertices.size(), many.soup.vertices.size());
  EXPECT_TRUE(one.soup.vertices == many.soup.vertices);
  EXPECT_TRUE(one.soup.triangles == many.soup.triangles);
}

TEST(Polygonize, RejectsANonPositiveThresholdAndCell) {
  const testing::ToPoint a(Vec3(0.0));
  KernelSum sum{{{&a, 1.0, 1.0, cube(a.center, 1.0)}}};
  EXPECT_THROW(polygonize(sum.source(0.0), {.cell = 0.1}), std::invalid_argument);
  EXPECT_THROW(polygonize(sum.source(0.5), {.cell = 0.0}), std::invalid_argument);
  EXPECT_THROW(polygonize(sum.source(0.5), {.cell = 1e-9}), std::invalid_argument);
}

TEST(Polygonize, EmptyFieldGivesAnEmptyMesh) {
  const testing::ToPoint a(Vec3(0.0));
  KernelSum sum{{{&a, 1.0, 1.0, cube(a.center, 1.0)}}};
  EXPECT_TRUE(polygonize(sum.source(2.0), {.cell = 0.1}).soup.triangles.empty());
}

}  // namespace
}  // namespace convray::polygonize
