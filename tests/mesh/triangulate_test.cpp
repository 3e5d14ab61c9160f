// Splitting polygons into triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/triangulate.hpp"

namespace convray::mesh {
namespace {

double area_along(const std::vector<Triangle>& triangles, const std::vector<Vec3>& p, const Vec3& normal) {
  double area = 0.0;
  for (auto [a, b, c] : triangles) area += 0.5 * glm::dot(glm::cross(p[b] - p[a], p[c] - p[a]), normal);
  return area;
}

TEST(Triangulate, TriangleStaysAsItIs) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Triangle> out;
  std::vector<uint32_t> corners = {2, 0, 1};
  triangulate_polygon(corners, p, out);
  EXPECT_EQ(out, (std::vector<Triangle>{{2, 0, 1}}));
}

TEST(Triangulate, ConcaveQuadUsesTheInsideDiagonal) {
  // A dart: corner 2 points inwards, so the diagonal 0-2 is the only one inside.
  std::vector<Vec3> p = {{0, 0, 0}, {2, 1, 0}, {0.5, 0.5, 0}, {1, 2, 0}};
  std::vector<uint32_t> corners = {0, 1, 2, 3};
  std::vector<Triangle> out;
  triangulate_polygon(corners, p, out);
  ASSERT_EQ(out.size(), 2u);
  for (auto [a, b, c] : out) EXPECT_GT(glm::cross(p[b] - p[a], p[c] - p[a]).z, 0.0);
}

TEST(Triangulate, WorksInAnyPlaneAndOrientation) {
  // A concave star in a tilted plane, listed clockwise as seen from +z.
  std::vector<Vec3> p;
  const Vec3 u = glm::normalize(Vec3(1, 0, 1)), v(0, -1, 0);
  for (int k = 0; k < 10; ++k) {
    double radius = k % 2 ? 0.4 : 1.0, angle = 2.0 * kPi * k / 10;
    p.push_back(radius * (std::cos(angle) * u + std::sin(angle) * v));
  }
  std::vector<uint32_t> corners = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  std::vector<Triangle> out;
  triangulate_polygon(corners, p, out);
  ASSERT_EQ(out.size(), 8u);
  Vec3 normal = glm::cross(u, v);
  // Every triangle keeps the polygon's orientation, so the areas add up to the star's.
  double star_area = 10 * 0.5 * 1.0 * 0.4 * std::sin(2.0 * kPi / 10);
  for (const Triangle& t : out) EXPECT_GT(area_along({t}, p, normal), 0.0);
  EXPECT_NEAR(area_along(out, p, normal), star_area, 1e-12);
}

TEST(Triangulate, DegeneratePolygonFallsBackToAFan) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  std::vector<uint32_t> corners = {0, 1, 2, 3};
  std::vector<Triangle> out;
  triangulate_polygon(corners, p, out);
  EXPECT_EQ(out, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
}

}  // namespace
}  // namespace convray::mesh
