// Line fans (accel/line_fans.hpp) against brute force: every line a fan serves gets exactly
// the balls that the ball-and-slab test keeps among all of them, and the index's answers
// through the fans are the exact spans of brute force, for camera-like lines through an eye,
// shadow-like lines through a light, lines that pass near but not through them, and random
// chunks of each.
#include "accel/line_fans.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <set>
#include <utility>

#include "accel/support_index.hpp"
#include "accel/support_shapes.hpp"
#include "core/spatial_order.hpp"

namespace convray::accel {
namespace {

struct Soup {
  std::vector<field::Triangle> a, b;  // two meshes: R = 0.3 and R = 0.1
};

Soup random_soup(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-2, 2), small(-0.4, 0.4);
  Soup s;
  for (int i = 0; i < count; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const Vec3 q = p + Vec3(small(rng), small(rng), small(rng));
    const Vec3 r = p + Vec3(small(rng), small(rng), small(rng));
    (i % 3 ? s.a : s.b).push_back({p, q, r});
  }
  return s;
}

// The lines of a tile of a camera at `eye` and of the shadow rays from their hits towards a
// light, interleaved as a renderer asks them, with lines that pass near the eye and the light
// (1e-3 and 1e-6 of a radius off) between; random chunks.
struct TestLine {
  Vec3 origin, direction;
  double tmin, tmax;
};
std::vector<TestLine> coherent_lines(std::mt19937_64& rng, const Vec3& eye, const Vec3& light,
                                     int size = 48) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<TestLine> lines;
  const Vec3 forward = glm::normalize(-eye);
  const Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward));
  const Vec3 up = glm::cross(forward, right);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = 0.1 * ((i + 0.5) / size - 0.5), y = 0.1 * ((j + 0.5) / size - 0.5);
      const Vec3 d = glm::normalize(forward + x * right + y * up);
      const double t0 = unit(rng) < 0.5 ? 0.0 : 8.0 * unit(rng);
      const double t1 = unit(rng) < 0.5 ? INFINITY : t0 + 4.0 * unit(rng);
      lines.push_back({eye, d, t0, t1});
      // A shadow ray from a point along the camera ray towards the light.
      const Vec3 point = eye + (glm::length(eye) - 1.0 + 2.0 * unit(rng)) * d;
      const Vec3 to_light = light - point;
      lines.push_back({point, glm::normalize(to_light), 1e-6, glm::length(to_light)});
      if ((i + j) % 7 == 0) {  // beside the eye, by a little and by a hair
        const double off = (i % 2 ? 1e-3 : 1e-6) * 0.3;
        lines.push_back({eye + off * right, d, t0, t1});
      }
    }
  }
  return lines;
}

// One source for each (triangles, radius) group; `balls` holds their bounding balls.
std::vector<detail::GeometrySource> sources_of(
    std::initializer_list<std::pair<const std::vector<field::Triangle>*, double>> groups,
    std::vector<std::vector<BoundingBall>>& balls) {
  std::vector<detail::GeometrySource> sources;
  uint32_t first = 0;
  for (const auto& [triangles, radius] : groups) {
    std::vector<BoundingBall>& b = balls.emplace_back();
    for (const field::Triangle& t : *triangles) b.push_back(triangle_bounding_ball(t, radius));
    detail::GeometrySource s{detail::GeometrySource::Kind::triangle};
    s.first_id = first;
    s.count = uint32_t(triangles->size());
    s.triangles = triangles->data();
    s.shared_radius = radius;
    first += s.count;
    sources.push_back(s);
  }
  for (size_t k = 0; k < sources.size(); ++k) sources[k].balls = balls[k].data();
  return sources;
}
std::vector<detail::GeometrySource> sources_of(const Soup& soup,
                                               std::vector<std::vector<BoundingBall>>& balls) {
  return sources_of({{&soup.a, 0.3}, {&soup.b, 0.1}}, balls);
}

Box3 bounds_of(const std::vector<detail::GeometrySource>& sources) {
  Box3 bounds;
  for (const detail::GeometrySource& s : sources) {
    for (uint32_t i = 0; i < s.count; ++i) {
      const Box3 box = s.support_box(i);
      bounds.extend(box.lo);
      bounds.extend(box.hi);
    }
  }
  return bounds;
}

// The exact spans of every triangle (brute force) that meet [tmin, tmax] of the line, by id.
std::vector<SupportInterval> brute_force_spans(const TestLine& l,
                                               const std::vector<field::Triangle>& a, double ra,
                                               const std::vector<field::Triangle>& b, double rb) {
  std::vector<SupportInterval> expected;
  for (uint32_t id = 0; id < a.size() + b.size(); ++id) {
    const bool in_a = id < a.size();
    const field::Triangle& t = in_a ? a[id] : b[id - a.size()];
    const Span s = triangle_span(l.origin, l.direction, t, in_a ? ra : rb);
    if (!s.empty() && s.exit >= l.tmin && s.enter <= l.tmax) {
      expected.push_back({id, s.enter, s.exit});
    }
  }
  return expected;
}

