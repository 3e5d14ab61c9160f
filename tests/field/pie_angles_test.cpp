// Two pie angles summed with one atan2 (field/pie_angles.hpp) against the two atan2 calls it
// replaces: random pies of every pair of signs and sizes, sums near 0, pi and a whole turn,
// and pies with signed zeros, where the turn is decided by the sign bits alone. And three
// summed with one call where their sum lies within a turn, against three calls.
#include "field/pie_angles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace convray::field {
namespace {

double libm_atan2(double y, double x) { return std::atan2(y, x); }

double two_calls(double y0, double x0, double y1, double x1) {
  return std::atan2(y0, x0) + std::atan2(y1, x1);
}

// The pie at angle `a` (in [-pi, pi]) and length `r`.
struct Pie {
  double y, x;
};
Pie pie(double a, double r) { return {r * std::sin(a), r * std::cos(a)}; }

TEST(PieAngles, RandomPairsMatchTwoCalls) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-6.0, 6.0);
  for (int k = 0; k < 200000; ++k) {
    const double scale = std::pow(10.0, exponent(rng));
    const Pie p = pie(angle(rng), scale * std::pow(10.0, 0.5 * exponent(rng)));
    const Pie q = pie(angle(rng), scale * std::pow(10.0, 0.5 * exponent(rng)));
    const double expected = two_calls(p.y, p.x, q.y, q.x);
    const double got = two_pie_angles(p.y, p.x, q.y, q.x, 1.0 / (scale * scale), libm_atan2);
    ASSERT_NEAR(got, expected, 1e-14) << p.y << " " << p.x << " " << q.y << " " << q.x;
  }
}

TEST(PieAngles, SumsNearTheBranchCutsKeepTheirTurn) {
  // Sums a hair either side of 0, pi, 2 pi, -pi and -2 pi, from both-positive, both-negative
  // and mixed pairs: a wrong turn would be off by 2 pi.
  const double tiny[] = {0.0, 1e-300, 1e-17, 1e-12, 1e-6};
  for (const double e : tiny) {
    for (const double f : tiny) {
      const double pairs[][2] = {
          {e, f},          {kPi - e, f},      {kPi - e, kPi - f}, {kPi, kPi - f},
          {-e, -f},        {-kPi + e, -f},    {-kPi + e, -kPi + f}, {kPi - e, -f},
          {0.5 * kPi + e, 0.5 * kPi - f}, {-0.5 * kPi - e, -0.5 * kPi + f}};
      for (const auto& pair : pairs) {
        const Pie p = pie(pair[0], 1.0), q = pie(pair[1], 2.0);
        EXPECT_NEAR(two_pie_angles(p.y, p.x, q.y, q.x, 1.0, libm_atan2),
                    two_calls(p.y, p.x, q.y, q.x), 1e-14)
            << pair[0] << " + " << pair[1];
      }
    }
  }
}

TEST(PieAngles, SignedZerosCountAsTheirAtan2Does) {
  // Every pie with a zero component (atan2 gives 0, -0, pi, -pi or ±pi/2 by the signs),
  // against every other such pie and a few ordinary ones; (±0, ±0) included.
  const double zeros[] = {0.0, -0.0};
  const double values[] = {0.0, -0.0, 1.0, -1.0, 3.0, -0.25};
  for (const double y0 : values) {
    for (const double x0 : values) {
      if (y0 != 0.0 && x0 != 0.0) continue;  // one component zero at least
      for (const double y1 : values) {
        for (const double x1 : values) {
          const double expected = two_calls(y0, x0, y1, x1);
          const double got = two_pie_angles(y0, x0, y1, x1, 1.0, libm_atan2);
          EXPECT_NEAR(got, expected, 1e-15) << y0 << " " << x0 << " " << y1 << " " << x1;
        }
      }
    }
  }
  for (const double z : zeros) {  // (z, -1) is pi or -pi by the zero's sign: 2 pi apart
    EXPECT_DOUBLE_EQ(two_pie_angles(z, -1.0, z, -1.0, 1.0, libm_atan2),
                     two_calls(z, -1.0, z, -1.0));
  }
}

