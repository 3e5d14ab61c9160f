// The sphere sweep (sphere_sweep.hpp) called directly, on chords computed here, against the
// blob field written out by hand and root-bracketed on a fine grid then bisected: shuffled
// supports, pieces of rays, first roots with their gradient, tangent chords, and chains of
// thousands of spheres whose running sum is rebuilt many times along the way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "implicit/convolution_surface.hpp"
#include "implicit/sphere_sweep.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// Where the ray crosses each sphere's ball: the chord around the closest approach tc, from
// the distance of the closest point (not b^2 - c, which cancels far from the origin).
std::vector<accel::SupportInterval> chords(const scene::ConvolutionObject& o, const Ray& ray) {
  std::vector<accel::SupportInterval> out;
  for (uint32_t i = 0; i < o.blob_spheres.size(); ++i) {
    const auto& s = o.blob_spheres[i];
    const double tc = glm::dot(s.center - ray.origin, ray.direction);
    const Vec3 offset = ray.at(tc) - s.center;
    const double h2 = s.weight.radius * s.weight.radius - glm::dot(offset, offset);
    if (h2 < 0.0) continue;
    out.push_back({i, tc - std::sqrt(h2), tc + std::sqrt(h2)});
  }
  return out;
}

// sum s (1 - d^2/r^2)^2 - T over the spheres listed, at ray.at(t).
double field_by_hand(const scene::ConvolutionObject& o, const std::vector<uint32_t>& ids, const Ray& ray,
                     double t) {
  double sum = 0.0;
  for (uint32_t i : ids) {
    const auto& s = o.blob_spheres[i];
    const Vec3 d = ray.at(t) - s.center;
    const double k = 1.0 - glm::dot(d, d) / (s.weight.radius * s.weight.radius);
    if (k > 0.0) sum += s.weight.strength * k * k;
  }
  return sum - o.threshold;
}

