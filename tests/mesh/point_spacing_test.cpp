// mean_point_spacing (a k-d tree) against the brute force over all pairs, on clouds of
// several shapes: a volume, a plane, a curve, far clusters, repeated positions.
#include <gtest/gtest.h>

#include <random>

#include "mesh/point_spacing.hpp"

namespace convray::mesh {
namespace {

double brute_force_spacing(const std::vector<Vec3>& points) {
  double total = 0.0;
  size_t count = 0;
  for (const Vec3& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (const Vec3& q : points) {
      const double d = glm::length(q - p);
      if (d > 0.0) best = std::min(best, d);
    }
    if (std::isfinite(best)) total += best, ++count;
  }
  return count ? total / static_cast<double>(count) : 0.0;
}

std::vector<Vec3> cloud(const std::string& shape, size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (size_t i = 0; i < n; ++i) {
    if (shape == "volume") points.emplace_back(u(random), u(random), u(random));
    if (shape == "plane") points.emplace_back(u(random), u(random), 0.25);
    if (shape == "curve") points.emplace_back(std::cos(3 * u(random)), std::sin(3 * u(random)), 0.0);
    if (shape == "clusters") points.emplace_back(Vec3(u(random), u(random), u(random)) * 0.01 + Vec3(i % 3 * 1000.0));
    if (shape == "repeats") points.emplace_back(std::floor(4 * u(random)), std::floor(4 * u(random)), 0.0);
  }
  return points;
}

TEST(PointSpacing, AgreesWithTheBruteForce) {
  for (const char* shape : {"volume", "plane", "curve", "clusters", "repeats"}) {
    for (size_t n : {2u, 9u, 200u, 1500u}) {
      const std::vector<Vec3> points = cloud(shape, n, static_cast<unsigned>(n));
      EXPECT_NEAR(mean_point_spacing(points), brute_force_spacing(points), 1e-12) << shape << " " << n;
    }
  }
}

TEST(PointSpacing, ByHand) {
  EXPECT_EQ(mean_point_spacing({}), 0.0);
  EXPECT_EQ(mean_point_spacing({Vec3(1, 2, 3)}), 0.0);
  EXPECT_EQ(mean_point_spacing({Vec3(1, 2, 3), Vec3(1, 2, 3)}), 0.0);  // one position
  // Points at 0, 1 and 3 on a line: nearest neighbours 1, 1 and 2.
  EXPECT_DOUBLE_EQ(mean_point_spacing({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0)}), 4.0 / 3.0);
}

}  // namespace
}  // namespace convray::mesh
