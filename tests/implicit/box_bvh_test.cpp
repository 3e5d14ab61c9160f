// The box hierarchy (box_bvh.hpp) against brute force over every box: which boxes hold a point
// (closed boxes: faces, edges and corners count), and which boxes a ray crosses within
// [tmin, tmax] and where, checked against the geometry (the span's points inside the box,
// points just beyond it outside) and against samples along the ray for the boxes it skips.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "implicit/box_bvh.hpp"
#include "core/box.hpp"

namespace convray::implicit {
namespace {

bool inside(const Box3& b, const Vec3& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (p[axis] < b.lo[axis] || p[axis] > b.hi[axis]) return false;
  }
  return true;
}

// Boxes of many sizes, some flat (zero thickness on an axis), some repeated, some sharing faces.
std::vector<Box3> random_boxes(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.0, 1.0), unit(0.0, 1.0);
  std::vector<Box3> boxes;
  for (int i = 0; i < count; ++i) {
    const double roll = unit(rng);
    if (roll < 0.05 && !boxes.empty()) {
      boxes.push_back(boxes[size_t(unit(rng) * boxes.size()) % boxes.size()]);  // a duplicate
      continue;
    }
    Box3 b;
    b.lo = Vec3(position(rng), position(rng), position(rng));
    Vec3 extent = Vec3(size(rng), size(rng), size(rng)) * (roll < 0.5 ? 0.5 : 4.0);
    if (roll > 0.9) extent[i % 3] = 0.0;  // flat
    b.hi = b.lo + extent;
    if (roll > 0.8 && roll <= 0.9 && !boxes.empty()) {  // on the face of the previous box
      const Box3& prev = boxes.back();
      b.lo.x = prev.hi.x;
      b.hi.x = b.lo.x + extent.x;
    }
    boxes.push_back(b);
  }
  return boxes;
}

// Points anywhere, inside boxes, and exactly on their faces and corners.
Vec3 random_point(std::mt19937_64& rng, const std::vector<Box3>& boxes) {
  std::uniform_real_distribution<double> position(-11.0, 11.0), unit(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 3), axis(0, 2);
  const int k = boxes.empty() ? 0 : kind(rng);
  if (k == 0) return {position(rng), position(rng), position(rng)};
  const Box3& b = boxes[std::uniform_int_distribution<size_t>(0, boxes.size() - 1)(rng)];
  Vec3 p = b.lo + (b.hi - b.lo) * Vec3(unit(rng), unit(rng), unit(rng));
  if (k == 2) {  // on a face
    const int a = axis(rng);
    p[a] = unit(rng) < 0.5 ? b.lo[a] : b.hi[a];
  } else if (k == 3) {  // on a corner
    for (int a = 0; a < 3; ++a) p[a] = unit(rng) < 0.5 ? b.lo[a] : b.hi[a];
  }
  return p;
}

TEST(BoxBvh, ContainFindsExactlyTheBoxesHoldingThePoint) {
  std::mt19937_64 rng(1441);
  long long found = 0;
  for (int count : {0, 1, 3, 4, 5, 17, 300, 2000}) {
    const std::vector<Box3> boxes = random_boxes(rng, count);
    const BoxBvh bvh(boxes);
    ASSERT_EQ(bvh.boxes().size(), boxes.size());
    for (int i = 0; i < 3000; ++i) {
      const Vec3 p = random_point(rng, boxes);
      std::vector<uint32_t> got;
      bvh.contain(p, got);
      std::sort(got.begin(), got.end());
      std::vector<uint32_t> expected;
      for (uint32_t b = 0; b < boxes.size(); ++b) {
        if (inside(boxes[b], p)) expected.push_back(b);
      }
      ASSERT_EQ(got, expected) << count << " boxes, point " << i;
      found += long(expected.size());
    }
  }
  EXPECT_GT(found, 5000);
}

TEST(BoxBvh, BoundsAreTheUnionOfTheBoxes) {
  std::mt19937_64 rng(1442);
  const std::vector<Box3> boxes = random_boxes(rng, 500);
  const BoxBvh bvh(boxes);
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Box3& b : boxes) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  EXPECT_EQ(bvh.bounds().lo, lo);
  EXPECT_EQ(bvh.bounds().hi, hi);
  EXPECT_TRUE(BoxBvh().bounds().empty());
  std::vector<uint32_t> none;
  BoxBvh().contain(Vec3(0.0), none);
  std::vector<BoxBvh::Span> spans;
  BoxBvh().crossed(Ray{}, 0.0, INFINITY, spans);
  EXPECT_TRUE(none.empty() && spans.empty());
}

