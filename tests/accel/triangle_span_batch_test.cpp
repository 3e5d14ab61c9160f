// The SIMD span batch against its scalar twin (triangle_span) and against the distance
// function along the line: random triangles and lines, and the degenerate cases the lanes
// handle with selects instead of branches (zero-area triangles, lines parallel to an edge or
// to the plane, lines through a corner).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "accel/support_shapes.hpp"
#include "reference/random_vectors.hpp"
#include "accel/triangle_span_batch.hpp"
#include "field/triangle_frame.hpp"

namespace convray::accel {
namespace {

using testing::random_point;
using testing::random_unit;

// Both empty, or the same interval to the last bit: the lanes round every operation as the
// scalar twin does (no contraction into fused multiply-adds in src/accel).
void expect_same(const Span& batch, const Span& scalar, const std::string& what) {
  ASSERT_EQ(batch.empty(), scalar.empty()) << what;
  if (scalar.empty()) return;
  EXPECT_EQ(batch.enter, scalar.enter) << what;
  EXPECT_EQ(batch.exit, scalar.exit) << what;
}

std::vector<Span> batch_spans(const std::vector<field::Triangle>& triangles, const Vec3& o,
                              const Vec3& d, double radius) {
  std::vector<uint32_t> ids(triangles.size());
  std::iota(ids.begin(), ids.end(), 0u);
  TriangleSpanBatch batch;
  batch.gather(triangles, field::triangle_frames(triangles), ids);
  batch.compute(o, d, radius);
  std::vector<Span> spans;
  for (size_t k = 0; k < batch.size(); ++k) spans.push_back(batch.span(k));
  return spans;
}

TEST(TriangleSpanBatch, MatchesTheScalarTwinOnRandomTrianglesAndLines) {
  std::mt19937_64 rng(21);
  int crossed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<field::Triangle> triangles;
    for (int k = 0; k < 37; ++k) {  // not a multiple of the lane count
      triangles.push_back({random_point(rng, 1.0), random_point(rng, 1.0), random_point(rng, 1.0)});
    }
    const Vec3 o = random_point(rng, 3.0), d = random_unit(rng);
    const double r = std::uniform_real_distribution<double>(0.05, 1.0)(rng);
    const std::vector<Span> spans = batch_spans(triangles, o, d, r);
    for (size_t k = 0; k < triangles.size(); ++k) {
      const Span scalar = triangle_span(o, d, triangles[k], r);
      crossed += !scalar.empty();
      expect_same(spans[k], scalar, "trial " + std::to_string(trial));
    }
  }
  EXPECT_GT(crossed, 500);  // both outcomes are exercised
}

// Every point of the line within R of the triangle lies in the span, and the span's ends are
// at distance R (to rounding): the span is the crossing, no more and no less.
TEST(TriangleSpanBatch, EndsLieOnTheSupportsBoundary) {
  std::mt19937_64 rng(22);
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<field::Triangle> triangles{
        {random_point(rng, 1.0), random_point(rng, 1.0), random_point(rng, 1.0)}};
    const Vec3 o = random_point(rng, 2.0), d = random_unit(rng);
    const double r = 0.4;
    const Span span = batch_spans(triangles, o, d, r)[0];
    if (span.empty()) {
      for (int i = -4000; i <= 4000; ++i) {
        ASSERT_GE(distance2_to_triangle(o + (i * 1e-3) * d, triangles[0]), r * r) << trial;
      }
      continue;
    }
    EXPECT_NEAR(std::sqrt(distance2_to_triangle(o + span.enter * d, triangles[0])), r, 1e-9);
    EXPECT_NEAR(std::sqrt(distance2_to_triangle(o + span.exit * d, triangles[0])), r, 1e-9);
    for (int i = -4000; i <= 4000; ++i) {
      const double t = i * 1e-3;
      if (distance2_to_triangle(o + t * d, triangles[0]) < r * r) {
        ASSERT_GE(t, span.enter - 1e-12) << trial;
        ASSERT_LE(t, span.exit + 1e-12) << trial;
      }
    }
  }
}