// The index's answers for `lines` against brute force; returns how many intervals they held.
size_t expect_exact_spans(const SupportIndex& index, const std::vector<TestLine>& lines,
                          const std::vector<field::Triangle>& a, double ra,
                          const std::vector<field::Triangle>& b, double rb) {
  size_t found_total = 0;
  for (const TestLine& l : lines) {
    std::vector<SupportInterval> got;
    index.intersect(l.origin, l.direction, l.tmin, l.tmax, got);
    std::sort(got.begin(), got.end(), [](auto& x, auto& y) { return x.primitive < y.primitive; });
    const std::vector<SupportInterval> expected = brute_force_spans(l, a, ra, b, rb);
    EXPECT_EQ(got.size(), expected.size());
    if (got.size() != expected.size()) return found_total;
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].primitive, expected[i].primitive);
      EXPECT_EQ(got[i].enter, expected[i].enter);
      EXPECT_EQ(got[i].exit, expected[i].exit);
    }
    found_total += got.size();
  }
  return found_total;
}

TEST(LineFans, ServedLinesGetEveryBallTheTestKeeps) {
  std::mt19937_64 rng(48);
  const Soup soup = random_soup(rng, 600);
  std::vector<std::vector<BoundingBall>> balls;
  balls.reserve(2);
  const std::vector<detail::GeometrySource> sources = sources_of(soup, balls);
  const LineFans fans(sources, bounds_of(sources));
  size_t served = 0, lines = 0, kept = 0;
  for (const Vec3 eye : {Vec3(0.3, 1.5, -9.0), Vec3(-7.0, 2.0, 1.0)}) {
    for (const TestLine& l : coherent_lines(rng, eye, Vec3(-5.0, 9.0, -6.0))) {
      std::vector<detail::TriangleCandidate> got;
      ++lines;
      if (!fans.candidates({l.origin, l.direction, l.tmin, l.tmax}, got)) continue;
      ++served;
      std::set<std::pair<const detail::GeometrySource*, uint32_t>> expected, found;
      for (const detail::GeometrySource& s : sources) {
        for (uint32_t i = 0; i < s.count; ++i) {
          if (may_cross(l.origin, l.direction, l.tmin, l.tmax, s.balls[i]))
            expected.insert({&s, i});
        }
      }
      for (const auto& c : got) found.insert({c.source, c.primitive});
      ASSERT_EQ(found.size(), got.size()) << "a ball listed twice, line " << lines;
      ASSERT_EQ(found, expected) << "line " << lines;
      kept += got.size();
    }
  }
  EXPECT_GT(served, lines * 8 / 10);
  EXPECT_GT(kept, served);  // the lines do cross supports
}

TEST(LineFans, IndexAnswersThroughFansAreTheExactSpans) {
  std::mt19937_64 rng(49);
  const Soup soup = random_soup(rng, 900);
  SupportSources sources;
  sources.triangle_groups = {{soup.a, 0.3}, {soup.b, 0.1}};
  const SupportIndex index(sources);
  const size_t found_total =
      expect_exact_spans(index, coherent_lines(rng, Vec3(0.5, 2.0, -8.0), Vec3(6.0, 8.0, -3.0)),
                         soup.a, 0.3, soup.b, 0.1);
  EXPECT_GT(found_total, 2000u);
}

// The exact spans keep each thread's last two gathers of triangles and reuse one where a
// line's candidates are the same. Lines asked of two indices in turn (the same ids, other
// corners), each line twice, and one index made again (likely where the freed one stood):
// each answer is its own index's brute force.
TEST(LineFans, KeptGathersNeverServeAnotherIndex) {
  std::mt19937_64 rng(51);
  const Soup first = random_soup(rng, 300);
  Soup second = first;
  for (auto* mesh : {&second.a, &second.b}) {
    for (field::Triangle& t : *mesh) t = {t.a * 0.9, t.b * 0.9, t.c * 0.9};
  }
  const auto index_of = [](const Soup& soup) {
    SupportSources sources;
    sources.triangle_groups = {{soup.a, 0.3}, {soup.b, 0.1}};
    return std::make_unique<SupportIndex>(sources);
  };
  std::unique_ptr<SupportIndex> a = index_of(first);
  const std::unique_ptr<SupportIndex> b = index_of(second);
  size_t found = 0;
  for (int round = 0; round < 2; ++round) {
    const std::vector<TestLine> lines =
        coherent_lines(rng, Vec3(0.5, 2.0, -8.0), Vec3(6.0, 8.0, -3.0), 12);
    for (const TestLine& line : lines) {
      const std::vector<TestLine> one{line, line};
      found += expect_exact_spans(*a, one, first.a, 0.3, first.b, 0.1);
      found += expect_exact_spans(*b, one, second.a, 0.3, second.b, 0.1);
    }
    a.reset();
    a = index_of(first);
  }
  EXPECT_GT(found, 1000u);
}

