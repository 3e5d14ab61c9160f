// Distances between soups, against values known without our code: closed-form point-triangle
// cases, a brute-force minimisation over each triangle, sheets a known distance apart,
// concentric icospheres (bounded by their radii and the faces' planes), and a brute-force
// O(n m) twin of the accelerated search.
#include "mesh/distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/procedural.hpp"

namespace convray::mesh {
namespace {

TEST(PointTriangleDistance, EachVoronoiRegion) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(point_triangle_distance({0.2, 0.2, 3}, a, b, c), 3.0);             // face
  EXPECT_DOUBLE_EQ(point_triangle_distance({0.2, 0.2, -3}, a, b, c), 3.0);            // face, below
  EXPECT_DOUBLE_EQ(point_triangle_distance({-1, -1, 0}, a, b, c), std::sqrt(2.0));    // vertex a
  EXPECT_DOUBLE_EQ(point_triangle_distance({2, 0, 1}, a, b, c), std::sqrt(2.0));      // vertex b
  EXPECT_DOUBLE_EQ(point_triangle_distance({-0.5, 3, 0}, a, b, c), std::sqrt(4.25));  // vertex c
  EXPECT_DOUBLE_EQ(point_triangle_distance({0.5, -2, 0}, a, b, c), 2.0);              // edge ab
  EXPECT_DOUBLE_EQ(point_triangle_distance({-3, 0.5, 4}, a, b, c), 5.0);              // edge ca
  EXPECT_NEAR(point_triangle_distance({1, 1, 0}, a, b, c), std::sqrt(0.5), 1e-15);    // edge bc
  EXPECT_EQ(point_triangle_distance({0.25, 0.25, 0}, a, b, c), 0.0);                  // on it
}

TEST(PointTriangleDistance, DegenerateTrianglesAreSegments) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
  EXPECT_DOUBLE_EQ(point_triangle_distance({3, 4, 0}, a, b, c), std::sqrt(17.0));
  EXPECT_DOUBLE_EQ(point_triangle_distance({1.5, 0, 2}, a, c, b), 2.0);
  EXPECT_DOUBLE_EQ(point_triangle_distance({1, 1, 1}, a, a, a), std::sqrt(3.0));
}

// The exact distance is at most the smallest over a fine barycentric grid of the triangle,
// and at least that minus the grid's spacing.
TEST(PointTriangleDistance, AgreesWithABruteForceMinimum) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
  const int n = 300;
  for (int trial = 0; trial < 100; ++trial) {
    Vec3 a = point(), b = point(), c = point(), p = 1.5 * point();
    double grid = INFINITY;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        grid = std::min(
            grid, glm::distance(p, a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n)));
      }
    }
    double spacing = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)}) / n;
    double exact = point_triangle_distance(p, a, b, c);
    EXPECT_LE(exact, grid + 1e-12) << "trial " << trial;
    EXPECT_GE(exact, grid - spacing) << "trial " << trial;
  }
}

TEST(SurfaceSamples, CoverTheAreaEvenly) {
  TriangleSoup triangle;
  triangle.vertices = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
  triangle.triangles = {{0, 1, 2}};
  SurfaceSamples samples = sample_surface(triangle, 9);
  ASSERT_EQ(samples.points.size(), 9u);  // three cuts per side, nine small triangles
  Vec3 mean(0.0);
  for (size_t s = 0; s < 9; ++s) {
    EXPECT_DOUBLE_EQ(samples.areas[s], 0.5);
    mean += samples.points[s] / 9.0;
  }
  EXPECT_NEAR(glm::distance(mean, Vec3(1, 1, 0)), 0.0, 1e-15);  // the centroid
  EXPECT_NE(
      std::find(samples.points.begin(), samples.points.end(), Vec3(1.0 / 3.0, 1.0 / 3.0, 0.0)),
      samples.points.end());  // the corner piece's centroid

  TriangleSoup sphere = icosphere(Vec3(0.0), 1.0, 3);
  SurfaceSamples many = sample_surface(sphere, 100000);
  double area = 0.0;
  for (double piece : many.areas) area += piece;
  double exact_area = 0.0;
  for (size_t t = 0; t < sphere.size(); ++t) {
    std::array<Vec3, 3> c = sphere.corners(t);
    exact_area += 0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0]));
  }
  EXPECT_NEAR(area, exact_area, 1e-10);
  EXPECT_GE(many.points.size(), 100000u);
  EXPECT_LE(many.points.size(), 200000u);
}

TriangleSoup shifted(TriangleSoup soup, const Vec3& by) {
  for (Vec3& p : soup.vertices) p += by;
  return soup;
}

TEST(HausdorffDistance, SheetAndTheSameSheetShifted) {
  const double d = 0.375;
  TriangleSoup sheet = flat_grid(1.0, 10);
  HausdorffDistance distance =
      hausdorff_distance(sheet, shifted(sheet, {0, 0, d}), {.samples = 5000});
  EXPECT_NEAR(distance.a_to_b.max, d, 1e-14);
  EXPECT_NEAR(distance.b_to_a.max, d, 1e-14);
  EXPECT_NEAR(distance.a_to_b.mean, d, 1e-14);
  EXPECT_NEAR(distance.symmetric(), d, 1e-14);
  EXPECT_NEAR(distance.mean(), d, 1e-14);
  EXPECT_EQ(distance.a_to_b.points, 121u + sample_surface(sheet, 5000).points.size());
}

