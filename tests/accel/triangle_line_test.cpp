// A triangle's terms along a line (accel/triangle_line.hpp): the span batch's rows against
// their scalar twins to the bit, and the twins against the geometry they stand for, measured
// independently (the plane's and the edges' distances of points of the line, the corners'
// distances to it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "accel/triangle_line.hpp"
#include "accel/triangle_span_batch.hpp"
#include "field/triangle_frame.hpp"
#include "reference/random_vectors.hpp"

namespace convray::accel {
namespace {

using testing::random_point;
using testing::random_unit;

std::vector<field::Triangle> random_triangles(std::mt19937_64& rng, int count) {
  std::vector<field::Triangle> triangles;
  for (int k = 0; k < count; ++k) {
    triangles.push_back({random_point(rng, 1.0), random_point(rng, 1.0), random_point(rng, 1.0)});
  }
  // The lanes' degenerate cases: no area (a repeated corner, collinear corners), a line in
  // the plane of the first triangle and along an edge of the second.
  triangles.push_back({Vec3(0.1, 0.2, 0.3), Vec3(0.1, 0.2, 0.3), Vec3(0.5, -0.2, 0.1)});
  triangles.push_back({Vec3(0.0), Vec3(0.5, 0.5, 0.5), Vec3(1.0, 1.0, 1.0)});
  return triangles;
}

void expect_same_bits(double batch, double scalar, const std::string& what) {
  if (std::isnan(scalar)) {
    EXPECT_TRUE(std::isnan(batch)) << what;
  } else {
    EXPECT_EQ(batch, scalar) << what;
  }
}

TEST(TriangleLineTable, BatchRowsMatchTheScalarTwinsToTheBit) {
  std::mt19937_64 rng(33);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<field::Triangle> triangles = random_triangles(rng, 35);
    const Vec3 d = trial % 10 == 0 ? glm::normalize(triangles[1].b - triangles[1].a)
                                   : random_unit(rng);
    const Vec3 o = trial % 10 == 0 ? triangles[1].a - 2.0 * d : random_point(rng, 3.0);
    const double r = std::uniform_real_distribution<double>(0.05, 1.5)(rng);
    std::vector<uint32_t> ids(triangles.size());
    std::iota(ids.begin(), ids.end(), 0u);
    TriangleSpanBatch batch;
    batch.gather(triangles, field::triangle_frames(triangles), ids);
    TriangleLineTable table;
    table.grow(8);  // rows from an earlier query: the batch appends after them
    const size_t first = batch.compute(o, d, r, table);
    ASSERT_EQ(first, 8u);
    for (size_t k = 0; k < triangles.size(); ++k) {
      const std::string what = "trial " + std::to_string(trial) + " triangle " + std::to_string(k);
      const TriangleReach row = table.reach(first + k);
      const TriangleReach twin = triangle_reach(o, d, triangles[k]);
      for (int i = 0; i < 2; ++i) {
        expect_same_bits(row.height[i], twin.height[i], what);
        expect_same_bits(row.along[i], twin.along[i], what);
        for (int edge = 0; edge < 3; ++edge) {
          expect_same_bits(row.outside[edge][i], twin.outside[edge][i], what);
        }
      }
      expect_same_bits(row.tilt, twin.tilt, what);
      const Span within = table.corners_within(first + k);
      const Span within_twin = corners_within(o, d, triangles[k], r);
      ASSERT_EQ(within.empty(), within_twin.empty()) << what;
      if (!within.empty()) {
        EXPECT_EQ(within.enter, within_twin.enter) << what;
        EXPECT_EQ(within.exit, within_twin.exit) << what;
      }
      // field::triangle_frame's area, where the triangle has one (the frame is made with fused
      // multiply-adds, as the field's batch wants it, the spans without: a few ulps apart).
      const field::TriangleFrame frame = field::triangle_frame(triangles[k]);
      if (frame.has_area()) {
        EXPECT_NEAR(0.5 * table.twice_area(first + k), frame.area, 1e-15 * frame.area) << what;
      }
      EXPECT_EQ(frame.has_area(), table.twice_area(first + k) > 0.0) << what;
      // The span is the batch's own, unchanged by the terms it writes beside it.
      const Span span = batch.span(k), scalar = triangle_span(o, d, triangles[k], r);
      ASSERT_EQ(span.empty(), scalar.empty()) << what;
      if (!span.empty()) EXPECT_EQ(span.enter, scalar.enter) << what;
    }
  }
}

// The signed distance from p to the line through v and w, in the plane with unit normal n,
// positive on the side away from `inside` (a point of the triangle off that line).
double past_edge(const Vec3& p, const Vec3& v, const Vec3& w, const Vec3& inside, const Vec3& n) {
  const Vec3 foot = p - glm::dot(p - v, n) * n;
  Vec3 across = glm::cross(n, w - v);
  across /= glm::length(across);
  if (glm::dot(inside - v, across) < 0.0) across = -across;
  return -glm::dot(foot - v, across);
}

TEST(TriangleLineTerms, DescribeTheTrianglesPlaneEdgesAndCornersAlongTheLine) {
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> unit(-4.0, 4.0);
  for (int trial = 0; trial < 300; ++trial) {
    const field::Triangle tri{random_point(rng, 1.0), random_point(rng, 1.0),
                              random_point(rng, 1.0)};
    const Vec3 o = random_point(rng, 3.0), d = random_unit(rng);
    const TriangleReach reach = triangle_reach(o, d, tri);
    const Vec3 corner[3] = {tri.a, tri.b, tri.c};
    const Vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    const Vec3 centroid = (tri.a + tri.b + tri.c) / 3.0;
    for (int sample = 0; sample < 5; ++sample) {
      const double t = unit(rng);
      const Vec3 p = o + t * d;
      EXPECT_NEAR(reach.height[0] + reach.height[1] * t, glm::dot(p - tri.a, n), 1e-11);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(reach.outside[k][0] + reach.outside[k][1] * t,
                    past_edge(p, corner[k], corner[(k + 1) % 3], centroid, n), 1e-9)
            << "trial " << trial << " edge " << k;
      }
    }
    double lo = kInfinity, hi = -kInfinity;
    for (const Vec3& v : corner) {
      lo = std::min(lo, glm::dot(v - o, d));
      hi = std::max(hi, glm::dot(v - o, d));
    }
    EXPECT_NEAR(reach.along[0], lo, 1e-12);
    EXPECT_NEAR(reach.along[1], hi, 1e-12);
  }
}

