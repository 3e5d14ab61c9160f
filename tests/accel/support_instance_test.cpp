// A prebuilt TriangleSupports placed as an instance answers as brute force over the placed
// triangles does (the same primitives, the same exact intervals, the same point-query
// answers), and as the local triangles do along the line carried back by the placement.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "accel/support_index.hpp"
#include "accel/support_shapes.hpp"
#include "accel/triangle_supports.hpp"

namespace convray::accel {
namespace {

constexpr double kRadius = 0.3;

using Triangles = std::vector<field::Triangle>;

std::shared_ptr<const Triangles> random_mesh(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-5, 5), small(-0.6, 0.6);
  auto mesh = std::make_shared<Triangles>();
  for (int i = 0; i < count; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng));
    auto near = [&] { return a + Vec3(small(rng), small(rng), small(rng)); };
    mesh->push_back({a, near(), near()});
  }
  return mesh;
}

Mat4 rigid(double degrees, const Vec3& axis, const Vec3& translation) {
  Mat4 m = glm::rotate(Mat4(1.0), glm::radians(degrees), glm::normalize(axis));
  m[3] = glm::dvec4(translation, 1.0);
  return m;
}

Triangles placed(const Triangles& local, const Mat4& m) {
  Triangles out;
  for (const field::Triangle& t : local) {
    out.push_back({transform_point(m, t.a), transform_point(m, t.b), transform_point(m, t.c)});
  }
  return out;
}

// A few spheres, capsules and arcs ahead of the triangles, so that the ids of the triangle
// groups start past them, and two placed copies of the same local mesh.
struct Scene {
  std::shared_ptr<const Triangles> local;
  Mat4 first, second;
  Triangles placed_first, placed_second;
  std::vector<Vec3> centers;
  std::vector<double> center_radii;
  std::vector<field::Segment> segments;
  std::vector<double> segment_radii;
  std::vector<field::Arc> arcs;
  std::vector<double> arc_radii;

  Scene(std::mt19937_64& rng, const Mat4& a, const Mat4& b)
      : local(random_mesh(rng, 1500)), first(a), second(b) {
    placed_first = placed(*local, first);
    placed_second = placed(*local, second);
    const Vec3 at = transform_point(first, Vec3(0.0));
    std::uniform_real_distribution<double> u(-5, 5);
    for (int i = 0; i < 20; ++i) {
      centers.push_back(at + Vec3(u(rng), u(rng), u(rng)));
      center_radii.push_back(0.4);
      const Vec3 s = at + Vec3(u(rng), u(rng), u(rng));
      segments.push_back({s, s + Vec3(0.5, 0.2, 0.1)});
      segment_radii.push_back(0.25);
    }
    field::Arc arc;
    arc.center = at;
    arc.axis = {0, 0, 1};
    arc.start = {1, 0, 0};
    arc.radius = 2.0;
    arc.angle = 2.0;
    arcs.push_back(arc);
    arc_radii.push_back(0.3);
  }

  SupportSources sources() const {
    SupportSources s;
    s.sphere_centers = centers;
    s.sphere_radii = center_radii;
    s.capsules = segments;
    s.capsule_radii = segment_radii;
    s.arcs = arcs;
    s.arc_radii = arc_radii;
    s.triangle_groups = {{placed_first, kRadius}, {placed_second, kRadius}};
    return s;
  }

  // The same, the triangle groups as instances of `prebuilt`.
  SupportSources instanced(const std::shared_ptr<const TriangleSupports>& prebuilt) const {
    SupportSources s = sources();
    s.triangle_groups[0].prebuilt = prebuilt;
    s.triangle_groups[0].placement = first;
    s.triangle_groups[1].prebuilt = prebuilt;
    s.triangle_groups[1].placement = second;
    return s;
  }

  uint32_t triangle_base() const {
    return uint32_t(centers.size() + segments.size() + arcs.size());
  }

  Span brute_span(uint32_t id, const Vec3& o, const Vec3& d) const {
    if (id < centers.size()) return sphere_span(o, d, centers[id], center_radii[id]);
    id -= uint32_t(centers.size());
    if (id < segments.size()) return capsule_span(o, d, segments[id], segment_radii[id]);
    id -= uint32_t(segments.size());
    if (id < arcs.size()) return arc_span(o, d, arcs[id], arc_radii[id]);
    id -= uint32_t(arcs.size());
    if (id < placed_first.size()) return triangle_span(o, d, placed_first[id], kRadius);
    return triangle_span(o, d, placed_second[id - placed_first.size()], kRadius);
  }

