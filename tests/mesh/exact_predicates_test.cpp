// The orientation predicates against determinants computed exactly in 128-bit integers, on
// points built to be coplanar (or collinear) and then moved by a unit or two: the cases where
// plain double arithmetic gets the sign wrong.
#include "mesh/exact_predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace convray::mesh {
namespace {

struct I3 {
  int64_t x, y, z;
};

int sign(__int128 v) { return (v > 0) - (v < 0); }

// det[b - a, c - a, d - a] in integers: differences below 2^39, products below 2^118.
int orient3d_integer(const I3& a, const I3& b, const I3& c, const I3& d) {
  const __int128 ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const __int128 vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const __int128 wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return sign(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx));
}

int orient2d_integer(const I3& a, const I3& b, const I3& c) {
  return sign(__int128(b.x - a.x) * (c.y - a.y) - __int128(b.y - a.y) * (c.x - a.x));
}

// Integer coordinates scaled by a power of two: the doubles hold them exactly.
Vec3 to_double(const I3& p, double scale) {
  return Vec3(double(p.x), double(p.y), double(p.z)) * scale;
}

// The plain double determinant, for showing that the cases below defeat it.
int orient3d_naive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = glm::dot(u, glm::cross(v, w));
  return (det > 0) - (det < 0);
}

class NearlyCoplanar {
 public:
  explicit NearlyCoplanar(unsigned seed) : random_(seed) {}

  // a, b, c within 2^35 of the origin, d in their plane (an integer combination) moved by at
  // most `nudge` units along each axis.
  std::array<I3, 4> next(int nudge) {
    std::uniform_int_distribution<int64_t> coordinate(-(int64_t(1) << 35), int64_t(1) << 35);
    std::uniform_int_distribution<int64_t> weight(-1, 2), move(-nudge, nudge);
    auto point = [&] { return I3{coordinate(random_), coordinate(random_), coordinate(random_)}; };
    const I3 a = point(), b = point(), c = point();
    const int64_t s = weight(random_), t = weight(random_);
    const I3 d{a.x + s * (b.x - a.x) + t * (c.x - a.x) + move(random_),
               a.y + s * (b.y - a.y) + t * (c.y - a.y) + move(random_),
               a.z + s * (b.z - a.z) + t * (c.z - a.z) + move(random_)};
    return {a, b, c, d};
  }

 private:
  std::mt19937_64 random_;
};

TEST(ExactPredicates, Orient3dMatchesIntegerDeterminantNearCoplanarity) {
  NearlyCoplanar points(7);
  int naive_wrong = 0, zero = 0;
  for (int i = 0; i < 20000; ++i) {
    const auto q = points.next(i % 3);
    const double scale = std::ldexp(1.0, (i % 7) * 20 - 60);  // 2^-60 .. 2^60
    const Vec3 a = to_double(q[0], scale), b = to_double(q[1], scale), c = to_double(q[2], scale),
               d = to_double(q[3], scale);
    const int expected = orient3d_integer(q[0], q[1], q[2], q[3]);
    ASSERT_EQ(orient3d(a, b, c, d), expected) << "case " << i;
    ASSERT_EQ(orient3d_exact(a, b, c, d), expected) << "case " << i;
    // The predicate's sign flips with an odd permutation of the corners.
    ASSERT_EQ(orient3d(b, a, c, d), -expected) << "case " << i;
    naive_wrong += orient3d_naive(a, b, c, d) != expected;
    zero += expected == 0;
  }
  EXPECT_GT(naive_wrong, 100);  // the cases reach where doubles alone fail
  EXPECT_GT(zero, 1000);        // and exact coplanarity is recognised
}

TEST(ExactPredicates, Orient2dMatchesIntegerDeterminantNearCollinearity) {
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int64_t> coordinate(-(int64_t(1) << 50), int64_t(1) << 50);
  std::uniform_int_distribution<int64_t> weight(-2, 3), move(-2, 2);
  int naive_wrong = 0, zero = 0;
  for (int i = 0; i < 20000; ++i) {
    // Collinear up to a nudge: c = a + s (b - a), with |a|, |b| small enough for 2^52.
    const I3 a{coordinate(random) >> 3, coordinate(random) >> 3, 0};
    const I3 b{coordinate(random) >> 3, coordinate(random) >> 3, 0};
    const int64_t s = weight(random);
    const I3 c{a.x + s * (b.x - a.x) + move(random), a.y + s * (b.y - a.y) + move(random), 0};
    const int expected = orient2d_integer(a, b, c);
    const double scale = std::ldexp(1.0, (i % 5) * 10 - 20);
    const Vec2 pa = Vec2(double(a.x), double(a.y)) * scale,
               pb = Vec2(double(b.x), double(b.y)) * scale,
               pc = Vec2(double(c.x), double(c.y)) * scale;
    ASSERT_EQ(orient2d(pa, pb, pc), expected) << "case " << i;
    ASSERT_EQ(orient2d_exact(pa, pb, pc), expected) << "case " << i;
    ASSERT_EQ(orient2d(pb, pa, pc), -expected) << "case " << i;
    const double naive = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
    naive_wrong += ((naive > 0) - (naive < 0)) != expected;
    zero += expected == 0;
  }
  EXPECT_GT(naive_wrong, 10);  // plain doubles fail on some of these
  EXPECT_GT(zero, 500);
}

// The classic failure of plain doubles (Kettner et al., "Classroom examples of robustness
// problems"): points a few units in the last place from the line y = x through (12, 12) and
// (24, 24). The exact sign is the sign of (y - x), scaled to integers by 2^53.
TEST(ExactPredicates, Orient2dNearTheDiagonalInUnitsInTheLastPlace) {
  const double ulp = std::ldexp(1.0, -53);
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Vec2 p(0.5 + i * ulp, 0.5 + j * ulp);
      const int expected = (j > i) - (j < i);  // left of the direction (12,12) -> (24,24)
      ASSERT_EQ(orient2d(p, Vec2(12, 12), Vec2(24, 24)), expected) << i << " " << j;
    }
  }
}

}  // namespace
}  // namespace convray::mesh
