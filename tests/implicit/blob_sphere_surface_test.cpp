// Objects made only of POV-Ray blob spheres go through the sphere sweep (sphere_sweep.cpp)
// and the chunked first-root search: checked here against the analytic sphere, against an
// independent root finder on the field written out by hand, and against the reference tracer
// on random blobs with negative strengths, tangent rays and touching supports.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

scene::ConvolutionObject blob(std::initializer_list<scene::BlobSphereComponent> spheres, double threshold) {
  scene::ConvolutionObject o;
  o.blob_spheres = spheres;
  o.threshold = threshold;
  return o;
}

// The field along the ray written out by hand, and its sign changes on a fine grid bisected:
// a root finder that shares nothing with the sweep.
std::vector<double> roots_by_hand(const scene::ConvolutionObject& o, const Ray& ray, double t0,
                                  double t1) {
  auto g = [&](double t) {
    double sum = 0.0;
    for (const auto& c : o.blob_spheres) {
      const Vec3 d = ray.at(t) - c.center;
      const double k = 1.0 - glm::dot(d, d) / (c.weight.radius * c.weight.radius);
      if (k > 0.0) sum += c.weight.strength * k * k;
    }
    return sum - o.threshold;
  };
  std::vector<double> roots;
  const int steps = 200000;
  double a = t0, ga = g(a);
  for (int i = 1; i <= steps; ++i) {
    double b = t0 + (t1 - t0) * i / steps, gb = g(b);
    if ((ga < 0.0) != (gb < 0.0)) {
      double lo = a, hi = b, glo = ga;
      for (int k = 0; k < 200 && 0.5 * (lo + hi) > lo && 0.5 * (lo + hi) < hi; ++k) {
        const double mid = 0.5 * (lo + hi), gm = g(mid);
        if ((gm < 0.0) == (glo < 0.0)) lo = mid, glo = gm;
        else hi = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    ga = gb;
  }
  return roots;
}

// s (1 - d^2/r^2)^2 = T is the sphere d = r sqrt(1 - sqrt(T/s)).
TEST(BlobSphereSurface, OneSphereOfAnyStrengthIsTheAnalyticSphere) {
  std::mt19937_64 rng(51);
  TraceStats stats;
  const Vec3 center(1.0, -2.0, 0.5);
  const double r = 1.7;
  for (double s : {0.5, 1.0, 3.0}) {
    for (double fraction : {0.1, 0.5, 0.9}) {
      const double T = fraction * s;
      const ConvolutionSurface surface(blob({{center, {s, r}}}, T));
      const double rho = r * std::sqrt(1.0 - std::sqrt(T / s));
      for (int i = 0; i < 200; ++i) {
        const Vec3 origin = center + 6.0 * random_unit(rng);
        const Ray ray{origin, glm::normalize(center + 1.2 * rho * random_unit(rng) - origin)};
        const Vec3 w = origin - center;
        const double b = glm::dot(w, ray.direction), c = glm::dot(w, w) - rho * rho;
        const double disc = b * b - c;
        std::vector<double> roots;
        surface.roots(ray, 0.0, INFINITY, roots, stats);
        const auto hit = surface.first_hit(ray, 0.0, INFINITY, stats);
        const bool blocked = surface.occluded(ray, 0.0, INFINITY, stats);
        if (disc <= 1e-9) {
          EXPECT_TRUE(roots.empty() && !hit && !blocked) << i;
          continue;
        }
        ASSERT_EQ(roots.size(), 2u) << s << " " << T << " " << i;
        EXPECT_NEAR(roots[0], -b - std::sqrt(disc), 1e-12 * r);
        EXPECT_NEAR(roots[1], -b + std::sqrt(disc), 1e-12 * r);
        ASSERT_TRUE(hit);
        EXPECT_TRUE(blocked);
        EXPECT_NEAR(hit->t, roots[0], 1e-13 * hit->t);
        EXPECT_NEAR(glm::length(hit->normal - glm::normalize(hit->point - center)), 0.0, 1e-9);
      }
    }
  }
}

// A negative sphere carves a dent into a positive one; along lines through both, every root
// agrees with the hand-written field's.
TEST(BlobSphereSurface, NegativeStrengthCarvesTheSolid) {
  const scene::ConvolutionObject o =
      blob({{{0, 0, 0}, {2.0, 2.0}}, {{0.8, 0, 0}, {-1.5, 1.0}}, {{-1.2, 0.3, 0}, {0.7, 0.8}}},
           0.5);
  const ConvolutionSurface surface(o);
  TraceStats stats;
  std::mt19937_64 rng(52);
  int compared = 0;
  for (int i = 0; i < 60; ++i) {
    const Vec3 origin = 4.0 * random_unit(rng);
    const Ray ray{origin, glm::normalize(Vec3(0.8 * random_unit(rng).x, 0, 0) - origin)};
    std::vector<double> roots;
    surface.roots(ray, 0.0, 10.0, roots, stats);
    const std::vector<double> expected = roots_by_hand(o, ray, 0.0, 10.0);
    ASSERT_EQ(roots.size(), expected.size()) << i;
    for (size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(roots[k], expected[k], 1e-12);
    compared += int(roots.size());
  }
  EXPECT_GT(compared, 100);
}

// `count` spheres in a box of side 4: 40 are sparse (lines cross about 1.5 supports), 300
// dense enough (about 13) for the chunked first-root search.
scene::ConvolutionObject random_blob(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-2.0, 2.0), radius(0.4, 1.0), positive(0.5, 1.5),
      negative(-1.0, -0.3), coin(0.0, 1.0);
  scene::ConvolutionObject o;
  for (int i = 0; i < count; ++i) {
    const double s = coin(rng) < 0.2 ? negative(rng) : positive(rng);
    o.blob_spheres.push_back({{u(rng), u(rng), u(rng)}, {s, radius(rng)}});
  }
  o.threshold = count > 100 ? 1.5 : 0.4;
  return o;
}

// First hits (with normals), every root, and shadow queries on pieces of rays that may start
// inside the solid, against the reference tracer.
TEST(BlobSphereSurface, RandomBlobsAgreeWithTheReferenceTracer) {
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int rays = 0, disagreements = 0, hits = 0, root_count = 0;
  double worst = 0.0, worst_normal = 0.0;
  TraceStats stats;
  const double R = 0.4;  // the smallest radius
  for (int scene = 0; scene < 6; ++scene) {
    const ConvolutionSurface surface(random_blob(rng, scene % 2 ? 300 : 40));
    EXPECT_EQ(surface.impl().gather_in_chunks, scene % 2 == 1);
    for (int i = 0; i < 300; ++i) {
      const Vec3 origin = 5.0 * random_unit(rng);
      const Ray ray{origin, glm::normalize(2.0 * random_unit(rng) - origin)};
      // Half the rays are pieces [tmin, tmax] starting anywhere along the way.
      const double tmin = i % 2 ? 0.0 : 8.0 * unit(rng);
      const double tmax = i % 2 ? INFINITY : tmin + 4.0 * unit(rng);
      ++rays;
      const auto fast = surface.first_hit(ray, tmin, tmax, stats);
      const auto exact = reference_first_hit(surface, ray, tmin, tmax, stats);
      std::vector<double> roots, reference;
      surface.roots(ray, tmin, tmax, roots, stats);
      reference_roots(surface, ray, tmin, tmax, reference, stats);
      const bool blocked = surface.occluded(ray, tmin, tmax, stats);
      if (fast.has_value() != exact.has_value() || roots.size() != reference.size() ||
          blocked != !reference.empty()) {
        ++disagreements;
        continue;
      }
      for (size_t k = 0; k < roots.size(); ++k) {
        worst = std::max(worst, std::abs(roots[k] - reference[k]) / R);
      }
      root_count += int(roots.size());
      if (!fast) continue;
      ++hits;
      worst = std::max(worst, std::abs(fast->t - exact->t) / R);
      EXPECT_NEAR(fast->t, roots.front(), 1e-13 * fast->t);
      worst_normal = std::max(worst_normal, glm::length(fast->normal - exact->normal));
    }
  }
  std::printf("rays %d, hits %d, roots %d, disagreements %d, worst |dt|/R %.3g, normals %.3g\n",
              rays, hits, root_count, disagreements, worst, worst_normal);
  EXPECT_GT(hits, rays / 4);
  EXPECT_LE(disagreements, rays * 5 / 10000 + 1);  // 0.05 %
  EXPECT_LE(worst, 1e-6);
  EXPECT_LE(worst_normal, 1e-9);
}

// Rays that touch a support or the surface tangentially, and supports that touch each other.
TEST(BlobSphereSurface, TangentRaysAndTouchingSupports) {
  TraceStats stats;
  const double r = 1.0, T = 0.25;
  const double rho = r * std::sqrt(1.0 - std::sqrt(T));  // the isolated sphere's radius
  // Along the support's edge (distance r from the centre): the field is zero on the line.
  const ConvolutionSurface one(blob({{{0, 0, 0}, {1.0, r}}}, T));
  std::vector<double> roots;
  one.roots(Ray{{-5, r, 0}, {1, 0, 0}}, 0.0, INFINITY, roots, stats);
  EXPECT_TRUE(roots.empty());
  // Grazing the surface from just inside: two roots either side of the tangent point.
  for (double inset : {1e-3, 1e-6}) {
    const double y = rho * (1.0 - inset);
    roots.clear();
    one.roots(Ray{{-5, y, 0}, {1, 0, 0}}, 0.0, INFINITY, roots, stats);
    const double half = std::sqrt(rho * rho - y * y);
    ASSERT_EQ(roots.size(), 2u) << inset;
    EXPECT_NEAR(roots[0], 5.0 - half, 1e-9);
    EXPECT_NEAR(roots[1], 5.0 + half, 1e-9);
  }
  // Just outside: nothing.
  roots.clear();
  one.roots(Ray{{-5, rho * (1.0 + 1e-6), 0}, {1, 0, 0}}, 0.0, INFINITY, roots, stats);
  EXPECT_TRUE(roots.empty());

  // Two supports touching at the origin: two separate spheres, four roots along the axis.
  const ConvolutionSurface pair(blob({{{-r, 0, 0}, {1.0, r}}, {{r, 0, 0}, {1.0, r}}}, T));
  roots.clear();
  pair.roots(Ray{{-5, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, roots, stats);
  ASSERT_EQ(roots.size(), 4u);
  const double expected[4] = {5 - r - rho, 5 - r + rho, 5 + r - rho, 5 + r + rho};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(roots[k], expected[k], 1e-12);

  // Two overlapping spheres whose field at the midpoint is exactly T: the surface touches
  // itself there. The outer roots are exact; anything between is the touching point.
  const double a = 0.6, touch = 2.0 * (1.0 - a * a) * (1.0 - a * a);
  const ConvolutionSurface neck(blob({{{-a, 0, 0}, {1.0, r}}, {{a, 0, 0}, {1.0, r}}}, touch));
  roots.clear();
  neck.roots(Ray{{-5, 0, 0}, {1, 0, 0}}, 0.0, INFINITY, roots, stats);
  ASSERT_GE(roots.size(), 2u);
  const std::vector<double> by_hand =
      roots_by_hand(blob({{{-a, 0, 0}, {1.0, r}}, {{a, 0, 0}, {1.0, r}}}, touch),
                    Ray{{-5, 0, 0}, {1, 0, 0}}, 0.0, 10.0);
  ASSERT_FALSE(by_hand.empty());
  EXPECT_NEAR(roots.front(), by_hand.front(), 1e-12);
  EXPECT_NEAR(roots.back(), by_hand.back(), 1e-12);
  for (size_t k = 1; k + 1 < roots.size(); ++k) EXPECT_NEAR(roots[k], 5.0, 1e-6);
}

// The first-root search gathers the ray in chunks: from far away, with an infinite or a
// finite end, its answer is the first of all the roots.
TEST(BlobSphereSurface, ChunkedFirstHitIsTheFirstRoot) {
  std::mt19937_64 rng(54);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ConvolutionSurface surface(random_blob(rng, 300));
  ASSERT_TRUE(surface.impl().gather_in_chunks);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 origin = (i % 2 ? 1000.0 : 3.0) * random_unit(rng);
    const Ray ray{origin, glm::normalize(2.0 * random_unit(rng) - origin)};
    const double tmin = i % 3 == 0 ? glm::length(origin) - 2.0 * unit(rng) : 0.0;
    const double tmax = i % 4 == 0 ? tmin + 3.0 * unit(rng) : INFINITY;
    std::vector<double> roots;
    surface.roots(ray, tmin, tmax, roots, stats);
    const auto hit = surface.first_hit(ray, tmin, tmax, stats);
    ASSERT_EQ(hit.has_value(), !roots.empty()) << i;
    EXPECT_EQ(surface.occluded(ray, tmin, tmax, stats), !roots.empty());
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(hit->t, roots.front(), 1e-13 * hit->t);
    EXPECT_GE(hit->t, tmin);
    EXPECT_LE(hit->t, tmax);
  }
  EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace convray::implicit