double three_calls(const Pie& p, const Pie& q, const Pie& r) {
  return std::atan2(p.y, p.x) + std::atan2(q.y, q.x) + std::atan2(r.y, r.x);
}

// Three pies whose angles sum to `sum` (in [0, 2 pi]), the first two drawn at random.
void three_pies_summing_to(double sum, std::mt19937_64& rng, Pie out[3]) {
  std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-3.0, 3.0);
  for (;;) {
    const double a = angle(rng), b = angle(rng), c = sum - a - b;
    if (!(std::abs(c) < kPi)) continue;
    const double angles[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) out[k] = pie(angles[k], std::pow(10.0, exponent(rng)));
    return;
  }
}

TEST(PieAngles, ThreeSummingWithinATurnMatchThreeCalls) {
  // A triangle's pies, as the batch sums them: their sum is the arc inside the triangle, in
  // [0, 2 pi]. Random sums across the range, and sums a hair from its ends, where the one
  // call cannot tell 0 from a whole turn and must say so.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int doubtful_count = 0, cases = 0;
  const auto check = [&](double sum) {
    Pie p[3];
    three_pies_summing_to(sum, rng, p);
    double doubtful = -1.0;
    const double got =
        three_pie_angles(p[0].y, p[0].x, p[1].y, p[1].x, p[2].y, p[2].x, 1.0, libm_atan2, doubtful);
    ++cases;
    ASSERT_TRUE(doubtful == 0.0 || doubtful == 1.0);
    if (doubtful != 0.0) {
      ++doubtful_count;
      EXPECT_TRUE(std::abs(sum) < 1e-8 || std::abs(sum - 2.0 * kPi) < 1e-8) << sum;
      return;
    }
    ASSERT_NEAR(got, three_calls(p[0], p[1], p[2]), 1e-13) << sum;
  };
  for (int k = 0; k < 100000; ++k) check(2.0 * kPi * unit(rng));
  for (const double e : {0.0, 1e-15, 1e-12, 1e-10, 1e-9, 1e-8, 1e-6}) {
    for (int k = 0; k < 200; ++k) {
      check(e);
      check(2.0 * kPi - e);
      check(kPi + e);
      check(kPi - e);
    }
  }
  EXPECT_LT(doubtful_count, cases / 50);
  EXPECT_GT(doubtful_count, 0);  // the sums at 0 and a whole turn are flagged
}

TEST(PieAngles, ThreeWithZeroPiesCountAsTheirAtan2Does) {
  // A zero pie stands for the angle atan2 gives it (0 or pi by the signs), as in two_pie_angles:
  // against three calls wherever the three-call sum lies in [0, 2 pi] and the turn is sure.
  const double values[] = {0.0, -0.0, 1.0, -1.0, 2.0};
  int compared = 0;
  for (const double y0 : values) {
    for (const double x0 : values) {
      for (const double y1 : values) {
        for (const double x1 : values) {
          for (const double y2 : {0.0, -0.0, 1.0}) {
            for (const double x2 : {1.0, -1.0, 0.0}) {
              const double expected = std::atan2(y0, x0) + std::atan2(y1, x1) + std::atan2(y2, x2);
              if (!(expected >= 0.0 && expected <= 2.0 * kPi)) continue;
              double doubtful = 0.0;
              const double got = three_pie_angles(y0, x0, y1, x1, y2, x2, 1.0, libm_atan2, doubtful);
              if (doubtful != 0.0) continue;
              ++compared;
              EXPECT_NEAR(got, expected, 1e-15) << y0 << " " << x0 << " " << y1 << " " << x1
                                                << " " << y2 << " " << x2;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 500);
}

}  // namespace
}  // namespace convray::field
