// Batched segments and points must agree with their exact scalar twins (segment.cpp,
// point.cpp), which the reference tests prove right.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "field/point.hpp"
#include "field/segment.hpp"
#include "field/segment_batch.hpp"

namespace convray::field {
namespace {

TEST(SegmentBatch, MatchesScalarTwinEverywhere) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Segment> segs;
  for (int i = 0; i < 200; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng));
    segs.push_back({a, a + 0.6 * Vec3(u(rng), u(rng), u(rng))});
  }
  segs.push_back({{0.2, 0.2, 0.2}, {0.2, 0.2, 0.2}});  // zero length: contributes 0
  const SegmentBatch batch(segs);
  for (double r : {0.01, 0.1, 0.5, 3.0}) {
    for (int k = 0; k < 100; ++k) {
      const Vec3 p(u(rng), u(rng), u(rng));
      FieldSample exact;
      for (const Segment& s : segs) exact += segment_field(p, s, r);
      const FieldSample fast = batch.field(p, r);
      ASSERT_NEAR(batch.value(p, r), exact.value, 1e-13 * r * segs.size()) << "R=" << r;
      ASSERT_NEAR(fast.value, exact.value, 1e-13 * r * segs.size());
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(fast.gradient[a], exact.gradient[a], 1e-12 * segs.size());
    }
  }
}

TEST(SegmentBatch, EndPointExactlyOnTheSupportCarriesItsGradient) {
  // p at distance R/2 from the line; the segment ends exactly where |s| = w.
  const double r = 1.0, q = 0.5, w = std::sqrt(r * r - q * q);
  const std::vector<Segment> segs = {{{-3.0, q, 0.0}, {w, q, 0.0}}};
  const SegmentBatch batch(segs);
  const FieldSample fast = batch.field({0.0, 0.0, 0.0}, r);
  const FieldSample exact = segment_field({0.0, 0.0, 0.0}, segs[0], r);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(fast.gradient[a], exact.gradient[a], 1e-14);
}

TEST(PointBatch, MatchesScalarTwin) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> centers;
  for (int i = 0; i < 300; ++i) centers.emplace_back(u(rng), u(rng), u(rng));
  const PointBatch batch(centers);
  for (double r : {0.05, 0.4, 2.0}) {
    for (int k = 0; k < 50; ++k) {
      const Vec3 p(u(rng), u(rng), u(rng));
      FieldSample exact;
      for (const Vec3& c : centers) exact += point_field(p, c, r);
      const FieldSample fast = batch.field(p, r);
      EXPECT_NEAR(batch.value(p, r), exact.value, 1e-13 * centers.size());
      EXPECT_NEAR(fast.value, exact.value, 1e-13 * centers.size());
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(fast.gradient[a], exact.gradient[a], 1e-12 * centers.size() / r);
    }
  }
}

}  // namespace
}  // namespace convray::field
