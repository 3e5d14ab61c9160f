// The batched SIMD evaluator must agree with its exact scalar twin (triangle.cpp), which the
// reference tests prove right, for every configuration: wholly inside the support sphere,
// clipped, out of reach, zero-area lanes, subsets, and per-triangle output.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "field/triangle.hpp"
#include "field/triangle_batch.hpp"
#include "field/triangle_frame.hpp"
#include "util/simd_width.hpp"

namespace convray::field {
namespace {

std::vector<Triangle> random_triangles(std::mt19937_64& rng, size_t n, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triangle> tris;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    tris.push_back({c + spread * Vec3(u(rng), u(rng), u(rng)),
                    c + spread * Vec3(u(rng), u(rng), u(rng)),
                    c + spread * Vec3(u(rng), u(rng), u(rng))});
  }
  // Degenerate lanes: zero area (collinear, repeated corner).
  tris.push_back({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
  tris.push_back({{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, {0.5, 0.2, 0.3}});
  return tris;
}

FieldSample scalar_sum(const std::vector<Triangle>& tris, const Vec3& p, double r) {
  FieldSample sum;
  for (const Triangle& t : tris) sum += triangle_field(p, t, r);
  return sum;
}

TEST(TriangleBatch, SumMatchesScalarTwinForRadiiFromTinyToHuge) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  const auto tris = random_triangles(rng, 300, 0.4);
  const TriangleBatch batch(tris);
  for (double r : {0.01, 0.1, 0.3, 1.0, 3.0, 100.0}) {
    const double scale = r * r;  // field scale (π/3) R^2, up to a constant
    for (int k = 0; k < 60; ++k) {
      const Vec3 p(u(rng), u(rng), u(rng));
      const FieldSample exact = scalar_sum(tris, p, r);
      const FieldSample fast = batch.field(p, r);
      EXPECT_NEAR(batch.value(p, r), exact.value, 1e-12 * scale * tris.size()) << "R=" << r;
      EXPECT_NEAR(fast.value, exact.value, 1e-12 * scale * tris.size());
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(fast.gradient[a], exact.gradient[a], 1e-11 * r * tris.size()) << "R=" << r;
      }
    }
  }
}

TEST(TriangleBatch, PerTriangleValuesMatchScalarTwin) {
  std::mt19937_64 rng(7);
  const auto tris = random_triangles(rng, 150, 0.5);
  const TriangleBatch batch(tris);
  std::vector<double> out(tris.size());
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Radii far smaller than the triangles too: most edges then miss the disk entirely, the
  // case where an unmasked empty piece once left an FMA residue of 3e-10 of the scale.
  for (double r : {0.002, 0.02, 0.2, 5.0}) {
    for (int k = 0; k < 40; ++k) {
      const Triangle& near = tris[size_t(k) * 3 % tris.size()];
      const Vec3 p = (near.a + near.b + near.c) / 3.0 + 2.0 * r * Vec3(u(rng), u(rng), u(rng));
      batch.values(p, r, out);
      for (size_t i = 0; i < tris.size(); ++i) {
        ASSERT_NEAR(out[i], triangle_value(p, tris[i], r), 1e-13 * r * r) << i << " R=" << r;
      }
    }
  }
}

TEST(TriangleBatch, SubsetSumsOnlyTheListedTriangles) {
  std::mt19937_64 rng(3);
  const auto tris = random_triangles(rng, 200, 0.5);
  const TriangleBatch batch(tris);
  const std::vector<uint32_t> subset = {3, 17, 17, 42, 199, 200, 201};  // repeats count twice
  const Vec3 p(0.1, 0.1, 0.1);
  FieldSample expected;
  for (uint32_t i : subset) expected += triangle_field(p, tris[i], 0.7);
  const FieldSample got = batch.field(p, 0.7, subset);
  EXPECT_NEAR(got.value, expected.value, 1e-13);
  EXPECT_NEAR(batch.value(p, 0.7, subset), expected.value, 1e-13);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(got.gradient[a], expected.gradient[a], 1e-12);
}

// Listed subsets of every length from 1 to 13 (every loop runs over whole SIMD widths, the
// last lane repeated and masked out), with and without the path for wholly inside chunks
// tried first, match the scalar twin: on small triangles near p (wholly inside the sphere at
// the larger radius, clipped at the smaller), value and gradient alike.
TEST(TriangleBatch, ListedSubsetsMatchTheScalarTwinWithOrWithoutTheWhollyInsidePath) {
  std::mt19937_64 rng(4);
  const auto tris = random_triangles(rng, 40, 0.15);
  const TriangleBatch batch(tris);
  std::uniform_int_distribution<uint32_t> pick(0, uint32_t(tris.size() - 1));
  for (double r : {0.4, 3.0}) {
    for (size_t n = 1; n <= 13; ++n) {
      std::vector<uint32_t> subset;
      for (size_t k = 0; k < n; ++k) subset.push_back(pick(rng));
      std::vector<Triangle> listed;
      for (uint32_t i : subset) listed.push_back(tris[i]);
      const Vec3 p(0.05, -0.1, 0.1);
      const FieldSample expected = scalar_sum(listed, p, r);
      const double scale = std::max(1.0, std::abs(expected.value));
      for (bool try_inside : {true, false}) {
        const std::string what = "R " + std::to_string(r) + ", " + std::to_string(n) +
                                 " lanes, wholly inside path " + (try_inside ? "on" : "off");
        EXPECT_NEAR(batch.value(p, r, subset, try_inside), expected.value, 1e-12 * scale) << what;
        const FieldSample got = batch.field(p, r, subset, try_inside);
        EXPECT_NEAR(got.value, expected.value, 1e-12 * scale) << what;
        for (int a = 0; a < 3; ++a) {
          EXPECT_NEAR(got.gradient[a], expected.gradient[a],
                      1e-11 * std::max(1.0, glm::length(expected.gradient)))
              << what;
        }
      }
    }
  }
}

// Ranges read in place with a mask (the window march's clipped lanes where they lie close
// together): every start and length up to 20 lanes, random masks, against the scalar twin
// summed over the lanes the mask keeps. The lanes outside the mask, and those read past the
// range's end to fill a SIMD width, must add nothing: the batch is sized by resize_unset, as
// the march sizes it, and lanes it never set read as zeros.
TEST(TriangleBatch, MaskedRangesMatchTheScalarTwinOfTheKeptLanes) {
  std::mt19937_64 rng(29);
  const auto tris = random_triangles(rng, 20, 0.15);
  TriangleBatch batch;
  batch.resize_unset(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) batch.set_lane(i, tris[i], triangle_frame(tris[i]));
  std::bernoulli_distribution keep(0.6);
  std::vector<double> mask(tris.size() + kSimdWidth);
  int ranges = 0;
  for (double r : {0.4, 3.0}) {
    for (size_t first = 0; first < tris.size(); ++first) {
      for (size_t count = 1; first + count <= tris.size(); ++count) {
        std::fill(mask.begin(), mask.end(), 0.0);
        std::vector<Triangle> kept;
        for (size_t i = first; i < first + count; ++i) {
          if (!keep(rng)) continue;
          mask[i] = 1.0;
          kept.push_back(tris[i]);
        }
        const Vec3 p(0.05, -0.1, 0.1);
        const double expected = scalar_sum(kept, p, r).value;
        const double scale = std::max(1.0, std::abs(expected));
        for (bool try_inside : {true, false}) {
          EXPECT_NEAR(batch.value_of_range(p, r, first, count, mask.data(), try_inside), expected,
                      1e-12 * scale)
              << "R " << r << ", lanes " << first << " + " << count;
        }
        ++ranges;
      }
    }
  }
  EXPECT_GT(ranges, 400);
}

TEST(TriangleBatch, ManyPointsMatchOnePointAtATime) {
  std::mt19937_64 rng(11);
  const auto tris = random_triangles(rng, 50, 0.5);
  const TriangleBatch batch(tris);
  const std::vector<Vec3> points = {Vec3(0.0), Vec3(0.5, 0.5, 0.5), Vec3(9.0, 9.0, 9.0)};
  std::vector<double> out(points.size());
  batch.values(points, 0.6, out);
  for (size_t k = 0; k < points.size(); ++k) {
    EXPECT_NEAR(out[k], scalar_sum(tris, points[k], 0.6).value, 1e-12);
  }
  EXPECT_EQ(out[2], 0.0);  // out of every support: exactly zero
}

TEST(TriangleBatch, FarPointsGiveExactlyZero) {
  const std::vector<Triangle> tris = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const TriangleBatch batch(tris);
  EXPECT_EQ(batch.value({5, 5, 0}, 1.0), 0.0);   // in the plane, beyond R
  EXPECT_EQ(batch.value({0.2, 0.2, 1.0}, 1.0), 0.0);  // h == R: tangent sphere
  const FieldSample f = batch.field({-3, 0.5, 0.5}, 1.0);
  EXPECT_EQ(f.value, 0.0);
  EXPECT_EQ(f.gradient, Vec3(0.0));
}

// The per-ray batches of the window march are set lane by lane, in any order, from frames
// computed once per mesh (triangle_frame.hpp): the same lanes, bit for bit, as a batch made
// from the same triangles' corners, zero-area ones included.
TEST(TriangleBatch, AssignedFromFramesEqualsAssignedFromCorners) {
  std::mt19937_64 rng(28);
  const auto tris = random_triangles(rng, 80, 0.5);
  std::vector<TriangleFrame> frames;
  for (const Triangle& t : tris) frames.push_back(triangle_frame(t));
  std::vector<uint32_t> ids;
  std::vector<Triangle> picked;
  for (uint32_t i = uint32_t(tris.size()); i-- > 0;) {
    if (i % 3 == 0) continue;  // a subset, out of order, with both zero-area triangles
    ids.push_back(i);
    picked.push_back(tris[i]);
  }
  TriangleBatch from_frames;
  from_frames.resize_unset(ids.size());
  for (size_t lane = ids.size(); lane-- > 0;) {  // last first, as a march may meet them
    from_frames.set_lane(lane, tris[ids[lane]], frames[ids[lane]]);
  }
  const TriangleBatch from_corners(picked);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const double r = k % 2 ? 0.3 : 1.5;
    EXPECT_EQ(from_frames.value(p, r), from_corners.value(p, r));
    const FieldSample a = from_frames.field(p, r), b = from_corners.field(p, r);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.gradient, b.gradient);
  }
  // The frame itself: the unit normal, the edges' lengths from corner k to corner k + 1, half
  // the cross product's length as the area; no normal for a zero-area triangle, whose edges
  // still have their lengths (its support is their capsules).
  const TriangleFrame f = triangle_frame({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}});
  EXPECT_EQ(f.normal, Vec3(0, 0, 1));
  EXPECT_EQ(f.length[0], 2.0);
  EXPECT_DOUBLE_EQ(f.length[1], std::sqrt(5.0));
  EXPECT_EQ(f.length[2], 1.0);
  EXPECT_EQ(f.area, 1.0);
  const TriangleFrame line = triangle_frame({{0, 0, 0}, {3, 0, 0}, {1, 0, 0}});
  EXPECT_FALSE(line.has_area());
  EXPECT_EQ(line.area, 0.0);
  EXPECT_EQ(line.length[0], 3.0);
  EXPECT_EQ(line.length[1], 2.0);
  EXPECT_EQ(line.length[2], 1.0);
}