// Rays from anywhere (inside boxes too), in any direction including along the axes, over
// pieces [tmin, tmax] finite or not.
Ray random_ray(std::mt19937_64& rng, int i) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> position(-12.0, 12.0);
  Vec3 d(n(rng), n(rng), n(rng));
  if (i % 5 == 0) d[i % 3] = 0.0;  // parallel to a pair of faces
  if (i % 7 == 0) {                // along an axis
    d = Vec3(0.0);
    d[i % 3] = i % 2 ? 1.0 : -1.0;
  }
  return {{position(rng), position(rng), position(rng)}, glm::normalize(d)};
}

TEST(BoxBvh, CrossedFindsEveryBoxTheRayMeetsAndWhere) {
  std::mt19937_64 rng(1443);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long long spans_checked = 0;
  for (int count : {1, 5, 60, 1500}) {
    const std::vector<Box3> boxes = random_boxes(rng, count);
    const BoxBvh bvh(boxes);
    for (int i = 0; i < 600; ++i) {
      const Ray ray = random_ray(rng, i);
      const double tmin = i % 2 ? 0.0 : -5.0 + 20.0 * unit(rng);
      const double tmax = i % 3 ? INFINITY : tmin + 15.0 * unit(rng);
      std::vector<BoxBvh::Span> spans;
      bvh.crossed(ray, tmin, tmax, spans);
      std::sort(spans.begin(), spans.end(),
                [](const auto& a, const auto& b) { return a.id < b.id; });
      // Brute force: every box clipped on its own.
      std::vector<BoxBvh::Span> expected;
      for (uint32_t b = 0; b < boxes.size(); ++b) {
        double t0 = tmin, t1 = tmax;
        if (clip_to_box(ray, boxes[b], t0, t1)) expected.push_back({b, t0, t1});
      }
      ASSERT_EQ(spans.size(), expected.size()) << count << " " << i;
      for (size_t k = 0; k < spans.size(); ++k) {
        EXPECT_EQ(spans[k].id, expected[k].id);
        EXPECT_EQ(spans[k].t0, expected[k].t0);
        EXPECT_EQ(spans[k].t1, expected[k].t1);
      }
      // The spans against the geometry: within [tmin, tmax], their points in the box (to
      // rounding), and just beyond an end that is not tmin or tmax, outside it.
      for (const BoxBvh::Span& s : spans) {
        const Box3& b = boxes[s.id];
        const Vec3 grow(1e-9 * (1.0 + std::abs(s.t0) + std::abs(s.t1)));
        const Box3 grown{b.lo - grow, b.hi + grow};
        EXPECT_LE(tmin, s.t0);
        EXPECT_LE(s.t0, s.t1);
        EXPECT_LE(s.t1, tmax);
        EXPECT_TRUE(inside(grown, ray.at(s.t0)));
        EXPECT_TRUE(inside(grown, ray.at(s.t1)));
        EXPECT_TRUE(inside(grown, ray.at(0.5 * (s.t0 + s.t1))));
        const double step = 1e-6;
        if (s.t0 > tmin) EXPECT_FALSE(inside(b, ray.at(s.t0 - step))) << s.id;
        if (s.t1 < tmax) EXPECT_FALSE(inside(b, ray.at(s.t1 + step))) << s.id;
        ++spans_checked;
      }
    }
  }
  EXPECT_GT(spans_checked, 1000);
}

// The boxes the ray skips: no sample along [tmin, tmax] (within the scene) lies inside them.
TEST(BoxBvh, SkippedBoxesAreNotOnTheRay) {
  std::mt19937_64 rng(1444);
  const std::vector<Box3> boxes = random_boxes(rng, 60);
  const BoxBvh bvh(boxes);
  int skipped_checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Ray ray = random_ray(rng, i);
    std::vector<BoxBvh::Span> spans;
    bvh.crossed(ray, 0.0, 60.0, spans);
    std::vector<bool> crossed(boxes.size(), false);
    for (const auto& s : spans) crossed[s.id] = true;
    for (uint32_t b = 0; b < boxes.size(); ++b) {
      if (crossed[b]) continue;
      ++skipped_checked;
      for (int j = 0; j <= 3000; ++j) {
        ASSERT_FALSE(inside(boxes[b], ray.at(60.0 * j / 3000.0))) << i << " box " << b;
      }
    }
  }
  EXPECT_GT(skipped_checked, 10000);
}

}  // namespace
}  // namespace convray::implicit
