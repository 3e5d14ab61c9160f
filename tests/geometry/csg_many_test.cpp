// CSG of many members (1 to 10^4) against a brute-force loop over the members, each built
// alone: the same crossings (distance, normal), the same first crossing, the same inside
// answers. The loop applies POV-Ray's rules itself (csg.hpp), with no hierarchy, so it checks
// both the rules and the hierarchies that make CsgShape cost log n per ray.
#include <gtest/gtest.h>

#include "core/box.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using scene::CsgOperation;
using testing::make_object;

// Random members, spheres and boxes (some rotated), laid out so that the operation keeps
// something: overlapping clutter for union and merge, nested solids for intersection, a
// block with clutter in and around it for difference.
std::vector<scene::ObjectPtr> members(CsgOperation op, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.3, 0.8), angle(0.0, 90.0);
  const double spread = 0.6 * std::cbrt(double(n));
  std::vector<scene::ObjectPtr> out;
  for (int i = 0; i < n; ++i) {
    Vec3 center(u(rng), u(rng), u(rng));
    double radius = size(rng);
    if (op == CsgOperation::intersection) {
      center *= 0.3;
      radius += 1.0;  // every member holds the ball of radius 0.6 about the origin
    } else {
      center *= spread;
    }
    if (op == CsgOperation::difference && i == 0) {
      out.push_back(make_object(scene::Box{Vec3(-0.8 * spread), Vec3(0.8 * spread)}));
    } else if (i % 3 == 2) {
      const Vec3 half(radius / std::sqrt(2.0));  // a box inside the sphere it stands for
      out.push_back(make_object(scene::Box{-half, half},
                                scene::Transform::rotation({angle(rng), angle(rng), 0.0})
                                    .then(scene::Transform::translation(center))));
    } else {
      out.push_back(make_object(scene::Sphere{center, radius}));
    }
  }
  return out;
}

// POV-Ray's rules over the members, one after the other (csg.hpp).
struct BruteForce {
  CsgOperation op;
  std::vector<ShapePtr> shapes;

  bool inside_but(const Vec3& p, size_t skip, bool want_all) const {
    for (size_t j = 0; j < shapes.size(); ++j) {
      if (j == skip) continue;
      if (shapes[j]->inside(p) != want_all) return !want_all;
    }
    return want_all;
  }
  bool keeps(size_t from, const Vec3& p) const {
    switch (op) {
      case CsgOperation::union_: return true;
      case CsgOperation::merge: return !inside_but(p, from, false);
      case CsgOperation::intersection: return inside_but(p, from, true);
      case CsgOperation::difference:
        for (size_t j = 0; j < shapes.size(); ++j) {
          if (j != from && (j == 0) != shapes[j]->inside(p)) return false;
        }
        return true;
    }
    return false;
  }
  bool inside(const Vec3& p) const {
    if (shapes.empty()) return false;
    switch (op) {
      case CsgOperation::union_:
      case CsgOperation::merge: return inside_but(p, size_t(-1), false);
      case CsgOperation::intersection: return inside_but(p, size_t(-1), true);
      case CsgOperation::difference:
        return shapes[0]->inside(p) && !inside_but(p, 0, false);
    }
    return false;
  }
  std::vector<Crossing> crossings(const Ray& ray, double tmin, double tmax) const {
    std::vector<std::pair<Crossing, size_t>> all;
    TraceStats stats;
    for (size_t i = 0; i < shapes.size(); ++i) {
      std::vector<Crossing> found;
      shapes[i]->crossings(ray, tmin, tmax, found, stats);
      for (const Crossing& c : found) all.emplace_back(c, i);
    }
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& a, const auto& b) { return a.first.t < b.first.t; });
    std::vector<Crossing> kept;
    for (auto& [c, i] : all) {
      if (!keeps(i, ray.at(c.t))) continue;
      if (op == CsgOperation::difference && i > 0) c.normal = -c.normal;
      kept.push_back(c);
    }
    return kept;
  }
};

