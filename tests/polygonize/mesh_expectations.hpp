#pragma once
// What every polygonized mesh must be, checked the same way in every test: closed,
// 2-manifold, consistently oriented, free of self-intersections, normals facing the way the
// triangles do.
#include <gtest/gtest.h>

#include "mesh/self_intersections.hpp"
#include "mesh/stats.hpp"
#include "polygonize/polygonize.hpp"
#include "reference/mesh_checks.hpp"

namespace convray::polygonize::testing {

inline reference::IndexedMesh indexed(const mesh::TriangleSoup& soup) {
  reference::IndexedMesh m;
  m.vertices = soup.vertices;
  for (const mesh::Triangle& t : soup.triangles) m.triangles.push_back({t[0], t[1], t[2]});
  return m;
}

// Checks the topology and returns the statistics for further checks. Self-intersections are
// decided exactly (mesh/self_intersections.hpp, itself checked against an integer separating
// axis test and a search of every pair): touching counts, a gap of one ulp does not.
inline mesh::MeshStats expect_closed_manifold(const SurfaceMesh& m) {
  const mesh::MeshStats stats = mesh::compute_stats(m.soup);
  EXPECT_GT(stats.triangles, 0u);
  EXPECT_EQ(stats.boundary_edges, 0u);
  EXPECT_EQ(stats.non_manifold_edges, 0u);
  EXPECT_EQ(stats.inconsistent_edges, 0u);
  EXPECT_EQ(stats.degenerate_triangles, 0u);
  // Each closed orientable component has V - E + F = 2 - 2 genus.
  EXPECT_EQ(stats.euler_characteristic() % 2, 0);
  EXPECT_LE(stats.euler_characteristic(), 2 * long(stats.connected_components));
  EXPECT_EQ(m.normals.size(), m.soup.vertices.size());
  // Vertex normals (from the gradient) and the triangles' winding agree: outward.
  size_t agreeing = 0;
  for (size_t t = 0; t < m.soup.triangles.size(); ++t) {
    const auto [a, b, c] = m.soup.corners(t);
    const Vec3 face = glm::cross(b - a, c - a);
    const mesh::Triangle& tri = m.soup.triangles[t];
    const Vec3 n = m.normals[tri[0]] + m.normals[tri[1]] + m.normals[tri[2]];
    agreeing += glm::dot(face, n) > 0.0;
  }
  EXPECT_GE(double(agreeing), 0.995 * double(m.soup.triangles.size()));
  const mesh::SelfIntersections crossings = mesh::find_self_intersections(m.soup);
  EXPECT_EQ(crossings.pairs, 0u);
  EXPECT_EQ(crossings.flat_faces, 0u);
  return stats;
}

}  // namespace convray::polygonize::testing
