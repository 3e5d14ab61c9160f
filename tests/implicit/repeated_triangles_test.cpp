// Repeated triangles: found against a brute-force comparison of every pair's corner sets,
// and a surface that merges them gives the field of the unmerged sum, each triangle's closed
// form added once per occurrence (field::triangle_field, independent of the merge).
#include "implicit/repeated_triangles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "field/cauchy.hpp"
#include "field/threshold.hpp"
#include "field/triangle.hpp"
#include "implicit/cauchy_surface.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/mesh_field.hpp"

namespace convray::implicit {
namespace {

using field::Triangle;

Vec3 random_point(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> coarse(-3, 3);  // coarse: some corners coincide
  std::uniform_real_distribution<double> fine(-1.0, 1.0);
  return rng() % 2 ? Vec3(coarse(rng), coarse(rng), coarse(rng)) * 0.25
                   : Vec3(fine(rng), fine(rng), fine(rng));
}

// A soup with copies: some triangles repeated up to 4 times, corners rotated or flipped.
std::vector<Triangle> soup_with_copies(std::mt19937_64& rng, size_t distinct) {
  std::vector<Triangle> soup;
  for (size_t i = 0; i < distinct; ++i) {
    const Triangle t{random_point(rng), random_point(rng), random_point(rng)};
    const int copies = 1 + int(rng() % 4);
    for (int c = 0; c < copies; ++c) {
      switch (rng() % 4) {
        case 0: soup.push_back(t); break;
        case 1: soup.push_back({t.b, t.c, t.a}); break;
        case 2: soup.push_back({t.a, t.c, t.b}); break;  // the other orientation
        default: soup.push_back({t.c, t.b, t.a}); break;
      }
    }
  }
  std::shuffle(soup.begin(), soup.end(), rng);
  return soup;
}

bool same_corners(const Triangle& s, const Triangle& t) {
  std::array<Vec3, 3> a{s.a, s.b, s.c}, b{t.a, t.b, t.c};
  auto less = [](const Vec3& p, const Vec3& q) {
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  };
  std::sort(a.begin(), a.end(), less);
  std::sort(b.begin(), b.end(), less);
  return a == b;
}

TEST(RepeatedTriangles, MultiplicitiesMatchBruteForce) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Triangle> soup = soup_with_copies(rng, 60);
    const auto merged = merge_repeated(soup);
    ASSERT_TRUE(merged.has_value());
    size_t total = 0;
    for (size_t i = 0; i < merged->size(); ++i) {
      const Triangle& distinct = soup[merged->first[i]];
      size_t count = 0;
      for (const Triangle& t : soup) count += same_corners(t, distinct);
      EXPECT_EQ(merged->multiplicity[i], count);
      // The first occurrence: no earlier triangle of the soup has the same corners.
      for (uint32_t j = 0; j < merged->first[i]; ++j) EXPECT_FALSE(same_corners(soup[j], distinct));
      for (size_t j = 0; j < i; ++j) {
        EXPECT_FALSE(same_corners(distinct, soup[merged->first[j]]));
      }
      total += merged->multiplicity[i];
    }
    EXPECT_EQ(total, soup.size());
  }
}

TEST(RepeatedTriangles, NothingToMergeInADistinctSoup) {
  std::vector<Triangle> soup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}};
  EXPECT_FALSE(merge_repeated(soup).has_value());
  EXPECT_EQ(repeated_triangle_count(soup), 0u);
  soup.push_back({{-0.0, 1, 0}, {0, -0.0, 0}, {1, 0, -0.0}});  // -0 is 0
  EXPECT_EQ(repeated_triangle_count(soup), 1u);
}

TEST(RepeatedTriangles, MergedSurfaceHasTheFieldOfTheUnmergedSum) {
  std::mt19937_64 rng(6);
  const std::vector<Triangle> soup = soup_with_copies(rng, 40);
  const double R = 0.4, strength = 1.7;
  scene::ConvolutionObject object;
  scene::MeshComponent mesh;
  mesh.triangles = soup;
  mesh.weight = {strength, R};
  object.meshes.push_back(mesh);
  object.threshold = field::threshold_for_offset(strength, R, 0.5 * R);
  const ConvolutionSurface surface(object);
  EXPECT_EQ(surface.merged_triangle_count(), soup.size() - merge_repeated(soup)->size());
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int k = 0; k < 300; ++k) {
    const Vec3 p(u(rng), u(rng), u(rng));
    field::FieldSample sum;
    for (const Triangle& t : soup) sum += field::triangle_field(p, t, R) * strength;
    const field::FieldSample got = surface.field(p);
    const double scale = 1e-12 * (1.0 + std::abs(sum.value));
    EXPECT_NEAR(got.value, sum.value, scale) << k;
    EXPECT_NEAR(glm::length(got.gradient - sum.gradient), 0.0, 1e-11 * (1.0 + glm::length(sum.gradient)));
  }
}