  bool brute_contains(uint32_t id, const Vec3& p) const {
    if (id < centers.size()) return glm::dot(p - centers[id], p - centers[id]) < 0.16;
    id -= uint32_t(centers.size());
    if (id < segments.size()) return distance2_to_segment(p, segments[id]) < 0.0625;
    id -= uint32_t(segments.size());
    if (id < arcs.size()) return distance2_to_arc(p, arcs[id]) < 0.09;
    id -= uint32_t(arcs.size());
    if (id < placed_first.size()) return distance2_to_triangle(p, placed_first[id]) < 0.09;
    return distance2_to_triangle(p, placed_second[id - placed_first.size()]) < 0.09;
  }

  // A prebuilt hierarchy with the margin the index needs, rounded up to a power of two.
  std::shared_ptr<const TriangleSupports> prebuild() const {
    const double needed = required_instance_margin(support_bounds(sources()),
                                                   triangle_supports_bounds(*local, kRadius));
    return std::make_shared<TriangleSupports>(local, kRadius,
                                              std::exp2(std::ceil(std::log2(needed))));
  }
};

// A point just inside the first copy's support of triangle i, where it touches its box in the
// local space (the local vertex of largest x, plus R less a hair, along local x): there the
// float rounding of Embree's transform into the instance, not the support's shape, decides.
Vec3 grazing_point(const Scene& scene, size_t i, double hair) {
  const field::Triangle& t = (*scene.local)[i];
  Vec3 v = t.a;
  if (t.b.x > v.x) v = t.b;
  if (t.c.x > v.x) v = t.c;
  return transform_point(scene.first, v + Vec3(kRadius - hair, 0.0, 0.0));
}

bool by_primitive(const SupportInterval& a, const SupportInterval& b) {
  return a.primitive < b.primitive;
}

void expect_same_line_answers(const Scene& scene, const SupportIndex& index, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-9, 9);
  std::normal_distribution<double> n;
  const auto total = uint32_t(index.size());
  const Mat4 to_local = glm::inverse(scene.first);
  size_t found = 0, local_checked = 0, local_close = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Triangles& group = trial % 2 ? scene.placed_first : scene.placed_second;
    const Vec3 target = group[size_t(trial) * 7 % group.size()].a;
    Vec3 o = target + Vec3(u(rng), u(rng), u(rng));
    Vec3 d = glm::normalize(target - o + 0.2 * Vec3(n(rng), n(rng), n(rng)));
    if (trial % 4 == 3) {  // tangent to a support where it touches its box (local y)
      d = Vec3(scene.first * glm::dvec4(0, 1, 0, 0));
      o = grazing_point(scene, size_t(trial) * 11 % scene.local->size(), 1e-6) - 4.0 * d;
    }
    const double tmin = trial % 3 == 0 ? 0.0 : 1.0, tmax = trial % 5 == 0 ? 8.0 : INFINITY;
    std::vector<SupportInterval> got;
    index.intersect(o, d, tmin, tmax, got);
    std::sort(got.begin(), got.end(), by_primitive);
    std::vector<SupportInterval> expected;
    for (uint32_t id = 0; id < total; ++id) {
      const Span s = scene.brute_span(id, o, d);
      if (!s.empty() && s.exit >= tmin && s.enter <= tmax)
        expected.push_back({id, s.enter, s.exit});
    }
    ASSERT_EQ(got.size(), expected.size()) << "trial " << trial;
    for (size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].primitive, expected[i].primitive) << "trial " << trial;
      EXPECT_EQ(got[i].enter, expected[i].enter);
      EXPECT_EQ(got[i].exit, expected[i].exit);
      // The first copy's spans, measured on the local triangle along the line carried back
      // by the inverse placement: a rigid map keeps t. Both sides round the placement at the
      // size of the coordinates, which a grazing crossing amplifies: nearly all agree to
      // 1e-12 of that size, every one to 1e-7.
      const uint32_t local_id = got[i].primitive - scene.triangle_base();
      if (got[i].primitive < scene.triangle_base() || local_id >= scene.local->size()) continue;
      const Vec3 lo = transform_point(to_local, o);
      const Vec3 ld = Vec3(to_local * glm::dvec4(d, 0.0));
      const Span s = triangle_span(lo, ld, (*scene.local)[local_id], kRadius);
      const double size = 1.0 + glm::length(o) + std::abs(got[i].enter) + std::abs(got[i].exit);
      const double error =
          std::max(std::abs(s.enter - got[i].enter), std::abs(s.exit - got[i].exit));
      EXPECT_LE(error, 1e-7 * size);
      if (error <= 1e-12 * size) ++local_close;
      ++local_checked;
    }
    found += got.size();
  }
  EXPECT_GT(found, 4000u);
  EXPECT_GT(local_checked, 1000u);
  EXPECT_GE(double(local_close), 0.99 * double(local_checked));
}

