// The torus against a brute-force search of its implicit function along the ray (sign
// changes on a dense grid, each bisected to the last bit), from near and from far; and the
// root isolation it relies on against polynomials with known roots.
#include "geometry/torus.hpp"

#include <gtest/gtest.h>

#include "core/polynomial_roots.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::build;
using testing::random_ray;

TEST(Polynomial, FindsKnownRootsIncludingCloseOnes) {
  // (x - 1)(x - 1.000001)(x + 2)(x - 5), expanded.
  const double r[4] = {1.0, 1.000001, -2.0, 5.0};
  double c[5] = {1.0, 0, 0, 0, 0};  // build the product coefficient by coefficient
  int degree = 0;
  for (double root : r) {
    for (int i = degree + 1; i > 0; --i) c[i] = c[i - 1] - root * c[i];
    c[0] = -root * c[0];
    ++degree;
  }
  double found[kMaxPolynomialDegree];
  ASSERT_EQ(polynomial_roots(c, -10.0, 10.0, found), 4);
  EXPECT_NEAR(found[0], -2.0, 1e-14);
  EXPECT_NEAR(found[1], 1.0, 1e-9);
  EXPECT_NEAR(found[2], 1.000001, 1e-9);
  EXPECT_NEAR(found[3], 5.0, 1e-13);
  // Only those in the interval.
  ASSERT_EQ(polynomial_roots(c, 0.0, 3.0, found), 2);
  // No real roots: x^4 + 1.
  const double none[5] = {1, 0, 0, 0, 1};
  EXPECT_EQ(polynomial_roots(none, -1e6, 1e6, found), 0);
  // A leading zero lowers the degree: 2x - 1.
  const double linear[3] = {-1, 2, 0};
  ASSERT_EQ(polynomial_roots(linear, -1, 1, found), 1);
  EXPECT_EQ(found[0], 0.5);
}

TEST(Polynomial, QuadraticKeepsTheSmallRootsDigits) {
  double t[2];
  ASSERT_EQ(quadratic_roots(1.0, -1e8, 1.0, t), 2);  // x^2 - 2e8 x + 1
  EXPECT_NEAR(t[0], 5e-9, 1e-24);
  EXPECT_NEAR(t[1], 2e8, 1e-7);
  EXPECT_EQ(quadratic_roots(1.0, 0.0, 1.0, t), 0);
  ASSERT_EQ(quadratic_roots(0.0, 1.0, -4.0, t), 1);  // 2x - 4
  EXPECT_EQ(t[0], 2.0);
}

// Sign changes of the torus' function (sqrt(x^2+z^2) - R)^2 + y^2 - r^2 along the ray.
std::vector<double> brute_force_torus(const TorusShape& torus, const Ray& ray, double t0, double t1,
                                      int samples) {
  return testing::inside_changes([&](const Vec3& p) { return torus.implicit_value(p) < 0.0; }, ray,
                                 t0, t1, samples);
}

void compare_with_brute_force(double major, double minor, double distance, uint64_t seed, int rays,
                              double relative_tolerance) {
  auto surface = std::make_shared<SurfaceInfo>();
  const TorusShape torus(major, minor, surface);
  std::mt19937_64 rng(seed);
  int compared = 0, with_hits = 0;
  for (int i = 0; i < rays; ++i) {
    // Aimed near the core circle, so that thin tori are hit too.
    const double angle = std::uniform_real_distribution<double>(0.0, 2.0 * kPi)(rng);
    const Vec3 aim = major * Vec3(std::cos(angle), 0.0, std::sin(angle)) +
                     1.5 * minor * testing::random_unit(rng);
    const Vec3 origin = distance * testing::random_unit(rng);
    const Ray ray{origin, glm::normalize(aim - origin)};
    // The span of the ray near the torus, sampled densely.
    const double t0 = distance - 2.0 * (major + minor), t1 = distance + 2.0 * (major + minor);
    const int samples = 40000;
    const auto expected = brute_force_torus(torus, ray, t0, t1, samples);
    const auto found = testing::crossing_distances(torus, ray, 0.0, INFINITY);
    const double step = (t1 - t0) / samples;
    if (testing::min_gap(expected) < 4 * step || testing::min_gap(found) < 4 * step) continue;
    ++compared;
    ASSERT_EQ(found.size(), expected.size()) << "ray " << i;
    with_hits += !found.empty();
    for (size_t k = 0; k < found.size(); ++k) {
      EXPECT_NEAR(found[k], expected[k], relative_tolerance * distance) << "ray " << i;
      // The point is on the surface: the distance-like function vanishes there.
      EXPECT_NEAR(torus.implicit_value(ray.at(found[k])), 0.0, 1e-9 * minor * distance);
    }
  }
  EXPECT_GT(compared, rays * 9 / 10);
  EXPECT_GT(with_hits, rays / 4);
}

TEST(Torus, MatchesBruteForceFromNearby) { compare_with_brute_force(1.0, 0.25, 4.0, 7, 400, 1e-9); }

TEST(Torus, MatchesBruteForceFromAfar) {
  // 1e4 radii away the closed-form quartic loses most digits; isolation plus polish does not.
  compare_with_brute_force(1.0, 0.25, 1e4, 8, 200, 1e-9);
}

TEST(Torus, ThinAndFatTori) {
  compare_with_brute_force(2.0, 0.02, 10.0, 9, 200, 1e-9);
  compare_with_brute_force(1.0, 0.9, 5.0, 10, 200, 1e-9);
}

TEST(Torus, AxisRayThroughTheHoleAndAcross) {
  const ShapePtr torus = build(scene::Torus{2.0, 0.5});
  // Down the y axis: through the hole, nothing.
  EXPECT_TRUE(testing::crossing_distances(*torus, Ray{{0, 5, 0}, {0, -1, 0}}, 0, INFINITY).empty());
  // Along x in the plane y = 0: -2.5, -1.5, 1.5, 2.5.
  std::vector<Crossing> out;
  TraceStats stats;
  torus->crossings(Ray{{-10, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, out, stats);
  ASSERT_EQ(out.size(), 4u);
  const double expected[4] = {7.5, 8.5, 11.5, 12.5};
  const Vec3 normals[4] = {{-1, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(out[size_t(k)].t, expected[k], 1e-14);
    EXPECT_NEAR(glm::length(out[size_t(k)].normal - normals[k]), 0.0, 1e-14);
  }
  EXPECT_TRUE(torus->inside({0, 0.2, 2.1}));
  EXPECT_FALSE(torus->inside({0, 0, 0}));
  // Random rays against inside() changes, normals facing out.
  std::mt19937_64 rng(11);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Ray ray = random_ray(rng, {0, 0, 0}, 6.0, 2.5);
    checked += testing::check_crossings_against_inside(*torus, ray, 0.0, 12.0, 1e-9);
  }
  EXPECT_GT(checked, 150);
}

}  // namespace
}  // namespace convray::geometry