// The same for MeshField (the field, slice and polygonize commands on a file): its SIMD path
// (TriangleBatch with the multiplicities as lane weights, lean and general paths) and its
// scalar twin, against the unmerged sum.
TEST(RepeatedTriangles, MergedMeshFieldHasTheFieldOfTheUnmergedSum) {
  std::mt19937_64 rng(7);
  const std::vector<Triangle> soup = soup_with_copies(rng, 40);
  for (const double R : {0.4, 5.0}) {  // clipped triangles, and every triangle wholly inside
    const MeshField field(soup, R, 1.3);
    EXPECT_EQ(field.triangle_count(), soup.size());
    EXPECT_LT(field.triangles().size(), soup.size());
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int k = 0; k < 200; ++k) {
      const Vec3 p(u(rng), u(rng), u(rng));
      field::FieldSample sum;
      for (const Triangle& t : soup) sum += field::triangle_field(p, t, R) * 1.3;
      const double tolerance = 1e-11 * (1.0 + std::abs(sum.value));
      EXPECT_NEAR(field.value(p), sum.value, tolerance) << k;
      EXPECT_NEAR(field.field(p).value, sum.value, tolerance) << k;
      EXPECT_NEAR(field.field_exact(p).value, sum.value, tolerance) << k;
      EXPECT_LT(glm::length(field.field(p).gradient - sum.gradient),
                1e-10 * (1.0 + glm::length(sum.gradient)));
    }
  }
}

// The Cauchy kernel's surface merges copies too: its truncated field against the unmerged sum
// of the closed forms (field::cauchy_triangle_field), each triangle's term kept where the point
// lies in that triangle's box grown by the truncation radius, as the kernel's truncation reads.
TEST(RepeatedTriangles, MergedCauchySurfaceHasTheFieldOfTheUnmergedSum) {
  std::mt19937_64 rng(8);
  const std::vector<Triangle> soup = soup_with_copies(rng, 40);
  const double sharpness = 2.0, strength = 0.7;
  for (const double radius : {0.3, 100.0}) {  // truncated, and every term everywhere
    scene::ConvolutionObject object;
    object.kernel = {field::KernelType::cauchy, sharpness};
    object.meshes.push_back({soup, {strength, radius}});
    object.threshold = 0.5;
    const CauchySurface surface(object);
    EXPECT_EQ(surface.merged_triangle_count(),
              soup.size() - merge_repeated(soup)->size());
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int k = 0; k < 200; ++k) {
      const Vec3 p(u(rng), u(rng), u(rng));
      field::FieldSample sum;
      for (const Triangle& t : soup) {
        const Vec3 lo = glm::min(glm::min(t.a, t.b), t.c) - Vec3(radius);
        const Vec3 hi = glm::max(glm::max(t.a, t.b), t.c) + Vec3(radius);
        const bool degenerate = glm::length(glm::cross(t.b - t.a, t.c - t.a)) == 0.0;
        if (degenerate || glm::any(glm::lessThan(p, lo)) || glm::any(glm::greaterThan(p, hi))) {
          continue;
        }
        sum += field::cauchy_triangle_field(p, t, sharpness) * strength;
      }
      const field::FieldSample got = surface.field(p);
      EXPECT_NEAR(got.value, sum.value, 1e-12 * (1.0 + std::abs(sum.value))) << k;
      EXPECT_LT(glm::length(got.gradient - sum.gradient), 1e-11 * (1.0 + glm::length(sum.gradient)))
          << k;
    }
  }
}

// The supports the polygonizer visits: one box per distinct triangle, the box each triangle
// alone would have (accel::triangle_support_box, the same as without the copies).
TEST(SupportBoxes, ExactRepeatsShareOneBox) {
  const Triangle a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Triangle b{Vec3(2, 0, 0), Vec3(3, 1, 0), Vec3(2, 0, 1)};
  const Triangle a_turned{a.b, a.c, a.a};  // the same corners, another order
  scene::ConvolutionObject copies, distinct;
  copies.meshes.push_back({{a, b, a, a_turned, b, a}, {1.0, 0.25}});
  distinct.meshes.push_back({{a, b}, {1.0, 0.25}});
  auto by_corner = [](const Box3& p, const Box3& q) { return p.lo.x < q.lo.x; };
  std::vector<Box3> got = ConvolutionSurface(copies).support_boxes();
  std::vector<Box3> want = ConvolutionSurface(distinct).support_boxes();
  std::sort(got.begin(), got.end(), by_corner);
  std::sort(want.begin(), want.end(), by_corner);
  ASSERT_EQ(got.size(), 2u);
  ASSERT_EQ(want.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(got[i].lo, want[i].lo) << i;
    EXPECT_EQ(got[i].hi, want[i].hi) << i;
  }
}

}  // namespace
}  // namespace convray::implicit