void expect_same_point_answers(const Scene& scene, const SupportIndex& index, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  size_t found = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Triangles& group = trial % 2 ? scene.placed_first : scene.placed_second;
    Vec3 p =
        group[size_t(trial) * 13 % group.size()].b + Vec3(jitter(rng), jitter(rng), jitter(rng));
    if (trial % 4 == 3) p = grazing_point(scene, size_t(trial) * 11 % scene.local->size(), 1e-6);
    std::vector<uint32_t> got;
    index.contain(p, got);
    std::sort(got.begin(), got.end());
    std::vector<uint32_t> expected;
    for (uint32_t id = 0; id < index.size(); ++id) {
      if (scene.brute_contains(id, p)) expected.push_back(id);
    }
    ASSERT_EQ(got, expected) << "trial " << trial;
    found += got.size();
  }
  EXPECT_GT(found, 2000u);
}

// Both copies instanced, and the index built directly: the same answers as brute force.
void expect_instanced_matches(const Mat4& first, const Mat4& second, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Scene scene(rng, first, second);
  const SupportIndex instanced(scene.instanced(scene.prebuild()));
  ASSERT_EQ(instanced.instance_count(), 2u);
  const SupportIndex direct(scene.sources());
  ASSERT_EQ(direct.instance_count(), 0u);
  ASSERT_EQ(instanced.size(), direct.size());
  EXPECT_EQ(instanced.bounds().lo, direct.bounds().lo);
  EXPECT_EQ(instanced.bounds().hi, direct.bounds().hi);
  expect_same_line_answers(scene, instanced, seed + 1);
  expect_same_point_answers(scene, instanced, seed + 2);
  expect_same_line_answers(scene, direct, seed + 1);
}

TEST(SupportIndexInstances, IdentityPlacementAnswersAsBruteForce) {
  expect_instanced_matches(Mat4(1.0), rigid(90, {0, 0, 1}, {0, 0, 0}), 31);
}

TEST(SupportIndexInstances, RotatedAndMovedPlacementAnswersAsBruteForce) {
  expect_instanced_matches(rigid(37, {1, 2, 3}, {3.5, -2, 7}), rigid(-120, {0, 1, 0.3}, {4, 1, 6}),
                           32);
}

TEST(SupportIndexInstances, FarPlacementAnswersAsBruteForce) {
  // Coordinates of 1e4 against supports of 0.3: the float rays stray by about 1e-3 there.
  expect_instanced_matches(rigid(75, {0.2, 1, -0.4}, {1e4, -0.6e4, 0.8e4}),
                           rigid(10, {1, 0, 0}, {1e4 + 3, -0.6e4, 0.8e4 + 2}), 33);
}

TEST(SupportIndexInstances, TooSmallAMarginIsBuiltDirectlyInstead) {
  std::mt19937_64 rng(34);
  const Mat4 far = rigid(75, {0.2, 1, -0.4}, {1e4, -0.6e4, 0.8e4});
  const Scene scene(rng, far, far);
  // Sized for the mesh where it lies, not for where it is placed.
  const auto small = std::make_shared<TriangleSupports>(
      scene.local, kRadius,
      required_instance_margin(triangle_supports_bounds(*scene.local, kRadius),
                               triangle_supports_bounds(*scene.local, kRadius)));
  const SupportIndex index(scene.instanced(small));
  EXPECT_EQ(index.instance_count(), 0u);
  expect_same_line_answers(scene, index, 35);
  expect_same_point_answers(scene, index, 36);
}

TEST(SupportIndexInstances, NonRigidPlacementOrAnotherMeshIsRefused) {
  std::mt19937_64 rng(37);
  const Scene scene(rng, Mat4(1.0), Mat4(1.0));
  SupportSources scaled = scene.instanced(scene.prebuild());
  scaled.triangle_groups[0].placement = glm::scale(Mat4(1.0), Vec3(2.0));
  EXPECT_THROW(SupportIndex{scaled}, std::invalid_argument);
  SupportSources other = scene.instanced(scene.prebuild());
  other.triangle_groups[0].radius = 0.5;
  EXPECT_THROW(SupportIndex{other}, std::invalid_argument);
}

TEST(SupportIndexInstances, MemoryCountsThePlacedHierarchy) {
  std::mt19937_64 rng(38);
  const Scene scene(rng, Mat4(1.0), rigid(45, {0, 0, 1}, {1, 2, 3}));
  const auto prebuilt = scene.prebuild();
  EXPECT_GT(prebuilt->memory_bytes(), 1500 * 8u);  // at least a little per support
  const SupportIndex instanced(scene.instanced(prebuilt));
  EXPECT_GT(instanced.memory_bytes(), prebuilt->memory_bytes());
  const SupportIndex direct(scene.sources());
  EXPECT_GT(direct.memory_bytes(), prebuilt->memory_bytes());
}

}  // namespace
}  // namespace convray::accel
