// The one hierarchy over boxes (core/bvh.hpp) against a loop over every box, for its three
// queries: the boxes a ray segment meets (and, with a closest-hit narrowing, the nearest box
// entry), the boxes holding a point, and the box nearest to a point. Boxes of many sizes,
// flat ones and duplicates among them; rays along the axes too.
#include "core/bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace convray {
namespace {

std::vector<Box3> random_boxes(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.0, 2.0), unit(0.0, 1.0);
  std::vector<Box3> boxes;
  for (int i = 0; i < count; ++i) {
    if (unit(rng) < 0.05 && !boxes.empty()) {
      boxes.push_back(boxes[size_t(unit(rng) * double(boxes.size())) % boxes.size()]);
      continue;
    }
    Box3 b;
    b.lo = Vec3(position(rng), position(rng), position(rng));
    Vec3 extent(size(rng), size(rng), size(rng));
    if (unit(rng) < 0.1) extent[i % 3] = 0.0;  // flat
    b.hi = b.lo + extent;
    boxes.push_back(b);
  }
  return boxes;
}

Ray random_ray(std::mt19937_64& rng, int i) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> position(-12.0, 12.0);
  Vec3 d(n(rng), n(rng), n(rng));
  if (i % 7 == 0) {  // along an axis
    d = Vec3(0.0);
    d[i % 3] = i % 2 ? 1.0 : -1.0;
  }
  return {{position(rng), position(rng), position(rng)}, glm::normalize(d)};
}

// The hierarchy is built over padded boxes, as its users build it; the queries' own tests
// are on the exact boxes.
std::vector<Box3> padded_all(const std::vector<Box3>& boxes) {
  std::vector<Box3> out;
  for (const Box3& b : boxes) out.push_back(padded(b));
  return out;
}

TEST(Bvh, RaysVisitEveryBoxTheSegmentMeetsAndNarrowToTheNearestEntry) {
  std::mt19937_64 rng(140);
  for (int count : {1, 7, 300}) {
    const std::vector<Box3> boxes = random_boxes(rng, count);
    const Bvh bvh(padded_all(boxes));
    for (int i = 0; i < 300; ++i) {
      const Ray ray = random_ray(rng, i);
      std::vector<uint32_t> met, expected;
      double tmax = 40.0;
      bvh.traverse(ray, 0.0, tmax, [&](uint32_t b, double&) {
        double t0 = 0.0, t1 = 40.0;
        if (clip_to_box(ray, boxes[b], t0, t1)) met.push_back(b);
      });
      for (uint32_t b = 0; b < boxes.size(); ++b) {
        double t0 = 0.0, t1 = 40.0;
        if (clip_to_box(ray, boxes[b], t0, t1)) expected.push_back(b);
      }
      std::sort(met.begin(), met.end());
      met.erase(std::unique(met.begin(), met.end()), met.end());
      EXPECT_EQ(met, expected) << count << " " << i;
      // Closest hit: each visit narrows tmax to the box's entry; the end is the nearest one.
      double nearest = 40.0, brute = 40.0;
      bvh.traverse(ray, 0.0, nearest, [&](uint32_t b, double& reach) {
        double t0 = 0.0, t1 = reach;
        if (clip_to_box(ray, boxes[b], t0, t1)) reach = std::min(reach, t0);
      });
      for (const Box3& b : boxes) {
        double t0 = 0.0, t1 = 40.0;
        if (clip_to_box(ray, b, t0, t1)) brute = std::min(brute, t0);
      }
      EXPECT_EQ(nearest, brute) << count << " " << i;
    }
  }
}

TEST(Bvh, PointsFindTheBoxesHoldingThemAndTheNearestBox) {
  std::mt19937_64 rng(141);
  std::uniform_real_distribution<double> position(-12.0, 12.0);
  for (int count : {1, 7, 300}) {
    const std::vector<Box3> boxes = random_boxes(rng, count);
    const Bvh bvh(padded_all(boxes));
    for (int i = 0; i < 500; ++i) {
      Vec3 p(position(rng), position(rng), position(rng));
      if (i % 3 == 0) p = boxes[size_t(i) % boxes.size()].hi;  // on a corner
      std::vector<uint32_t> holding, expected;
      EXPECT_FALSE(bvh.any_at(p, [&](uint32_t b) {
        if (contains(boxes[b], p)) holding.push_back(b);
        return false;
      }));
      for (uint32_t b = 0; b < boxes.size(); ++b) {
        if (contains(boxes[b], p)) expected.push_back(b);
      }
      std::sort(holding.begin(), holding.end());
      EXPECT_EQ(holding, expected);
      // any_at stops at the first box that says so.
      EXPECT_EQ(bvh.any_at(p, [&](uint32_t b) { return contains(boxes[b], p); }),
                !expected.empty());
      // The nearest box, by the distance to it (0 inside).
      double best = INFINITY, brute = INFINITY;
      bvh.nearer_than(p, best, [&](uint32_t b, double& nearest) {
        nearest = std::min(nearest, std::sqrt(box_distance2(p, boxes[b])));
      });
      for (const Box3& b : boxes) {
        const Vec3 outside = glm::max(glm::max(b.lo - p, p - b.hi), Vec3(0.0));
        brute = std::min(brute, glm::length(outside));
      }
      EXPECT_EQ(best, brute) << count << " " << i;
    }
  }
}

TEST(Bvh, AnEmptyHierarchyAnswersNothing) {
  const Bvh empty;
  EXPECT_TRUE(empty.empty());
  double tmax = INFINITY, best = INFINITY;
  int visits = 0;
  empty.traverse(Ray{{0, 0, 0}, {1, 0, 0}}, 0.0, tmax, [&](uint32_t, double&) { ++visits; });
  EXPECT_FALSE(empty.any_at(Vec3(0.0), [&](uint32_t) { return ++visits, true; }));
  empty.nearer_than(Vec3(0.0), best, [&](uint32_t, double&) { ++visits; });
  EXPECT_EQ(visits, 0);
  EXPECT_EQ(best, INFINITY);
}

}  // namespace
}  // namespace convray
