// The search for F = T along one lattice edge (edge_root.hpp) on fields written out by hand:
// the quartic kernel of the distance to a point (its level set a sphere, so the crossing is a
// line-sphere intersection solved here), a linear field, a field read through a perturbed
// approximation, and a truncated field that jumps across T.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygonize/edge_root.hpp"

namespace convray::polygonize {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// (1 - |p - c|^2 / R^2)^2 inside the ball, 0 outside, with its gradient.
field::FieldSample kernel(const Vec3& p, const Vec3& c, double R) {
  const Vec3 d = p - c;
  const double x = 1.0 - glm::dot(d, d) / (R * R);
  if (x <= 0.0) return {};
  return {x * x, (-4.0 * x / (R * R)) * d};
}

// Where the segment a -> b meets the sphere |p - c| = rho, the one t in [0, 1].
double segment_sphere(const Vec3& a, const Vec3& b, const Vec3& c, double rho) {
  const Vec3 d = b - a, w = a - c;
  const double A = glm::dot(d, d), B = glm::dot(w, d), C = glm::dot(w, w) - rho * rho;
  const double root = std::sqrt(B * B - A * C);
  const double t1 = (-B - root) / A, t2 = (-B + root) / A;
  return t1 >= 0.0 && t1 <= 1.0 ? t1 : t2;
}

// The distance from p to the segment a -> b, and where along it p projects.
double off_segment(const Vec3& p, const Vec3& a, const Vec3& b, double& t) {
  t = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
  return glm::length(p - (a + t * (b - a)));
}

TEST(EdgeRoot, FindsTheLevelSphereOfThePointKernel) {
  std::mt19937_64 rng(1481);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int evaluations = 0, cases = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 c = 10.0 * random_unit(rng);
    const double R = 0.1 + 3.0 * unit(rng), T = 0.02 + 0.9 * unit(rng);
    const double rho = R * std::sqrt(1.0 - std::sqrt(T));  // (1 - rho^2/R^2)^2 = T
    FieldSource source;
    source.field = [&](const Vec3& p) { return kernel(p, c, R); };
    source.threshold = T;
    // One end inside the level sphere, the other outside (beyond the support, sometimes).
    const Vec3 in = c + rho * unit(rng) * random_unit(rng);
    const Vec3 out = c + rho * (1.0 + (i % 4 ? 0.3 : 2.0) * (0.01 + unit(rng))) * random_unit(rng);
    const bool forward = i % 2;
    const Vec3 a = forward ? in : out, b = forward ? out : in;
    const double tolerance = i % 3 ? 1e-7 : 1e-12;
    const EdgeRoot root =
        find_edge_root(source, a, kernel(a, c, R).value, b, kernel(b, c, R).value, tolerance);
    ++cases;
    evaluations += root.evaluations;
    EXPECT_TRUE(root.converged) << i;
    const field::FieldSample exact = kernel(root.position, c, R);
    EXPECT_LE(std::abs(exact.value - T), tolerance * T) << i;
    EXPECT_EQ(root.sample.value, exact.value) << i;
    EXPECT_EQ(root.sample.gradient, exact.gradient) << i;
    // On the edge, at the line-sphere intersection to within what the tolerance allows
    // (|F - T| over the field's slope along the edge, with room for rounding).
    double t = 0.0;
    EXPECT_LE(off_segment(root.position, a, b, t), 1e-12 * (10.0 + R)) << i;
    EXPECT_GT(t, 0.0);
    EXPECT_LT(t, 1.0);
    const double t_exact = segment_sphere(a, b, c, rho);
    const double slope = std::abs(glm::dot(exact.gradient, b - a));
    EXPECT_NEAR(t, t_exact, 2.0 * tolerance * T / slope + 1e-13) << i;
  }
  // Superlinear: far fewer evaluations than bisection to 1e-7 or 1e-12 (24 to 40 halvings).
  std::printf("mean evaluations %.2f\n", double(evaluations) / cases);
  EXPECT_LT(double(evaluations) / cases, 15.0);
}

