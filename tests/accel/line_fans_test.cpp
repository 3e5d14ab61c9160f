// Line fans (accel/line_fans.hpp) against brute force: every line a fan serves gets exactly
// the balls that the ball-and-slab test keeps among all of them, and the index's answers
// through the fans are the exact spans of brute force, for camera-like lines through an eye,
// shadow-like lines through a light, lines that pass near but not through them, and random
// chunks of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

#include "accel/line_fans.hpp"
#include "accel/support_index.hpp"
#include "accel/support_shapes.hpp"

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
std::vector<TestLine> coherent_lines(std::mt19937_64& rng, const Vec3& eye, const Vec3& light) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<TestLine> lines;
  const Vec3 forward = glm::normalize(-eye);
  const Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward));
  const Vec3 up = glm::cross(forward, right);
  const int size = 48;
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

std::vector<detail::GeometrySource> sources_of(const Soup& soup,
                                               std::vector<std::vector<BoundingBall>>& balls) {
  std::vector<detail::GeometrySource> sources;
  const std::pair<const std::vector<field::Triangle>*, double> groups[] = {{&soup.a, 0.3},
                                                                           {&soup.b, 0.1}};
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

TEST(LineFans, ServedLinesGetEveryBallTheTestKeeps) {
  std::mt19937_64 rng(48);
  const Soup soup = random_soup(rng, 600);
  std::vector<std::vector<BoundingBall>> balls;
  balls.reserve(2);
  const std::vector<detail::GeometrySource> sources = sources_of(soup, balls);
  Box3 bounds;
  for (const detail::GeometrySource& s : sources) {
    for (uint32_t i = 0; i < s.count; ++i) {
      const Box3 box = s.support_box(i);
      bounds.extend(box.lo);
      bounds.extend(box.hi);
    }
  }
  const LineFans fans(sources, bounds);
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
          if (may_cross(l.origin, l.direction, l.tmin, l.tmax, s.balls[i])) expected.insert({&s, i});
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
  size_t found_total = 0;
  for (const TestLine& l : coherent_lines(rng, Vec3(0.5, 2.0, -8.0), Vec3(6.0, 8.0, -3.0))) {
    std::vector<SupportInterval> got;
    index.intersect(l.origin, l.direction, l.tmin, l.tmax, got);
    std::sort(got.begin(), got.end(), [](auto& a, auto& b) { return a.primitive < b.primitive; });
    std::vector<SupportInterval> expected;
    for (uint32_t id = 0; id < soup.a.size() + soup.b.size(); ++id) {
      const bool in_a = id < soup.a.size();
      const field::Triangle& t = in_a ? soup.a[id] : soup.b[id - soup.a.size()];
      const Span s = triangle_span(l.origin, l.direction, t, in_a ? 0.3 : 0.1);
      if (!s.empty() && s.exit >= l.tmin && s.enter <= l.tmax) {
        expected.push_back({id, s.enter, s.exit});
      }
    }
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].primitive, expected[i].primitive);
      EXPECT_EQ(got[i].enter, expected[i].enter);
      EXPECT_EQ(got[i].exit, expected[i].exit);
    }
    found_total += got.size();
  }
  EXPECT_GT(found_total, 2000u);
}

}  // namespace
}  // namespace convray::accel