// Sign changes of g on a grid of `steps` over [t0, t1], each bisected to adjacent doubles.
template <class G>
std::vector<double> bracketed_roots(const G& g, double t0, double t1, int steps) {
  std::vector<double> roots;
  double a = t0, ga = g(a);
  for (int i = 1; i <= steps; ++i) {
    const double b = i == steps ? t1 : t0 + (t1 - t0) * i / steps, gb = g(b);
    if ((ga < 0.0) != (gb < 0.0)) {
      double lo = a, hi = b, glo = ga;
      while (0.5 * (lo + hi) > lo && 0.5 * (lo + hi) < hi) {
        const double mid = 0.5 * (lo + hi), gm = g(mid);
        if ((gm < 0.0) == (glo < 0.0)) {
          lo = mid;
          glo = gm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    ga = gb;
  }
  return roots;
}

std::vector<double> sweep(const ConvolutionSurface& surface, const Ray& ray,
                          std::vector<accel::SupportInterval> supports, double tmin, double tmax,
                          RootMode mode = RootMode::all, std::optional<Vec3>* gradient = nullptr) {
  const SphereSweepRequest request{ray, mode, gradient};
  std::vector<double> out;
  TraceStats stats;
  sweep_spheres(surface.impl(), request, supports, tmin, tmax, out, stats);
  return out;
}

scene::ConvolutionObject random_blob(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-2.0, 2.0), radius(0.4, 1.0), positive(0.5, 1.5),
      negative(-1.0, -0.3), coin(0.0, 1.0);
  scene::ConvolutionObject o;
  for (int i = 0; i < count; ++i) {
    const double s = coin(rng) < 0.2 ? negative(rng) : positive(rng);
    o.blob_spheres.push_back({{u(rng), u(rng), u(rng)}, {s, radius(rng)}});
  }
  o.threshold = 0.4;
  return o;
}

// Supports in any order, any piece [tmin, tmax] of the ray: the roots of the hand-written field.
TEST(SphereSweep, RootsAreThoseOfTheHandWrittenField) {
  std::mt19937_64 rng(1431);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, rays = 0;
  for (int scene = 0; scene < 6; ++scene) {
    const scene::ConvolutionObject o = random_blob(rng, 40);
    const ConvolutionSurface surface(o);
    ASSERT_TRUE(surface.impl().spheres_only);
    for (int i = 0; i < 60; ++i) {
      const Vec3 origin = 5.0 * random_unit(rng);
      const Ray ray{origin, glm::normalize(1.5 * random_unit(rng) - origin)};
      std::vector<accel::SupportInterval> supports = chords(o, ray);
      if (supports.empty()) continue;
      std::shuffle(supports.begin(), supports.end(), rng);
      double lo = INFINITY, hi = -INFINITY;
      std::vector<uint32_t> ids;
      for (const auto& s : supports) {
        lo = std::min(lo, s.enter);
        hi = std::max(hi, s.exit);
        ids.push_back(s.primitive);
      }
      // Half the rays whole, half cut to a piece that may start or end inside the solid.
      double tmin = lo - 0.1, tmax = hi + 0.1;
      if (i % 2) {
        tmin = lo + (hi - lo) * unit(rng);
        tmax = tmin + (hi - tmin) * unit(rng);
      }
      ++rays;
      const std::vector<double> roots = sweep(surface, ray, supports, tmin, tmax);
      const std::vector<double> expected = bracketed_roots(
          [&](double t) { return field_by_hand(o, ids, ray, t); }, tmin, tmax, 20000);
      ASSERT_EQ(roots.size(), expected.size()) << scene << " " << i;
      for (size_t k = 0; k < roots.size(); ++k) {
        EXPECT_NEAR(roots[k], expected[k], 1e-12) << scene << " " << i;
        EXPECT_GE(roots[k], tmin);
        EXPECT_LE(roots[k], tmax);
      }
      compared += int(roots.size());
    }
  }
  EXPECT_GT(rays, 300);
  EXPECT_GT(compared, 400);
}

// RootMode first: the first of all the roots, with the gradient of the field there from the
// spheres the sweep holds: the hand-written gradient -4 s k / r^2 (p - c) summed over all.
TEST(SphereSweep, FirstRootComesWithTheExactGradient) {
  std::mt19937_64 rng(1432);
  int found = 0;
  for (int scene = 0; scene < 6; ++scene) {
    const scene::ConvolutionObject o = random_blob(rng, 40);
    const ConvolutionSurface surface(o);
    for (int i = 0; i < 80; ++i) {
      const Vec3 origin = 5.0 * random_unit(rng);
      const Ray ray{origin, glm::normalize(1.5 * random_unit(rng) - origin)};
      const std::vector<accel::SupportInterval> supports = chords(o, ray);
      const std::vector<double> all = sweep(surface, ray, supports, 0.0, INFINITY);
      std::optional<Vec3> gradient;
      const std::vector<double> first =
          sweep(surface, ray, supports, 0.0, INFINITY, RootMode::first, &gradient);
      const std::vector<double> any = sweep(surface, ray, supports, 0.0, INFINITY, RootMode::any);
      ASSERT_EQ(first.size(), all.empty() ? 0u : 1u);
      ASSERT_EQ(any.size(), first.size());
      if (all.empty()) continue;
      ++found;
      EXPECT_EQ(first[0], all[0]);
      EXPECT_EQ(any[0], all[0]);
      ASSERT_TRUE(gradient.has_value());
      Vec3 expected(0.0);
      const Vec3 p = ray.at(first[0]);
      for (const auto& s : o.blob_spheres) {
        const double r2 = s.weight.radius * s.weight.radius;
        const double k = 1.0 - glm::dot(p - s.center, p - s.center) / r2;
        if (k > 0.0) expected += (-4.0 * s.weight.strength * k / r2) * (p - s.center);
      }
      EXPECT_LE(glm::length(*gradient - expected), 1e-12 * std::max(1.0, glm::length(expected)))
          << scene << " " << i;
    }
  }
  EXPECT_GT(found, 200);
}

// Spheres far apart and a ray through all their centres: each gives the analytic sphere
// s (1 - d^2/r^2)^2 = T, d = r sqrt(1 - sqrt(T/s)); a tangent chord (enter == exit) and a
// sphere too weak to reach T add nothing.
TEST(SphereSweep, SeparateSpheresAreAnalyticSpheres) {
  scene::ConvolutionObject o;
  o.threshold = 0.3;
  const double strengths[4] = {1.0, 2.0, 0.2, 0.7}, radii[4] = {0.5, 1.0, 1.0, 2.0};
  double x = 0.0;
  for (int i = 0; i < 4; ++i) {
    x += radii[i] + 0.5;
    o.blob_spheres.push_back({{x, 0.0, 0.0}, {strengths[i], radii[i]}});
    x += radii[i];
  }
  o.blob_spheres.push_back({{3.0, 1.0, 0.0}, {5.0, 1.0}});  // the ray touches its support
  const ConvolutionSurface surface(o);
  const Ray ray{{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  std::vector<accel::SupportInterval> supports = chords(o, ray);
  ASSERT_EQ(supports.size(), 5u);
  EXPECT_EQ(supports[4].enter, supports[4].exit);
  std::reverse(supports.begin(), supports.end());
  const std::vector<double> roots = sweep(surface, ray, supports, 0.0, INFINITY);
  std::vector<double> expected;
  for (int i = 0; i < 4; ++i) {
    if (strengths[i] < o.threshold) continue;
    const double d = radii[i] * std::sqrt(1.0 - std::sqrt(o.threshold / strengths[i]));
    const double cx = o.blob_spheres[i].center.x - ray.origin.x;
    expected.push_back(cx - d);
    expected.push_back(cx + d);
  }
  ASSERT_EQ(roots.size(), expected.size());
  for (size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(roots[k], expected[k], 1e-12);
}

// 3000 spheres in a row, 0.35 apart (about six active at once), 6000 chord ends: the running
// sum that rules pieces out drifts as spheres enter and leave, and is rebuilt every few chords
// and after its update limit, its test widened by a bound on its rounding. No crossing is
// lost to that drift: every root along the ray agrees with the hand-written field (each point
// summing its neighbours in the row). Without the rebuilds and the widening, roots are lost.
TEST(SphereSweep, LongChainsKeepTheirAccuracy) {
  std::mt19937_64 rng(1433);
  std::uniform_real_distribution<double> strength(0.5, 1.5), jitter(-0.05, 0.05);
  constexpr int kCount = 3000;
  constexpr double kSpacing = 0.35, kRadius = 1.0;
  scene::ConvolutionObject o;
  for (int i = 0; i < kCount; ++i) {
    o.blob_spheres.push_back({{i * kSpacing, jitter(rng), jitter(rng)}, {strength(rng), kRadius}});
  }
  // About the mean field along the axis, (16/15) r / spacing: it crosses T again and again.
  o.threshold = 16.0 / 15.0 * kRadius / kSpacing;
  const ConvolutionSurface surface(o);
  for (const Vec3& direction : {Vec3(1.0, 0.0, 0.0), glm::normalize(Vec3(1.0, 2e-4, -1e-4))}) {
    const Ray ray{{-3.0, 0.02, 0.0}, direction};
    std::vector<accel::SupportInterval> supports = chords(o, ray);
    ASSERT_EQ(supports.size(), size_t(kCount));
    std::shuffle(supports.begin(), supports.end(), rng);
    const std::vector<double> roots = sweep(surface, ray, supports, 0.0, INFINITY);
    const auto g = [&](double t) {
      const double x = ray.at(t).x;
      std::vector<uint32_t> near;
      const int first = std::max(0, int(std::floor((x - 1.5 * kRadius) / kSpacing)));
      const int last = std::min(kCount - 1, int(std::ceil((x + 1.5 * kRadius) / kSpacing)));
      for (int i = first; i <= last; ++i) near.push_back(uint32_t(i));
      return field_by_hand(o, near, ray, t);
    };
    const double end = kCount * kSpacing + 5.0;  // past the last support
    const std::vector<double> expected = bracketed_roots(g, 0.0, end, 400000);
    ASSERT_GT(expected.size(), 100u);
    ASSERT_EQ(roots.size(), expected.size());
    for (size_t k = 0; k < roots.size(); ++k)
      EXPECT_NEAR(roots[k], expected[k], 1e-14 * std::max(1.0, expected[k])) << k;
  }
}

}  // namespace
}  // namespace convray::implicit
