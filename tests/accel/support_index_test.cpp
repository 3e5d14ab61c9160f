// The Embree index against brute force over every primitive: the same primitives, the same
// exact intervals, the same point-query answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "accel/support_index.hpp"
#include "accel/support_shapes.hpp"

namespace convray::accel {
namespace {

struct Scene {
  std::vector<Vec3> centers;
  std::vector<double> center_radii;
  std::vector<field::Segment> segments;
  std::vector<double> segment_radii;
  std::vector<field::Arc> arcs;
  std::vector<double> arc_radii;
  std::vector<field::Triangle> triangles_a, triangles_b;

  SupportSources sources() const {
    SupportSources s;
    s.sphere_centers = centers;
    s.sphere_radii = center_radii;
    s.capsules = segments;
    s.capsule_radii = segment_radii;
    s.arcs = arcs;
    s.arc_radii = arc_radii;
    s.triangle_groups = {{triangles_a, 0.3}, {triangles_b, 0.1}};
    return s;
  }
};

Scene random_scene(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-10, 10), small(-0.7, 0.7), radius(0.05, 0.6);
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  auto near = [&](const Vec3& p) { return p + Vec3(small(rng), small(rng), small(rng)); };
  Scene s;
  for (int i = 0; i < 300; ++i) {
    s.centers.push_back(point());
    s.center_radii.push_back(radius(rng));
  }
  for (int i = 0; i < 300; ++i) {
    const Vec3 a = point();
    s.segments.push_back({a, near(a)});
    s.segment_radii.push_back(radius(rng));
  }
  for (int i = 0; i < 100; ++i) {
    field::Arc arc;
    arc.center = point();
    arc.axis = glm::normalize(Vec3(small(rng), small(rng), 1.0));
    arc.start = glm::normalize(glm::cross(arc.axis, Vec3(1, 0, 0)));
    arc.radius = 0.5;
    arc.angle = 3.0;
    s.arcs.push_back(arc);
    s.arc_radii.push_back(radius(rng));
  }
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a = point();
    (i % 2 ? s.triangles_a : s.triangles_b).push_back({a, near(a), near(a)});
  }
  return s;
}

Span brute_span(const Scene& s, uint32_t id, const Vec3& o, const Vec3& d) {
  if (id < s.centers.size()) return sphere_span(o, d, s.centers[id], s.center_radii[id]);
  id -= uint32_t(s.centers.size());
  if (id < s.segments.size()) return capsule_span(o, d, s.segments[id], s.segment_radii[id]);
  id -= uint32_t(s.segments.size());
  if (id < s.arcs.size()) return arc_span(o, d, s.arcs[id], s.arc_radii[id]);
  id -= uint32_t(s.arcs.size());
  if (id < s.triangles_a.size()) return triangle_span(o, d, s.triangles_a[id], 0.3);
  id -= uint32_t(s.triangles_a.size());
  return triangle_span(o, d, s.triangles_b[id], 0.1);
}

bool brute_contains(const Scene& s, uint32_t id, const Vec3& p) {
  if (id < s.centers.size()) {
    const double r = s.center_radii[id];
    return glm::dot(p - s.centers[id], p - s.centers[id]) < r * r;
  }
  id -= uint32_t(s.centers.size());
  if (id < s.segments.size()) return distance2_to_segment(p, s.segments[id]) < s.segment_radii[id] * s.segment_radii[id];
  id -= uint32_t(s.segments.size());
  if (id < s.arcs.size()) return distance2_to_arc(p, s.arcs[id]) < s.arc_radii[id] * s.arc_radii[id];
  id -= uint32_t(s.arcs.size());
  if (id < s.triangles_a.size()) return distance2_to_triangle(p, s.triangles_a[id]) < 0.09;
  id -= uint32_t(s.triangles_a.size());
  return distance2_to_triangle(p, s.triangles_b[id]) < 0.01;
}

TEST(SupportIndex, LineQueryFindsExactlyTheCrossedSupports) {
  std::mt19937_64 rng(21);
  const Scene scene = random_scene(rng);
  const SupportIndex index(scene.sources());
  const auto total = uint32_t(index.size());
  ASSERT_EQ(total, 300 + 300 + 100 + 2000);
  std::uniform_real_distribution<double> u(-12, 12);
  std::normal_distribution<double> n;
  size_t found_total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Aim at a primitive so that most lines cross something; origins outside and inside.
    const Vec3 o(u(rng), u(rng), u(rng));
    const Vec3 target = scene.centers[trial % scene.centers.size()];
    const Vec3 d = glm::normalize(target - o + 0.3 * Vec3(n(rng), n(rng), n(rng)));
    const double tmin = trial % 3 == 0 ? 0.0 : 1.0, tmax = trial % 5 == 0 ? 8.0 : INFINITY;
    std::vector<SupportInterval> got;
    index.intersect(o, d, tmin, tmax, got);
    std::sort(got.begin(), got.end(), [](auto& a, auto& b) { return a.primitive < b.primitive; });
    std::vector<SupportInterval> expected;
    for (uint32_t id = 0; id < total; ++id) {
      const Span s = brute_span(scene, id, o, d);
      if (!s.empty() && s.exit >= tmin && s.enter <= tmax) expected.push_back({id, s.enter, s.exit});
    }
    ASSERT_EQ(got.size(), expected.size()) << trial;
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].primitive, expected[i].primitive);
      EXPECT_EQ(got[i].enter, expected[i].enter);
      EXPECT_EQ(got[i].exit, expected[i].exit);
    }
    found_total += got.size();
  }
  EXPECT_GT(found_total, 300u);
}

TEST(SupportIndex, PointQueryFindsExactlyThePrimitivesWithinReach) {
  std::mt19937_64 rng(22);
  const Scene scene = random_scene(rng);
  const SupportIndex index(scene.sources());
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  size_t found_total = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 p = scene.triangles_a[trial % scene.triangles_a.size()].a +
                   Vec3(jitter(rng), jitter(rng), jitter(rng));
    std::vector<uint32_t> got;
    index.contain(p, got);
    std::sort(got.begin(), got.end());
    std::vector<uint32_t> expected;
    for (uint32_t id = 0; id < index.size(); ++id) {
      if (brute_contains(scene, id, p)) expected.push_back(id);
    }
    ASSERT_EQ(got, expected) << trial;
    found_total += got.size();
  }
  EXPECT_GT(found_total, 150u);
}

TEST(SupportIndex, BoundsHoldEverySupportAndMemoryIsReported) {
  std::mt19937_64 rng(23);
  const Scene scene = random_scene(rng);
  const SupportIndex index(scene.sources());
  const Box3 b = index.bounds();
  for (const Vec3& c : scene.centers) {
    EXPECT_TRUE(glm::all(glm::lessThanEqual(b.lo, c - Vec3(0.05))));
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(b.hi, c + Vec3(0.05))));
  }
  EXPECT_GT(index.memory_bytes(), 0u);
}

TEST(SupportIndex, EmptyIndexAnswersNothing) {
  const SupportIndex index(SupportSources{});
  std::vector<SupportInterval> hits;
  index.intersect({0, 0, 0}, {0, 0, 1}, 0, INFINITY, hits);
  std::vector<uint32_t> ids;
  index.contain({0, 0, 0}, ids);
  EXPECT_TRUE(hits.empty());
  EXPECT_TRUE(ids.empty());
  EXPECT_TRUE(index.bounds().empty());
}

}  // namespace
}  // namespace convray::accel
