// The grid search for intersecting faces against testing every pair (its slow twin), and
// against what is known of closed and interpenetrating procedural meshes.
#include "mesh/self_intersections.hpp"

#include <gtest/gtest.h>

#include <random>

#include "mesh/procedural.hpp"

namespace convray::mesh {
namespace {

TriangleSoup concatenated(TriangleSoup a, const TriangleSoup& b) {
  const uint32_t offset = uint32_t(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles)
    a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

// Faces with corners on a small lattice (many touching, coplanar and shared-corner pairs), or
// small faces with arbitrary double corners scattered in a box.
TriangleSoup random_soup(unsigned seed, size_t faces, bool lattice) {
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> cell(0, 6);
  std::uniform_real_distribution<double> where(0.0, 10.0), offset(-0.6, 0.6);
  TriangleSoup soup;
  for (size_t f = 0; f < faces; ++f) {
    const Vec3 base = lattice ? Vec3(cell(random), cell(random), cell(random))
                              : Vec3(where(random), where(random), where(random));
    for (int k = 0; k < 3; ++k) {
      const Vec3 corner = lattice ? Vec3(cell(random), cell(random), cell(random)) * 0.5
                                  : base + Vec3(offset(random), offset(random), offset(random));
      soup.vertices.push_back(corner);
    }
    const uint32_t first = uint32_t(3 * f);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  return soup;
}

void expect_same(const SelfIntersections& fast, const SelfIntersections& slow) {
  EXPECT_EQ(fast.pairs, slow.pairs);
  EXPECT_EQ(fast.flat_faces, slow.flat_faces);
  EXPECT_EQ(fast.examples, slow.examples);
}

TEST(SelfIntersections, GridSearchFindsWhatEveryPairFindsOnLatticeSoups) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const TriangleSoup soup = random_soup(seed, 400, true);
    const SelfIntersections slow = find_self_intersections_brute_force(soup, 20);
    EXPECT_GT(slow.pairs, 1000u);
    EXPECT_GT(slow.flat_faces, 0u);
    expect_same(find_self_intersections(soup, 20), slow);
  }
}

TEST(SelfIntersections, GridSearchFindsWhatEveryPairFindsOnScatteredSoups) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const TriangleSoup soup = random_soup(seed, 3000, false);
    const SelfIntersections slow = find_self_intersections_brute_force(soup, 20);
    EXPECT_GT(slow.pairs, 10u);
    expect_same(find_self_intersections(soup, 20), slow);
  }
}

// One face spanning the whole soup makes the grid coarsen; nothing may be lost.
TEST(SelfIntersections, OneHugeFaceAmongSmallOnes) {
  TriangleSoup soup = random_soup(4, 3000, false);
  const uint32_t first = uint32_t(soup.vertices.size());
  soup.vertices.insert(soup.vertices.end(), {Vec3(-1, -1, 5), Vec3(30, -1, 5), Vec3(-1, 30, 5.2)});
  soup.triangles.push_back({first, first + 1, first + 2});
  const SelfIntersections slow = find_self_intersections_brute_force(soup, 50);
  expect_same(find_self_intersections(soup, 50), slow);
}

TEST(SelfIntersections, ClosedMeshesHaveNone) {
  EXPECT_EQ(find_self_intersections(icosphere(Vec3(0), 1.0, 4)).pairs, 0u);
  EXPECT_EQ(find_self_intersections(torus(2.0, 0.5, 48, 24)).pairs, 0u);
  // A sphere inside another, apart.
  const TriangleSoup nested =
      concatenated(icosphere(Vec3(0), 1.0, 3), icosphere(Vec3(0.1, 0, 0), 0.5, 3));
  EXPECT_EQ(find_self_intersections(nested).pairs, 0u);
  EXPECT_EQ(find_self_intersections(nested).flat_faces, 0u);
}

// Two unit spheres whose centres are 1 apart cross along a circle of radius sqrt(3)/2; every
// crossing pair has one face of each sphere, and there are at least as many as the faces the
// circle passes through on either sphere.
TEST(SelfIntersections, InterpenetratingSpheresCrossAlongTheirCommonCircle) {
  const TriangleSoup a = icosphere(Vec3(0), 1.0, 3), b = icosphere(Vec3(1, 0, 0), 1.0, 3);
  const TriangleSoup both = concatenated(a, b);
  const SelfIntersections found = find_self_intersections(both, 1000000);
  const size_t a_faces = a.size();
  size_t circle_faces_of_a = 0;
  std::vector<bool> seen(a_faces, false);
  for (const auto& pair : found.examples) {
    EXPECT_LT(pair[0], a_faces);
    EXPECT_GE(pair[1], a_faces);
    if (!seen[pair[0]]) seen[pair[0]] = true, ++circle_faces_of_a;
  }
  EXPECT_EQ(found.examples.size(), found.pairs);
  // The circle is 2 pi sqrt(3)/2 = 5.4 long; faces of a subdivision-3 unit icosphere are
  // about 0.15 across, so it passes through at least 5.4 / 0.2 of them.
  EXPECT_GT(circle_faces_of_a, 27u);
  expect_same(found, find_self_intersections_brute_force(both, 1000000));
}

}  // namespace
}  // namespace convray::mesh
