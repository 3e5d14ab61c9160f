// The exact triangle contact tests against the separating axis theorem in integer arithmetic
// (tests/reference/separating_axes.hpp), on random triangles with corners on a small lattice,
// where touching, coplanar and collinear configurations are common.
#include "mesh/triangle_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reference/separating_axes.hpp"

namespace convray::mesh {
namespace {

using reference::IntPoint;

Vec3 to_vec(const IntPoint& p) { return Vec3(double(p.x), double(p.y), double(p.z)); }

Corners to_corners(const std::array<IntPoint, 3>& t) {
  return {to_vec(t[0]), to_vec(t[1]), to_vec(t[2])};
}

class LatticeTriangles {
 public:
  explicit LatticeTriangles(unsigned seed) : random_(seed) {}

  IntPoint point(int64_t size) {
    std::uniform_int_distribution<int64_t> c(0, size);
    return {c(random_), c(random_), c(random_)};
  }
  // Often in the plane z = 1 (so that pairs are coplanar), there on a finer lattice so that
  // one triangle can lie inside another without touching it; otherwise anywhere.
  std::array<IntPoint, 3> triangle(int64_t size) {
    const bool flat_layer = std::uniform_int_distribution<int>(0, 3)(random_) == 0;
    const int64_t reach = flat_layer ? 3 * size : size;
    std::array<IntPoint, 3> t{point(reach), point(reach), point(reach)};
    if (flat_layer) {
      for (IntPoint& p : t) p.z = 1;
    }
    return t;
  }