TEST(HausdorffDistance, SmallSheetInsideALargeOneIsOneSided) {
  // Every point of the small sheet lies on the large one; the large one's corner (2, 2) is
  // sqrt 2 from the small one's (1, 1).
  HausdorffDistance distance =
      hausdorff_distance(flat_grid(1.0, 4), flat_grid(2.0, 4), {.samples = 1000});
  EXPECT_EQ(distance.a_to_b.max, 0.0);
  EXPECT_DOUBLE_EQ(distance.b_to_a.max, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(std::abs(distance.b_to_a.farthest.x), 2.0);
  EXPECT_DOUBLE_EQ(distance.symmetric(), std::sqrt(2.0));
}

// The smallest distance from the centre to the planes of the faces: the icosphere is
// convex, so it holds the ball of that radius and lies in the ball of its corners' radius.
double inscribed_radius(const TriangleSoup& sphere) {
  double r = INFINITY;
  for (size_t t = 0; t < sphere.size(); ++t) {
    std::array<Vec3, 3> c = sphere.corners(t);
    r = std::min(r, std::abs(glm::dot(c[0], glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0])))));
  }
  return r;
}

TEST(HausdorffDistance, ConcentricIcospheresAreTheirRadiiApart) {
  // Points of either surface lie between the inscribed and circumscribed radii of their own,
  // and the distance to the other surface is bounded by the other's radii in the same way:
  // every one-sided distance lies in [r_in(big) - R_small, R_big - r_in(small)].
  TriangleSoup small = icosphere(Vec3(0.0), 1.0, 3), big = icosphere(Vec3(0.0), 1.5, 3);
  const double lower = inscribed_radius(big) - 1.0, upper = 1.5 - inscribed_radius(small);
  ASSERT_LT(upper - lower, 0.02);  // the chord error of 3 subdivisions
  HausdorffDistance distance = hausdorff_distance(small, big, {.samples = 20000});
  for (const OneSidedDistance& side : {distance.a_to_b, distance.b_to_a}) {
    EXPECT_GE(side.max, lower);
    EXPECT_LE(side.max, upper);
    EXPECT_GE(side.mean, lower);
    EXPECT_LE(side.mean, side.max);
  }
}

TriangleSoup random_soup(std::mt19937& random, int triangles, double spread) {
  std::uniform_real_distribution<double> coordinate(-spread, spread), jitter(-0.3, 0.3);
  TriangleSoup soup;
  for (int t = 0; t < triangles; ++t) {
    Vec3 centre(coordinate(random), coordinate(random), coordinate(random));
    for (int corner = 0; corner < 3; ++corner) {
      soup.vertices.push_back(centre + Vec3(jitter(random), jitter(random), jitter(random)));
    }
    uint32_t first = static_cast<uint32_t>(3 * t);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  return soup;
}

// Every point against every triangle: what the tree must find, bit for bit.
OneSidedDistance brute_force(const TriangleSoup& from, const TriangleSoup& to, size_t count) {
  std::vector<Vec3> points = from.vertices;  // random_soup uses every vertex
  SurfaceSamples samples = sample_surface(from, count);
  points.insert(points.end(), samples.points.begin(), samples.points.end());
  OneSidedDistance result;
  double weighted = 0.0, area = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    double nearest = INFINITY;
    for (size_t t = 0; t < to.size(); ++t) {
      std::array<Vec3, 3> c = to.corners(t);
      nearest = std::min(nearest, point_triangle_distance(points[i], c[0], c[1], c[2]));
    }
    result.max = std::max(result.max, nearest);
    if (i >= from.vertices.size()) {
      weighted += samples.areas[i - from.vertices.size()] * nearest;
      area += samples.areas[i - from.vertices.size()];
    }
  }
  result.mean = weighted / area;
  result.points = points.size();
  return result;
}

TEST(HausdorffDistance, TreeFindsWhatBruteForceFinds) {
  std::mt19937 random(2024);
  for (int trial = 0; trial < 20; ++trial) {
    TriangleSoup a = random_soup(random, 20 + trial * 7, 1.0);
    TriangleSoup b = random_soup(random, 150 - trial * 5, 1.0 + 0.1 * trial);
    OneSidedDistance fast = one_sided_distance(a, b, {.samples = 3000});
    OneSidedDistance slow = brute_force(a, b, 3000);
    EXPECT_EQ(fast.max, slow.max) << "trial " << trial;
    EXPECT_NEAR(fast.mean, slow.mean, 1e-12 * slow.mean) << "trial " << trial;
    EXPECT_EQ(fast.points, slow.points) << "trial " << trial;
  }
}

TEST(HausdorffDistance, EmptySoupIsAnError) {
  EXPECT_THROW(one_sided_distance(TriangleSoup{}, flat_grid(1.0, 2)), std::invalid_argument);
  EXPECT_THROW(one_sided_distance(flat_grid(1.0, 2), TriangleSoup{}), std::invalid_argument);
}

}  // namespace
}  // namespace convray::mesh