// A linear field is solved by the first regula falsi step.
TEST(EdgeRoot, LinearFieldInOneStep) {
  std::mt19937_64 rng(1482);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Vec3 a = random_unit(rng), b = a + random_unit(rng);
    const double t_root = 0.01 + 0.98 * unit(rng), T = 0.5;
    const Vec3 g = (b - a) / glm::dot(b - a, b - a);  // F rises by 1 from a to b
    const Vec3 at_root = a + t_root * (b - a);
    FieldSource source;
    source.field = [&](const Vec3& p) {
      return field::FieldSample{T + glm::dot(p - at_root, g), g};
    };
    source.threshold = T;
    const EdgeRoot root =
        find_edge_root(source, a, source.field(a).value, b, source.field(b).value, 1e-9);
    EXPECT_TRUE(root.converged);
    EXPECT_LE(root.evaluations, 3) << i;  // one search step, one exact sample (+ a polish)
    EXPECT_LE(glm::length(root.position - at_root), 1e-9) << i;
  }
}

// The search reads an approximation of F (off by up to 1e-4 T, smoothly); the answer is on
// the exact field all the same.
TEST(EdgeRoot, ApproximateValuesStillEndOnTheExactField) {
  std::mt19937_64 rng(1483);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int converged = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 c(0.0);
    const double R = 1.0, T = 0.1 + 0.8 * unit(rng);
    const double rho = R * std::sqrt(1.0 - std::sqrt(T));
    FieldSource source;
    source.field = [&](const Vec3& p) { return kernel(p, c, R); };
    source.value = [&](const Vec3& p) {
      return kernel(p, c, R).value + 1e-4 * T * std::sin(7.0 * p.x + 3.0 * p.y);
    };
    source.threshold = T;
    const Vec3 a = rho * 0.5 * unit(rng) * random_unit(rng);
    const Vec3 b = rho * (1.05 + unit(rng)) * random_unit(rng);
    const EdgeRoot root =
        find_edge_root(source, a, source.value_at(a), b, source.value_at(b), 1e-9);
    converged += root.converged;
    EXPECT_LE(std::abs(kernel(root.position, c, R).value - T), 1e-9 * T) << i;
    double t = 0.0;
    EXPECT_LE(off_segment(root.position, a, b, t), 1e-12);
    EXPECT_NEAR(t, segment_sphere(a, b, c, rho), 1e-8) << i;
  }
  EXPECT_EQ(converged, 1000);
}

// A field that jumps across T (a truncated kernel) has no crossing to converge on: the search
// closes in on the jump and says it did not converge.
TEST(EdgeRoot, AJumpIsBracketedAndReportedNotConverged) {
  for (double jump : {0.3, 0.5, 0.999, 1e-3}) {
    const double T = 1.0;
    FieldSource source;
    source.field = [&](const Vec3& p) {
      return field::FieldSample{p.x < jump ? 2.0 * T : 0.0, Vec3(0.0)};
    };
    source.threshold = T;
    const Vec3 a(0.0), b(1.0, 0.0, 0.0);
    const EdgeRoot root = find_edge_root(source, a, 2.0 * T, b, 0.0, 1e-7);
    EXPECT_FALSE(root.converged) << jump;
    EXPECT_NEAR(root.position.x, jump, 1e-12) << jump;
    EXPECT_LE(root.evaluations, 110) << jump;
  }
}

// A crossing (almost) on an end: the answer stays a hair inside the edge, never on the
// lattice point itself.
TEST(EdgeRoot, TheAnswerStaysInsideTheEdge) {
  for (double t_root : {0.0, 1e-15, 1e-11, 1.0 - 1e-12, 1.0}) {
    const double T = 1.0;
    FieldSource source;
    // Falls from a to b, T at t_root (the field exactly T at an end counts as inside).
    source.field = [&](const Vec3& p) {
      return field::FieldSample{T - (p.x - t_root), Vec3(-1, 0, 0)};
    };
    source.threshold = T;
    const Vec3 a(0.0), b(1.0, 0.0, 0.0);
    const double fa = source.field(a).value,
                 fb = std::min(source.field(b).value, T * (1.0 - 1e-16));
    const EdgeRoot root = find_edge_root(source, a, fa, b, fb, 1e-7);
    EXPECT_GE(root.position.x, 1e-9 * (1.0 - 1e-12)) << t_root;
    EXPECT_LE(root.position.x, 1.0 - 1e-9 * (1.0 - 1e-6)) << t_root;
    EXPECT_NE(root.position, a);
    EXPECT_NE(root.position, b);
    EXPECT_TRUE(root.converged) << t_root;  // within 1e-9 of the end: |F - T| <= 1e-9 < 1e-7 T
  }
}

}  // namespace
}  // namespace convray::polygonize
