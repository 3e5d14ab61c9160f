// The spatial order (Morton's Z-order): a permutation, monotone along a line parallel to an
// axis, non-finite points last, ties in the given order, and near points near each other in
// the order (consecutive points much closer than in a random order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "core/spatial_order.hpp"

namespace convray {
namespace {

TEST(SpatialOrder, IsAPermutation) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::vector<Vec3> points(1000);
  for (Vec3& p : points) p = {u(rng), u(rng), u(rng)};
  std::vector<uint32_t> order = spatial_order(points);
  ASSERT_EQ(order.size(), points.size());
  std::sort(order.begin(), order.end());
  for (uint32_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
}

TEST(SpatialOrder, AlongALineParallelToAnAxisItSortsByThatCoordinate) {
  std::mt19937_64 rng(2);
  std::vector<Vec3> points;
  for (int i = 0; i < 200; ++i) points.push_back({0.5, -2.0, double(i) * 0.37});
  std::shuffle(points.begin(), points.end(), rng);
  const std::vector<uint32_t> order = spatial_order(points);
  for (size_t k = 1; k < order.size(); ++k) {
    EXPECT_LT(points[order[k - 1]].z, points[order[k]].z) << k;
  }
}

TEST(SpatialOrder, NonFinitePointsGoLastAndTiesKeepTheirOrder) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec3> points{{1, 1, 1}, {nan, 0, 0}, {0, 0, 0}, {1, 1, 1},
                                 {0, INFINITY, 0}, {0, 0, 0}};
  const std::vector<uint32_t> order = spatial_order(points);
  EXPECT_EQ(order, (std::vector<uint32_t>{2, 5, 0, 3, 1, 4}));
  EXPECT_TRUE(spatial_order(std::vector<Vec3>{}).empty());
  // Finite points too far apart for their difference to be finite still get an order.
  const std::vector<Vec3> wide{{1e308, 0, 0}, {-1e308, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(spatial_order(wide).size(), 3u);
  EXPECT_EQ(spatial_order(std::vector<Vec3>{{3, 3, 3}}), std::vector<uint32_t>{0});
}

TEST(SpatialOrder, ConsecutivePointsLieMuchCloserThanInARandomOrder) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points(20000);
  for (Vec3& p : points) p = {u(rng), u(rng), u(rng)};
  auto mean_step = [&](const std::vector<uint32_t>& order) {
    double sum = 0.0;
    for (size_t k = 1; k < order.size(); ++k) {
      sum += glm::length(points[order[k]] - points[order[k - 1]]);
    }
    return sum / double(order.size() - 1);
  };
  std::vector<uint32_t> given(points.size());
  std::iota(given.begin(), given.end(), 0u);
  // Random points in a unit cube: about 0.66 apart in the given order; 20,000 of them are
  // about 0.037 apart from their nearest neighbour, and the curve's steps stay near that.
  EXPECT_LT(mean_step(spatial_order(points)), 0.1 * mean_step(given));
}

}  // namespace
}  // namespace convray
