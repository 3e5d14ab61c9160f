// sor: crossings against a brute-force search (dense sampling and bisection of
// x^2 + z^2 - r^2(y) along the ray, r^2 written out here from POV-Ray's rule: the cubic
// Hermite curve of r^2 in h through the points, slopes 2 r (r[j+1] - r[j-1]) / (h[j+1] - h[j-1]),
// measured with the povray binary's trace()), the caps, and inside.
#include <random>

#include "geometry/sor.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry::testing {
namespace {

const std::vector<Vec2> kPoints = {{0.5, -0.5}, {1, 0}, {0.6, 0.7}, {1.2, 1.1}, {0.4, 2}, {0.9, 2.6}};

double reference_r2(double y) {
  const auto& p = kPoints;
  for (size_t i = 1; i + 2 < p.size(); ++i) {
    if (y < p[i].y || y > p[i + 1].y) continue;
    const double d = p[i + 1].y - p[i].y, t = (y - p[i].y) / d;
    const double m0 = 2 * p[i].x * (p[i + 1].x - p[i - 1].x) / (p[i + 1].y - p[i - 1].y);
    const double m1 = 2 * p[i + 1].x * (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y);
    const double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
    const double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
    return h00 * p[i].x * p[i].x + h10 * d * m0 + h01 * p[i + 1].x * p[i + 1].x + h11 * d * m1;
  }
  return -1.0;  // outside the segments: no surface
}

// Positive outside the solid between the caps, negative inside.
double field(const Vec3& q) {
  if (q.y < 0.0 || q.y > 2.0) return 1.0;
  return q.x * q.x + q.z * q.z - reference_r2(q.y);
}

TEST(Sor, SurfaceMatchesPovRaysMeasuredRadii) {
  // trace() from <5, y, 0> towards -x in the povray binary, this sor, y = 0.385 and 0.935.
  SorShape sor(kPoints, true, nullptr);
  EXPECT_NEAR(std::sqrt(sor.radius_squared(0.385)), 0.79016691, 1e-7);
  EXPECT_NEAR(std::sqrt(sor.radius_squared(0.935)), 1.03443479, 1e-7);
}

TEST(Sor, CrossingsMatchABruteForceSearch) {
  const ShapePtr sor = build(scene::Sor{kPoints, false});
  std::mt19937_64 rng(9);
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    const Ray ray = random_ray(rng, {0, 1, 0}, 5.0, 1.5);
    // Brute force: sign changes of the field (caps included) over t in [0, 10].
    std::vector<double> expected;
    const int steps = 20000;
    double previous = field(ray.origin);
    for (int k = 1; k <= steps; ++k) {
      const double t = 10.0 * k / steps;
      const double value = field(ray.at(t));
      if ((value < 0) != (previous < 0)) {
        double lo = 10.0 * (k - 1) / steps, hi = t;
        for (int b = 0; b < 60; ++b) {
          const double mid = 0.5 * (lo + hi);
          ((field(ray.at(mid)) < 0) == (previous < 0) ? lo : hi) = mid;
        }
        expected.push_back(0.5 * (lo + hi));
      }
      previous = value;
    }
    const auto got = crossing_distances(*sor, ray, 0.0, 10.0);
    // Rays grazing the surface within a sampling step may pair up differently: skip them.
    if (got.size() != expected.size()) {
      bool grazing = false;
      for (double t : got) grazing |= std::abs(field(ray.at(t + 1e-3))) < 1e-3;
      if (grazing) continue;
    }
    ASSERT_EQ(got.size(), expected.size()) << i;
    for (size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], expected[k], 1e-7) << i;
    ++compared;
  }
  EXPECT_GT(compared, 350);
}

TEST(Sor, InsideBetweenTheCapsAndNoneWhenOpen) {
  const ShapePtr closed = build(scene::Sor{kPoints, false});
  const ShapePtr open = build(scene::Sor{kPoints, true});
  EXPECT_TRUE(closed->inside({0.5, 0.5, 0}));
  EXPECT_FALSE(closed->inside({0.95, 0.5, 0}));
  EXPECT_FALSE(closed->inside({0.1, 2.1, 0}));
  EXPECT_FALSE(open->inside({0.5, 0.5, 0}));
  // The caps: a vertical ray down the axis meets the top cap at y = 2 and the bottom at 0.
  const auto t = crossing_distances(*closed, Ray{{0.1, 5, 0}, {0, -1, 0}}, 0.0, INFINITY);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 3.0, 1e-12);
  EXPECT_NEAR(t[1], 5.0, 1e-12);
  EXPECT_TRUE(crossing_distances(*open, Ray{{0.1, 5, 0}, {0, -1, 0}}, 0.0, INFINITY).empty());
}

}  // namespace
}  // namespace convray::geometry::testing