TEST(TriangleBatch, DisksAHairFromAllOrNoneInsideMatchTheScalarTwin) {
  // The batch sums a lane's three pie angles with one atan2 (pie_angles.hpp), which tells a
  // whole turn from none only by the product's sign: disks crossing an edge by a hair from
  // inside (the arc inside the triangle nearly the whole turn) and from outside (nearly none),
  // and reaching past a corner by a hair (an arc of about the hair), at every distance from
  // 10^-3 to 10^-15 of R, against the scalar twin. (Where the sign is in doubt the lane is
  // summed the two-call way: pie_angles_test.cpp checks which sums are flagged.)
  const Triangle t{{-10.0, -10.0, 0.0}, {10.0, -10.0, 0.0}, {0.0, 10.0, 0.0}};
  const TriangleBatch batch(std::vector<Triangle>{t});
  const double R = 1.0, h = 0.6, r0 = std::sqrt(R * R - h * h);
  int points = 0;
  for (double e = 1e-3; e >= 1e-15; e *= 0.1) {
    for (const double sign : {-1.0, 1.0}) {
      const Vec3 ps[] = {
          {0.0, -10.0 + r0 + sign * e, h},   // inside, reaching the bottom edge
          {0.0, -10.0 - r0 + sign * e, h},   // outside, reaching it from below
          {10.0 + r0 + sign * e, -10.0, h},  // the corner (10, -10) on the circle
      };
      for (const Vec3& p : ps) {
        const FieldSample exact = triangle_field(p, t, R);
        EXPECT_NEAR(batch.value(p, R), exact.value, 1e-13) << p.x << " " << p.y;
        const FieldSample got = batch.field(p, R);
        EXPECT_NEAR(got.value, exact.value, 1e-13) << p.x << " " << p.y;
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(got.gradient[a], exact.gradient[a], 1e-12);
        ++points;
      }
    }
  }
  EXPECT_EQ(points, 78);
}

TEST(TriangleBatch, EmptyBatchIsZero) {
  const TriangleBatch batch;
  EXPECT_EQ(batch.value(Vec3(0.0), 1.0), 0.0);
}

}  // namespace
}  // namespace convray::field
