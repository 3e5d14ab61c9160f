// The near-hit bound that starts a shadow ray leaving a surface (implicit/near_hit.hpp),
// against brute force: each primitive's upward bend against second differences of its exact
// field, the bound against the exact field at points around first hits, and shadow rays
// leaving hits against the same rays searched with no near-hit sample at hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/coherent_rays.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/near_hit.hpp"
#include "implicit/surface_impl.hpp"
#include "implicit/surface_roots.hpp"
#include "test_objects.hpp"
#include "reference/random_vectors.hpp"

namespace convray::implicit {
namespace {

using test_objects::kMixedRadius;
using test_objects::mixed_object;

// Twice the bend bounds of the primitives whose support holds p: H(p) of near_hit.hpp.
double rise_bound_at(const ConvolutionSurface::Impl& s, const Vec3& p) {
  std::vector<uint32_t> ids;
  s.index->contain(p, ids);
  double sum = 0.0;
  for (uint32_t id : ids) sum += 2.0 * s.bend_bound(id);
  return sum;
}

// Along any line, no primitive's field bends up faster than twice its bend bound (the
// kernel's Hessian has eigenvalues up to 8 / R^2), and that is reached within a factor of
// four somewhere (at the edge of a point's support the kernel's own 8 / R^2).
TEST(NearHit, UpwardBendWithinTwiceTheBendBound) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  const ConvolutionSurface::Impl& s = surface.impl();
  double closest = 0.0;  // the largest second difference over the bound
  int samples = 0;
  test_objects::for_each_second_difference(s, 91, 40000, [&](uint32_t id, double second, int trial) {
    const double bound = 2.0 * s.bend_bound(id);
    EXPECT_LE(second, bound * (1.0 + 1e-6) + 1e-6) << "primitive " << id << " trial " << trial;
    closest = std::max(closest, second / bound);
    ++samples;
  });
  EXPECT_GT(samples, 20000);
  EXPECT_GT(closest, 0.25);
}

// Rays from around the object towards its middle that hit it (the window march's first hits,
// with their near-hit samples): each sample is the exact field and gradient at its point, a
// hair from the root, with H there; and around it, at distances from 10^-7 to 0.3 R in every
// direction, the exact field never exceeds the bound.
TEST(NearHit, BoundHoldsAroundFirstHits) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  const ConvolutionSurface::Impl& s = surface.impl();
  std::mt19937_64 rng(92);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int hits = 0, below = 0;
  for (int trial = 0; trial < 3000 && hits < 300; ++trial) {
    const Vec3 origin = 3.0 * convray::testing::random_unit(rng);
    const Vec3 target = 0.8 * convray::testing::random_point(rng, 1.0);
    const Ray ray{origin, glm::normalize(target - origin)};
    std::vector<double> found;
    std::optional<Vec3> gradient;
    NearHit near;
    TraceStats stats;
    find_roots(s, ray, 0.0, 10.0, RootMode::first, found, stats, &gradient, nullptr, &near);
    if (found.empty() || near.bend < 0.0) continue;
    ++hits;
    const field::FieldSample at = surface.field(near.point);
    EXPECT_NEAR(near.value, at.value, 1e-12 * std::abs(at.value) + 1e-14);
    EXPECT_NEAR(glm::length(near.gradient - at.gradient), 0.0, 1e-12 * glm::length(at.gradient));
    // The march's members include every support that holds the point (an arc's interval is
    // conservative: it may hold more).
    EXPECT_GE(near.bend, rise_bound_at(s, near.point) * (1.0 - 1e-12));
    EXPECT_LT(glm::length(near.point - ray.at(found.front())), 1e-4 * s.min_radius);
    for (int k = 0; k < 60; ++k) {
      const double distance = kMixedRadius * 0.3 * std::pow(10.0, -6.0 * unit(rng));
      const Vec3 x = near.point + distance * convray::testing::random_unit(rng);
      const double bound = field_bound_near(near, x, rise_bound_at(s, x));
      const double exact = surface.field(x).value;
      EXPECT_LE(exact, bound) << "trial " << trial << " point " << k << " at " << distance;
      below += bound < s.threshold;
    }
  }
  EXPECT_EQ(hits, 300);
  EXPECT_GT(below, 300);  // the bound is below T on the side the field falls, near the hit
}

// Camera rays of a tile hit the torus; a shadow ray leaves each hit towards a light, in the
// same run (the near-hit sample at hand), as the renderer traces them. Each answer is that of
// the same ray searched in a fresh run (no sample), and every 64th also that of the reference
// tracer (a tenth of a second a ray); the sample saved evaluations.
TEST(NearHit, ShadowRaysLeavingHitsAnswerAsTheSearch) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  const ConvolutionSurface reference(mixed_object(), nullptr, Tracer::reference);
  const double offset = 1e-6;
  int shadows = 0, blocked = 0;
  uint64_t with_sample = 0, without = 0;
  for (const Vec3 light : {Vec3(-3.0, 6.0, -5.0), Vec3(4.0, 1.0, -2.0), Vec3(0.0, -5.0, 0.5)}) {
    const Vec3 eye{0.3, 2.5, -4.0};
    const int size = 40;
    for (int j = 0; j < size; ++j) {
      begin_coherent_rays();
      for (int i = 0; i < size; ++i) {
        const Vec3 target{-1.4 + 2.8 * (i + 0.5) / size, 0.0, -1.4 + 2.8 * (j + 0.5) / size};
        TraceStats camera;
        const Ray ray{eye, glm::normalize(target - eye)};
        const std::optional<SurfaceHit> hit = surface.first_hit(ray, 0.0, 20.0, camera);
        if (!hit) continue;
        const Vec3 to_light = light - hit->point;
        if (!(glm::dot(hit->normal, to_light) > 0.0)) continue;
        const Ray shadow{hit->point, glm::normalize(to_light)};
        const double length = glm::length(to_light) - offset;
        TraceStats run;
        const bool answer = surface.occluded(shadow, offset, length, run);
        // The next camera ray starts a new run (the fresh search below began one).
        begin_coherent_rays();
        TraceStats fresh, exact;
        ASSERT_EQ(answer, surface.occluded(shadow, offset, length, fresh)) << i << " " << j;
        if (shadows % 64 == 0) {
          ASSERT_EQ(answer, reference.occluded(shadow, offset, length, exact)) << i << " " << j;
        }
        ++shadows;
        blocked += answer;
        with_sample += run.field_evaluations;
        without += fresh.field_evaluations;
      }
    }
  }
  EXPECT_GT(shadows, 1500);
  EXPECT_GT(blocked, 50);
  EXPECT_LT(double(with_sample), 0.9 * double(without));
}

}  // namespace
}  // namespace convray::implicit
