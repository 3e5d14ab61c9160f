// The quartic helpers of the sphere sweep (implicit/quartic.hpp) against direct evaluation:
// a sphere's term, the change of origin and the Bernstein hull. (The roots of quartics:
// tests/core/quartic_roots_test.cpp; the sweep's insertion sort: tests/core/sort_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "implicit/quartic.hpp"

namespace convray::implicit {
namespace {

TEST(Quartic, SphereTermShiftAndBernsteinAgreeWithDirectEvaluation) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double k = u(rng), h2 = std::abs(u(rng)), vc = u(rng), d = u(rng);
    const Quartic q = sphere_term(k, h2, vc);
    const Quartic moved = shifted(q, d);
    const double width = 0.1 + std::abs(u(rng));
    const auto b = bernstein(q, width);
    const auto [least, most] = std::minmax_element(b.begin(), b.end());
    for (int j = 0; j <= 20; ++j) {
      const double v = width * j / 20.0;
      const double e = h2 - (v - vc) * (v - vc);
      const double direct = k * e * e;
      const double scale = std::abs(k) * (h2 + 36.0) * (h2 + 36.0);
      EXPECT_NEAR(q(v), direct, 1e-13 * scale);
      EXPECT_NEAR(moved(v - d), direct, 1e-12 * scale);
      EXPECT_NEAR(q.slope(v), -4.0 * k * e * (v - vc), 1e-12 * scale);
      // The Bernstein hull holds the polynomial; its end points are the end values.
      EXPECT_GE(q(v), *least - 1e-12 * scale);
      EXPECT_LE(q(v), *most + 1e-12 * scale);
    }
    EXPECT_NEAR(b[0], q(0.0), 1e-13 * std::abs(k) * (h2 + 36.0) * (h2 + 36.0));
    EXPECT_NEAR(b[4], q(width), 1e-12 * std::abs(k) * (h2 + 36.0) * (h2 + 36.0));
  }
}

}  // namespace
}  // namespace convray::implicit
