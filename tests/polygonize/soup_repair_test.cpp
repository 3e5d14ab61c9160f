// Polygon soups with defects through the real convolution field (implicit::MeshField): the
// output is closed and 2-manifold whatever the input, and a round hole of radius a in a flat
// sheet closes exactly when a <= offset (the field at the hole's centre equals the plane's
// field at distance a). The sheet's outcome is read off the topology: a thickened sheet with
// an open hole is a torus (Euler characteristic 0), with the hole closed a sphere (2).
#include <gtest/gtest.h>

#include "fixtures/defective_soups.hpp"
#include "implicit/mesh_field.hpp"
#include "field/threshold.hpp"
#include "mesh/procedural.hpp"
#include "mesh_expectations.hpp"
#include "polygonize/outer_shells.hpp"
#include "polygonize/surface_error.hpp"

namespace convray::polygonize {
namespace {

struct SoupField {
  implicit::MeshField field;
  FieldSource source;
};

std::unique_ptr<SoupField> soup_field(const mesh::TriangleSoup& soup, double radius,
                                      double offset) {
  std::vector<field::Triangle> triangles;
  for (size_t t = 0; t < soup.size(); ++t) {
    const auto [a, b, c] = soup.corners(t);
    triangles.push_back({a, b, c});
  }
  auto f = std::make_unique<SoupField>(SoupField{implicit::MeshField(triangles, radius), {}});
  f->source.supports = triangle_support_boxes(f->field.triangles(), radius);
  f->source.threshold = field::threshold_for_offset(1.0, radius, offset);
  const implicit::MeshField* mesh_field = &f->field;
  f->source.field = [mesh_field](const Vec3& p) { return mesh_field->field(p); };
  return f;
}

// The sheet's squares are 0.1 wide, so the hole's jagged rim lies within 0.071 of its radius.
TEST(SoupRepair, RoundHoleClosesWhenTheOffsetExceedsItsRadius) {
  const mesh::TriangleSoup sheet = mesh::sheet_with_hole(1.0, 20, 0.2);
  const auto f = soup_field(sheet, 0.6, 0.35);
  const SurfaceMesh m = polygonize(f->source, {.cell = 0.06});
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 1u);
  EXPECT_EQ(topology.euler_characteristic(), 2);
}

TEST(SoupRepair, RoundHoleStaysOpenWhenTheOffsetIsBelowItsRadius) {
  const mesh::TriangleSoup sheet = mesh::sheet_with_hole(1.0, 20, 0.45);
  const auto f = soup_field(sheet, 0.6, 0.2);
  const SurfaceMesh m = polygonize(f->source, {.cell = 0.06});
  const mesh::MeshStats topology = testing::expect_closed_manifold(m);
  EXPECT_EQ(topology.connected_components, 1u);
  EXPECT_EQ(topology.euler_characteristic(), 0);
}

// The library evaluation's sheet (bench/polygonizer_libraries.cpp --procedural sheet): flat,
// axis-aligned, so the surface runs parallel to lattice planes and makes slivers near lattice
// points, where a triangle test with a tolerance once flagged five pairs. Decided exactly,
// there are none.
TEST(SoupRepair, AxisAlignedSheetAtTheEvaluationsResolutionHasNoSelfIntersections) {
  mesh::TriangleSoup sheet = mesh::sheet_with_hole(1.0, 8, 0.4);
  mesh::fit_into_box(sheet, 40.0);
  const auto f = soup_field(sheet, 2.0, 1.0);
  const SurfaceMesh m = polygonize(f->source, {.cell = 0.5});
  EXPECT_GT(m.soup.size(), 50000u);
  testing::expect_closed_manifold(m);
}

TEST(SoupRepair, DefectiveSoupBecomesClosedAndItsOuterShellIsKept) {
  // Hole, flipped and duplicated triangles, a sliver and a fin (fixtures/defective_soups.hpp).
  // The hole (five triangles around a vertex, about 0.3 across) closes at offset 0.35 with R = 0.6:
  // an outer and an inner shell; --outer keeps one.
  const auto f = soup_field(mesh::defective_soup(), 0.6, 0.35);
  SurfaceMesh m = polygonize(f->source, {.cell = 0.05});
  const mesh::MeshStats both = testing::expect_closed_manifold(m);
  EXPECT_EQ(both.connected_components, 2u);
  EXPECT_EQ(both.euler_characteristic(), 4);
  EXPECT_EQ(keep_outer_shells(m), 1u);
  const mesh::MeshStats outer = testing::expect_closed_manifold(m);
  EXPECT_EQ(outer.connected_components, 1u);
  EXPECT_EQ(outer.euler_characteristic(), 2);
  for (const Vec3& p : m.soup.vertices) EXPECT_GT(glm::length(p), 1.0);  // outside the sphere
}

TEST(SoupRepair, VerticesLieOnTheExactFieldOfTheSlowTwin) {
  // MeshField's SIMD fast path finds the vertices; its scalar closed-form twin checks them.
  const auto f = soup_field(mesh::defective_soup(), 0.3, 0.1);
  const SurfaceMesh m = polygonize(f->source, {.cell = 0.04});
  testing::expect_closed_manifold(m);
  const double threshold = f->source.threshold;
  for (size_t v = 0; v < m.soup.vertices.size(); ++v) {
    const field::FieldSample exact = f->field.field_exact(m.soup.vertices[v]);
    EXPECT_LE(std::abs(exact.value - threshold), 1e-6 * threshold) << v;
    EXPECT_NEAR(glm::dot(m.normals[v], -glm::normalize(exact.gradient)), 1.0, 1e-9) << v;
  }
}

TEST(SoupRepair, MaxErrorBoundIsMetOnTheCentroids) {
  const auto f = soup_field(mesh::defective_soup(), 0.3, 0.1);
  const ErrorBoundedResult r = polygonize_to_error(f->source, 0.004, 0.15, {});
  EXPECT_LE(r.error, 0.004);
  EXPECT_GT(r.passes, 1);
  testing::expect_closed_manifold(r.mesh);
  // Independent of the estimate: each centroid's exact field is within what a surface at
  // distance <= 0.004 allows, by the gradient bound |grad F| <= max over the vertices x 2.
  double steepest = 0.0;
  for (const Vec3& p : r.mesh.soup.vertices) {
    steepest = std::max(steepest, glm::length(f->field.field_exact(p).gradient));
  }
  for (size_t t = 0; t < r.mesh.soup.size(); ++t) {
    const auto [a, b, c] = r.mesh.soup.corners(t);
    const double excess =
        std::abs(f->field.field_exact((a + b + c) / 3.0).value - f->source.threshold);
    EXPECT_LE(excess, 2.0 * steepest * 0.004) << t;
  }
}

}  // namespace
}  // namespace convray::polygonize
