// Balls certified inside a convolution surface (implicit/inside_balls.hpp), against brute
// force: each primitive's bend bound against second differences of its exact field, each
// certified ball against the exact field at points throughout it, and shadow rays settled by
// the balls against the same rays searched with no ball at hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/coherent_rays.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/inside_balls.hpp"
#include "implicit/surface_impl.hpp"
#include "test_objects.hpp"

namespace convray::implicit {
namespace {

using test_objects::kMixedRadius;
using test_objects::mixed_object;
constexpr double kRadius = kMixedRadius;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    const Vec3 v{n(rng), n(rng), n(rng)};
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

// Along any line, no primitive's field bends down faster than its bend bound (second
// differences of the exact field, which average the second derivative over 2h), and the bound
// is reached within a factor of three somewhere (the kernel's own -4 / R^2 at a point's
// centre): a bound, and not a vacuous one.
TEST(InsideBalls, BendBoundHoldsForEveryKindOfPrimitive) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  const ConvolutionSurface::Impl& s = surface.impl();
  double closest = 0.0;  // the most negative second difference over the bound, per primitive
  int samples = 0;
  test_objects::for_each_second_difference(s, 46, 40000, [&](uint32_t id, double second, int trial) {
    const double bound = s.bend_bound(id);
    ASSERT_GT(bound, 0.0) << id;
    EXPECT_GE(second, -bound * (1.0 + 1e-6) - 1e-6) << "primitive " << id << " trial " << trial;
    closest = std::min(closest, second / bound);
    ++samples;
  });
  EXPECT_GT(samples, 20000);
  EXPECT_LT(closest, -1.0 / 3.0);
}

// Around points inside, the certified ball holds no point with F <= T: 200 points throughout
// each ball and on its sphere, on the exact field; and the balls are not vacuous.
TEST(InsideBalls, CertifiedBallsLieInside) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  const ConvolutionSurface::Impl& s = surface.impl();
  ASSERT_TRUE(s.nonnegative);
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Box3 box = s.index->bounds();
  std::vector<uint32_t> ids;
  int balls = 0, wide = 0;
  for (int trial = 0; trial < 20000 && balls < 300; ++trial) {
    const Vec3 p = box.lo + Vec3(unit(rng), unit(rng), unit(rng)) * (box.hi - box.lo);
    const field::FieldSample at = surface.field(p);
    if (!(at.value > s.threshold)) continue;
    ids.clear();
    s.index->contain(p, ids);
    double bend = 0.0;
    for (uint32_t id : ids) bend += s.bend_bound(id);
    const double radius = inside_radius(at.value, s.threshold, glm::length(at.gradient), bend);
    ASSERT_GT(radius, 0.0) << trial;
    ++balls;
    wide += radius > 0.05 * kRadius;
    for (int k = 0; k < 200; ++k) {
      const double r = k % 2 ? 0.999 * radius : radius * std::cbrt(unit(rng));
      const Vec3 q = p + r * random_unit(rng);
      EXPECT_GT(surface.field(q).value, s.threshold) << "trial " << trial << " point " << k;
    }
  }
  EXPECT_EQ(balls, 300);
  EXPECT_GT(wide, 30);
}

// The formula against its definition: F(p) - slope d - bend d^2 / 2 = T at the radius, and no
// ball where F(p) <= T.
TEST(InsideBalls, RadiusIsWhereTheLowerBoundMeetsTheThreshold) {
  const double value = 1.7, threshold = 1.2, slope = 3.0, bend = 40.0;
  const double d = inside_radius(value, threshold, slope, bend);
  EXPECT_NEAR(value - slope * d - 0.5 * bend * d * d, threshold, 1e-8);
  EXPECT_LT(value - slope * d - 0.5 * bend * d * d, value);
  EXPECT_EQ(inside_radius(1.2, 1.2, slope, bend), 0.0);
  EXPECT_EQ(inside_radius(1.0, 1.2, slope, bend), 0.0);
  EXPECT_NEAR(inside_radius(value, threshold, 0.0, bend), std::sqrt(2.0 * 0.5 / bend), 1e-9);
}

// Shadow rays from a floor below the torus's tube towards a point light above, in one run of
// coherent rays as a tile traces them: the answers are those of the same rays searched each
// in a fresh run (no ball at hand), and the balls settled many of them. Lights inside the
// surface's box (the segment's far end where the field may exceed T) are answered by
// searching.
TEST(InsideBalls, SettledShadowRaysAnswerAsTheSearch) {
  const ConvolutionSurface surface(mixed_object(), nullptr, Tracer::fast);
  for (const Vec3 light : {Vec3(0.3, 6.0, -0.4), Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)}) {
    const int size = 48;
    TraceStats run_stats;
    int blocked = 0;
    begin_coherent_rays();
    std::vector<bool> answers;
    std::vector<Ray> rays;
    std::vector<double> lengths;
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        // A patch under the tube at x = 1, rays a thirtieth of R apart (a picture's).
        const Vec3 floor{0.8 + 0.4 * (i + 0.5) / size, -1.0, -0.2 + 0.4 * (j + 0.5) / size};
        const Vec3 to_light = light - floor;
        rays.push_back({floor, glm::normalize(to_light)});
        lengths.push_back(glm::length(to_light));
        answers.push_back(surface.occluded(rays.back(), 1e-6, lengths.back(), run_stats));
      }
    }
    for (size_t k = 0; k < rays.size(); ++k) {
      begin_coherent_rays();
      TraceStats fresh;
      ASSERT_EQ(answers[k], surface.occluded(rays[k], 1e-6, lengths[k], fresh))
          << "light " << light.x << " " << light.y << " " << light.z << " ray " << k;
      EXPECT_EQ(fresh.shadows_settled, 0u);
      blocked += answers[k];
    }
    if (light.y > 1.0) {  // outside the box: the balls settle most blocked rays
      EXPECT_GT(blocked, 200);
      EXPECT_GT(run_stats.shadows_settled, uint64_t(blocked / 4));
    } else {  // inside it: never settled
      EXPECT_EQ(run_stats.shadows_settled, 0u);
    }
  }
}

}  // namespace
}  // namespace convray::implicit