void check(CsgOperation op, int n, int rays, uint64_t seed) {
  const std::vector<scene::ObjectPtr> children = members(op, n, seed);
  const ShapePtr csg = build_shape(*make_object(scene::Csg{op, children}));
  BruteForce reference{op, {}};
  for (const scene::ObjectPtr& child : children) reference.shapes.push_back(build_shape(*child));

  std::mt19937_64 rng(seed + 1);
  // Rays from well outside, aimed at the members (intersection's are all near the origin).
  const double spread = op == CsgOperation::intersection ? 2.0 : 0.6 * std::cbrt(double(n)) + 0.8;
  TraceStats stats;
  int with_crossings = 0, inside_points = 0;
  for (int i = 0; i < rays; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 3.0 * spread + 2.0, spread);
    const double tmax = 6.0 * spread + 4.0;
    std::vector<Crossing> fast;
    csg->crossings(ray, 0.0, tmax, fast, stats);
    const std::vector<Crossing> slow = reference.crossings(ray, 0.0, tmax);
    ASSERT_EQ(fast.size(), slow.size()) << "ray " << i;
    for (size_t k = 0; k < fast.size(); ++k) {
      EXPECT_EQ(fast[k].t, slow[k].t) << "ray " << i << " crossing " << k;
      EXPECT_EQ(fast[k].normal, slow[k].normal) << "ray " << i << " crossing " << k;
    }
    with_crossings += !slow.empty();
    const auto first = csg->first_crossing(ray, 0.0, tmax, stats);
    ASSERT_EQ(first.has_value(), !slow.empty()) << "ray " << i;
    if (first) {
      EXPECT_EQ(first->t, slow.front().t);
      EXPECT_EQ(first->normal, slow.front().normal);
    }
    // Inside at points along the ray: where members begin and end, and between.
    std::uniform_real_distribution<double> along(0.0, tmax);
    for (int k = 0; k < 8; ++k) {
      const Vec3 p = ray.at(along(rng));
      const bool expected = reference.inside(p);
      EXPECT_EQ(csg->inside(p), expected) << "ray " << i << " point " << k;
      inside_points += expected;
    }
  }
  // The random members must make a case worth checking.
  EXPECT_GT(with_crossings, rays / 10);
  if (op != CsgOperation::intersection || n < 100) {
    EXPECT_GT(inside_points, 0);
  }
}

class CsgMany : public ::testing::TestWithParam<std::tuple<CsgOperation, int>> {};

TEST_P(CsgMany, MatchesBruteForceOverTheMembers) {
  const auto [op, n] = GetParam();
  // Fewer rays where the brute force is slow: its cost is rays x members.
  const int rays = n >= 10000 ? 100 : (n >= 1000 ? 300 : 1000);
  check(op, n, rays, 100 + uint64_t(n) + 7 * uint64_t(op));
}

std::string case_name(const ::testing::TestParamInfo<std::tuple<CsgOperation, int>>& info) {
  static const char* names[] = {"Union", "Intersection", "Difference", "Merge"};
  return std::string(names[int(std::get<0>(info.param))]) + "Of" +
         std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(
    EveryOperation, CsgMany,
    ::testing::Combine(::testing::Values(CsgOperation::union_, CsgOperation::merge,
                                         CsgOperation::intersection, CsgOperation::difference),
                       ::testing::Values(1, 2, 3, 10, 100, 1000, 10000)),
    case_name);

// Unbounded members (a plane, an inverted sphere) sit outside the hierarchy and are always
// asked.
TEST(CsgMany, UnboundedMembersAreAlwaysAsked) {
  for (CsgOperation op : {CsgOperation::union_, CsgOperation::merge, CsgOperation::intersection,
                          CsgOperation::difference}) {
    std::vector<scene::ObjectPtr> children = members(op, 200, 7);
    children.push_back(make_object(scene::Plane{{0.2, 1, 0.1}, 0.5}));
    auto inverted = make_object(scene::Sphere{{0.1, 0, 0}, 0.2});
    inverted->inverse = true;
    children.insert(children.begin() + 1, inverted);
    const ShapePtr csg = build_shape(*make_object(scene::Csg{op, children}));
    BruteForce reference{op, {}};
    for (const auto& child : children) reference.shapes.push_back(build_shape(*child));
    std::mt19937_64 rng(8);
    TraceStats stats;
    for (int i = 0; i < 300; ++i) {
      const Ray ray = testing::random_ray(rng, {0, 0, 0}, 12.0, 5.0);
      std::vector<Crossing> fast;
      csg->crossings(ray, 0.0, 30.0, fast, stats);
      const auto slow = reference.crossings(ray, 0.0, 30.0);
      ASSERT_EQ(fast.size(), slow.size()) << i;
      for (size_t k = 0; k < fast.size(); ++k) EXPECT_EQ(fast[k].t, slow[k].t);
      const Vec3 p = ray.at(std::uniform_real_distribution<double>(0.0, 30.0)(rng));
      EXPECT_EQ(csg->inside(p), reference.inside(p)) << i;
    }
  }
}

}  // namespace
}  // namespace convray::geometry