TEST(TriangleLineTerms, CornersWithinIsWhereEveryCornerLiesWithinTheRadius) {
  std::mt19937_64 rng(35);
  int inside_somewhere = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 c = random_point(rng, 1.0);
    const field::Triangle tri{c + 0.3 * random_point(rng, 1.0), c + 0.3 * random_point(rng, 1.0),
                              c + 0.3 * random_point(rng, 1.0)};
    const Vec3 d = random_unit(rng), o = c + 0.4 * random_point(rng, 1.0) - 3.0 * d;
    const double r = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    const Span within = corners_within(o, d, tri, r);
    inside_somewhere += !within.empty();
    // Brute force along the line: every corner within r exactly on the span (up to rounding).
    for (int i = 0; i <= 600; ++i) {
      const double t = i * 0.01;
      const Vec3 p = o + t * d;
      const double farthest = std::max({glm::length(tri.a - p), glm::length(tri.b - p),
                                        glm::length(tri.c - p)});
      const bool inside = !within.empty() && t >= within.enter && t <= within.exit;
      if (std::abs(farthest - r) < 1e-9) continue;  // on the boundary
      EXPECT_EQ(inside, farthest < r) << "trial " << trial << " t " << t;
    }
  }
  EXPECT_GT(inside_somewhere, 50);
}

}  // namespace
}  // namespace convray::accel