 private:
  std::mt19937_64 random_;
};

std::vector<IntPoint> hull(const std::array<IntPoint, 3>& t) { return {t[0], t[1], t[2]}; }

TEST(TriangleContact, TrianglesMeetAgreesWithSeparatingAxes) {
  LatticeTriangles lattice(3);
  int tested = 0, meeting = 0, coplanar = 0;
  while (tested < 20000) {
    const auto p = lattice.triangle(3), q = lattice.triangle(3);
    const Corners cp = to_corners(p), cq = to_corners(q);
    if (is_flat(cp) || is_flat(cq)) continue;
    const bool expected = reference::convex_hulls_meet(hull(p), hull(q));
    ASSERT_EQ(triangles_meet(cp, cq), expected) << "pair " << tested;
    ASSERT_EQ(triangles_meet(cq, cp), expected) << "pair " << tested;
    ++tested;
    meeting += expected;
    coplanar +=
        p[0].z == 1 && p[1].z == 1 && p[2].z == 1 && q[0].z == 1 && q[1].z == 1 && q[2].z == 1;
  }
  EXPECT_GT(meeting, 2000);
  EXPECT_LT(meeting, 18000);
  EXPECT_GT(coplanar, 500);
}

TEST(TriangleContact, SegmentMeetsTriangleAgreesWithSeparatingAxes) {
  LatticeTriangles lattice(5);
  int tested = 0, meeting = 0;
  while (tested < 20000) {
    const auto t = lattice.triangle(3);
    const IntPoint s0 = lattice.point(3),
                   s1 = tested % 4 == 0 ? IntPoint{s0.x, s0.y, 1} : lattice.point(3);
    const Corners ct = to_corners(t);
    if (is_flat(ct) || (s0.x == s1.x && s0.y == s1.y && s0.z == s1.z)) continue;
    const bool expected = reference::convex_hulls_meet({s0, s1}, hull(t));
    ASSERT_EQ(segment_meets_triangle(to_vec(s0), to_vec(s1), ct), expected) << "case " << tested;
    ASSERT_EQ(segment_meets_triangle(to_vec(s1), to_vec(s0), ct), expected) << "case " << tested;
    ++tested;
    meeting += expected;
  }
  EXPECT_GT(meeting, 2000);
}

// Points of the shared-corner tests below, in integers scaled by K: a itself, and the point
// 1/K of the way from a to d.
constexpr int64_t K = int64_t(1) << 16;

IntPoint scaled(const IntPoint& p) { return {p.x * K, p.y * K, p.z * K}; }

IntPoint toward(const IntPoint& a, const IntPoint& d) {  // K a + (d - a)
  return {a.x * K + d.x - a.x, a.y * K + d.y - a.y, a.z * K + d.z - a.z};
}

// Faces sharing corner a meet elsewhere exactly when p meets q with a small neighbourhood of a
// cut off: q' = hull(a + (d - a)/K, a + (e - a)/K, d, e). In integers, everything is scaled by
// K; K = 2^16 is far beyond the denominators of the common points of lattice triangles this
// small, so no common point other than a hides inside the cut.
TEST(TriangleContact, FacesSharingOneCornerAgreeWithSeparatingAxes) {
  LatticeTriangles lattice(9);
  int tested = 0, meeting = 0;
  while (tested < 10000) {
    auto p = lattice.triangle(3), q = lattice.triangle(3);
    q[0] = p[0];
    const Corners cp = to_corners(p), cq = to_corners(q);
    if (is_flat(cp) || is_flat(cq)) continue;
    int shared = 0;
    for (const Vec3& x : cp) shared += int(std::count(cq.begin(), cq.end(), x));
    if (shared != 1) continue;
    const bool expected = reference::convex_hulls_meet(
        {scaled(p[0]), scaled(p[1]), scaled(p[2])},
        {toward(q[0], q[1]), toward(q[0], q[2]), scaled(q[1]), scaled(q[2])});
    // Rotating either face's corners must not matter.
    const Corners rp{cp[1], cp[2], cp[0]}, rq{cq[2], cq[0], cq[1]};
    ASSERT_EQ(faces_intersect(cp, cq), expected) << "case " << tested;
    ASSERT_EQ(faces_intersect(rq, rp), expected) << "case " << tested;
    ++tested;
    meeting += expected;
  }
  EXPECT_GT(meeting, 500);
  EXPECT_LT(meeting, 9500);
}

// Faces sharing edge (a, b) overlap beyond it exactly when p meets the part of q at least 1/K
// away from that edge (barycentric weight of q's third corner d at least 1/K).
TEST(TriangleContact, FacesSharingAnEdgeAgreeWithSeparatingAxes) {
  LatticeTriangles lattice(13);
  int tested = 0, meeting = 0;
  while (tested < 10000) {
    auto p = lattice.triangle(3), q = lattice.triangle(3);
    if (tested % 2 == 0) {  // coplanar often
      for (IntPoint& c : p) c.z = 1;
      q[2].z = 1;
    }
    q[0] = p[1], q[1] = p[0];  // the same edge, run the other way as in a consistent mesh
    const Corners cp = to_corners(p), cq = to_corners(q);
    if (is_flat(cp) || is_flat(cq) || cp[2] == cq[2]) continue;
    const bool expected =
        reference::convex_hulls_meet({scaled(p[0]), scaled(p[1]), scaled(p[2])},
                                     {toward(q[0], q[2]), toward(q[1], q[2]), scaled(q[2])});
    ASSERT_EQ(faces_intersect(cp, cq), expected) << "case " << tested;
    ASSERT_EQ(faces_intersect(cq, cp), expected) << "case " << tested;
    ++tested;
    meeting += expected;
  }
  EXPECT_GT(meeting, 500);
  EXPECT_LT(meeting, 9500);
}

TEST(TriangleContact, TheSameFaceTwiceIntersects) {
  const Corners t{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_TRUE(faces_intersect(t, {t[1], t[2], t[0]}));
  EXPECT_TRUE(faces_intersect(t, {t[0], t[2], t[1]}));  // flipped
}

// Two slivers that come within one unit in the last place of each other near a common point,
// as marching tetrahedra makes around a lattice point, do not intersect; moved by that unit
// onto each other, they do. A tolerance cannot tell these apart.
TEST(TriangleContact, AGapOfOneUnitInTheLastPlaceIsAGap) {
  const double x = 3.0, next = std::nextafter(x, 4.0);
  const Corners p{Vec3(x, 0, 0), Vec3(x, 1, 0), Vec3(x, 0, 1)};
  const Corners apart{Vec3(next, 0.25, 0.25), Vec3(5, 0.25, 0.25), Vec3(5, 0.5, 0.25)};
  const Corners touching{Vec3(x, 0.25, 0.25), Vec3(5, 0.25, 0.25), Vec3(5, 0.5, 0.25)};
  EXPECT_FALSE(triangles_meet(p, apart));
  EXPECT_TRUE(triangles_meet(p, touching));
  EXPECT_TRUE(is_flat({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)}));
  EXPECT_FALSE(is_flat({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, std::nextafter(2.0, 3.0))}));
}

}  // namespace
}  // namespace convray::mesh