// Lines through the seams between the support's pieces, where each piece gives only the ends
// it holds (a face's crossing over the triangle, a cylinder's over its edge): on the rim of
// the prism's faces above an edge, on the rim of an edge's end disk at a corner, and above a
// corner. The span holds the seam point and ends on the boundary, batch and twin alike.
TEST(TriangleSpanBatch, LinesThroughTheSeamsBetweenPiecesEndOnTheSupport) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = 0.3;
  for (int trial = 0; trial < 600; ++trial) {
    const field::Triangle tri{random_point(rng, 1.0), random_point(rng, 1.0),
                              random_point(rng, 1.0)};
    const Vec3 corners[3] = {tri.a, tri.b, tri.c};
    const Vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    const int edge = trial % 3;
    const Vec3 a = corners[edge], b = corners[(edge + 1) % 3];
    const double side = unit(rng) < 0.5 ? r : -r;
    Vec3 seam;
    switch ((trial / 3) % 3) {
      case 0:  // above the edge, at height R
        seam = a + unit(rng) * (b - a) + side * n;
        break;
      case 1: {  // the end disk's rim at a: R from a, square to the edge
        const Vec3 u = glm::normalize(b - a);
        const Vec3 across = glm::normalize(glm::cross(u, random_unit(rng)));
        seam = a + r * across;
        break;
      }
      default:  // above the corner
        seam = a + side * n;
    }
    const Vec3 d = random_unit(rng), o = seam - 3.0 * d;
    const Span span = batch_spans({tri}, o, d, r)[0];
    expect_same(span, triangle_span(o, d, tri, r), "trial " + std::to_string(trial));
    ASSERT_FALSE(span.empty()) << trial;
    EXPECT_LE(span.enter, 3.0 + 1e-9) << trial;
    EXPECT_GE(span.exit, 3.0 - 1e-9) << trial;
    EXPECT_NEAR(std::sqrt(distance2_to_triangle(o + span.enter * d, tri)), r, 1e-9) << trial;
    EXPECT_NEAR(std::sqrt(distance2_to_triangle(o + span.exit * d, tri)), r, 1e-9) << trial;
    for (int i = -6000; i <= 6000; ++i) {
      const double t = i * 1e-3;
      if (distance2_to_triangle(o + t * d, tri) < r * r) {
        ASSERT_GE(t, span.enter - 1e-12) << trial;
        ASSERT_LE(t, span.exit + 1e-12) << trial;
      }
    }
  }
}

TEST(TriangleSpanBatch, DegenerateCasesMatchTheScalarTwin) {
  const std::vector<field::Triangle> triangles{
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}},        // collinear: its three capsules
      {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},        // a point: a ball
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},        // an ordinary triangle in z = 0
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}},        // two corners the same: a capsule
  };
  const std::vector<std::pair<Vec3, Vec3>> lines{
      {{1, -5, 0}, {0, 1, 0}},                  // across the collinear triangle
      {{-3, 0, 0}, {1, 0, 0}},                  // along an edge's line
      {{0.2, 0.2, -4}, {0, 0, 1}},              // through the plane, inside the triangle
      {{-3, 0.3, 0.1}, {1, 0, 0}},              // parallel to the plane, within R of it
      {{-3, 0.3, 0.9}, {1, 0, 0}},              // parallel to the plane, beyond R
      {{0, 0, -2}, {0, 0, 1}},                  // through a corner
  };
  for (double r : {0.5, 1e-3, 50.0}) {
    for (const auto& [o, d] : lines) {
      const std::vector<Span> spans = batch_spans(triangles, o, d, r);
      for (size_t k = 0; k < triangles.size(); ++k) {
        expect_same(spans[k], triangle_span(o, d, triangles[k], r),
                    "triangle " + std::to_string(k) + ", R " + std::to_string(r));
      }
    }
  }
}

}  // namespace
}  // namespace convray::accel