// More triangles than kFanBalls: fans only where a line meets many balls (here wide ones,
// about 200 a line), and then the same exact spans as brute force.
TEST(LineFans, BigMeshesWithWideSupportsHaveFansAndTheExactSpans) {
  std::mt19937_64 rng(50);
  std::uniform_real_distribution<double> u(-2, 2), small(-0.08, 0.08);
  std::vector<field::Triangle> triangles;
  while (triangles.size() < LineFans::kFanBalls + 600) {
    const Vec3 p(u(rng), u(rng), u(rng));
    triangles.push_back({p, p + Vec3(small(rng), small(rng), small(rng)),
                         p + Vec3(small(rng), small(rng), small(rng))});
  }
  // In spatial order, as a scene's meshes are (scene/mesh_skeleton.cpp): the fans' blocks
  // are then tight.
  std::vector<Vec3> centres;
  for (const field::Triangle& t : triangles) centres.push_back((t.a + t.b + t.c) / 3.0);
  std::vector<field::Triangle> ordered;
  for (uint32_t k : spatial_order(centres)) ordered.push_back(triangles[k]);
  triangles = ordered;
  const std::vector<field::Triangle> none;
  for (const double radius : {0.3, 0.02}) {
    std::vector<std::vector<BoundingBall>> balls;
    const std::vector<detail::GeometrySource> sources = sources_of({{&triangles, radius}}, balls);
    const bool wide = radius > 0.1;
    EXPECT_EQ(LineFans::worth_making(sources, bounds_of(sources)), wide) << radius;
    SupportSources groups;
    groups.triangle_groups = {{triangles, radius}};
    const SupportIndex index(groups);
    const size_t found = expect_exact_spans(
        index, coherent_lines(rng, Vec3(0.5, 2.0, -8.0), Vec3(6.0, 8.0, -3.0), 10), triangles,
        radius, none, 0.0);
    EXPECT_GT(found, wide ? 10000u : 10u) << radius;
  }
}

// Cauchy's formula against random lines: directions uniform on the sphere, each line's
// offset uniform over the plane across it, kept where it meets the bounds; the mean number of
// balls within their radius of the line.
TEST(LineFans, BallsPerLineIsTheMeanOverRandomLines) {
  std::mt19937_64 rng(51);
  std::uniform_real_distribution<double> u(-2, 2), small(-0.3, 0.3), unit(0.0, 1.0);
  std::vector<field::Triangle> triangles;
  for (int i = 0; i < 400; ++i) {
    const Vec3 p(u(rng), 0.5 * u(rng), u(rng));
    triangles.push_back({p, p + Vec3(small(rng), small(rng), small(rng)),
                         p + Vec3(small(rng), small(rng), small(rng))});
  }
  std::vector<std::vector<BoundingBall>> balls;
  const auto sources = sources_of({{&triangles, 0.2}}, balls);
  const Box3 bounds = bounds_of(sources);
  const Vec3 centre = 0.5 * (bounds.lo + bounds.hi);
  const double reach = 0.5 * glm::length(bounds.hi - bounds.lo);
  double met = 0.0;
  int lines = 0;
  while (lines < 20000) {
    const double z = 2.0 * unit(rng) - 1.0, phi = 2.0 * kPi * unit(rng);
    const Vec3 d(std::sqrt(1.0 - z * z) * std::cos(phi), std::sqrt(1.0 - z * z) * std::sin(phi), z);
    const Vec3 e1 =
        glm::normalize(glm::cross(d, std::abs(d.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 e2 = glm::cross(d, e1);
    const Vec3 o = centre + reach * ((2.0 * unit(rng) - 1.0) * e1 + (2.0 * unit(rng) - 1.0) * e2);
    // Through the box? (slabs)
    double t0 = -kInfinity, t1 = kInfinity;
    for (int k = 0; k < 3; ++k) {
      if (d[k] == 0.0) continue;
      const double a = (bounds.lo[k] - o[k]) / d[k], b = (bounds.hi[k] - o[k]) / d[k];
      t0 = std::max(t0, std::min(a, b));
      t1 = std::min(t1, std::max(a, b));
    }
    if (!(t0 <= t1)) continue;
    ++lines;
    for (const BoundingBall& ball : balls[0]) {
      const Vec3 w = Vec3(ball.center[0], ball.center[1], ball.center[2]) - o;
      const double along = glm::dot(w, d);
      met += glm::dot(w, w) - along * along <= double(ball.radius) * ball.radius ? 1.0 : 0.0;
    }
  }
  // Balls that reach past the bounds meet some lines that miss them: a few percent.
  EXPECT_NEAR(met / lines, LineFans::balls_per_line(sources, bounds),
              0.08 * LineFans::balls_per_line(sources, bounds));
}

}  // namespace
}  // namespace convray::accel
