// The window march through tangent rays that graze the surface, against the reference
// tracer (its certificate, the curvature bounds, is tested in line_curvature_test.cpp).
#include "implicit/window_march.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "core/coherent_rays.hpp"
#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "field/threshold.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// Rays that graze a blob of triangles (an octahedron's) 10^-2 R and 10^-3 R inside and outside
// the tangent ray (found by bisection on the reference tracer): the march finds the same hits
// and misses as the reference tracer, and the same distances.
// An octahedron's triangles convolved with radius R, its corners scaled by `scale` (the
// surface stands 0.5 R off them).
scene::ConvolutionObject octahedron_object(double R, double scale = 1.0) {
  scene::ConvolutionObject object;
  scene::MeshComponent octahedron;
  const Vec3 v[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& f : faces) {
    octahedron.triangles.push_back({scale * v[f[0]], scale * v[f[1]], scale * v[f[2]]});
  }
  octahedron.weight = {1.0, R};
  object.meshes.push_back(octahedron);
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  return object;
}

TEST(WindowMarch, GrazingRaysAgreeWithTheReferenceTracer) {
  const double R = 0.5;
  const ConvolutionSurface fast(octahedron_object(R));
  std::mt19937_64 rng(72);
  TraceStats stats;
  int rays = 0, disagreements = 0, hits = 0;
  for (int i = 0; i < 120; ++i) {
    // A ray towards a random direction from far away; then moved sideways until it just
    // touches the surface: bisect on hit/miss of the reference tracer.
    const Vec3 dir = random_unit(rng);
    Vec3 side = glm::normalize(glm::cross(dir, random_unit(rng)));
    double lo = 0.0, hi = 3.0;  // offsets that hit / miss
    for (int k = 0; k < 30; ++k) {
      const double mid = 0.5 * (lo + hi);
      const Ray ray{-5.0 * dir + mid * side, dir};
      (reference_first_hit(fast, ray, 0.0, INFINITY, stats) ? lo : hi) = mid;
    }
    for (double offset : {-1e-2, -1e-3, 1e-3, 1e-2}) {
      const Ray ray{-5.0 * dir + (lo + offset * R) * side, dir};
      const auto a = fast.first_hit(ray, 0.0, INFINITY, stats);
      const auto b = reference_first_hit(fast, ray, 0.0, INFINITY, stats);
      ++rays;
      if (a.has_value() != b.has_value()) {
        ++disagreements;
        continue;
      }
      if (!a) continue;
      ++hits;
      EXPECT_NEAR(a->t, b->t, 1e-6 * R);
    }
  }
  std::printf("rays %d, hits %d, disagreements %d\n", rays, hits, disagreements);
  EXPECT_GT(hits, rays / 3);
  EXPECT_EQ(disagreements, 0);
}

// A first hit's refiner starts from the tangent plane at the last hit of its run of coherent
// rays where the ray passes near that point. A camera's tile of rays 0.004 R apart (one run,
// as the renderer traces a tile) finds the reference tracer's hits, to 1e-6 R, with its
// normals (to 1e-4 of a radian), whether or not a run's earlier hits are near.
TEST(WindowMarch, CoherentRaysFromTheLastHitsTangentAgreeWithTheReferenceTracer) {
  const double R = 0.5;
  const ConvolutionSurface surface(octahedron_object(R));
  const Vec3 eye(0.3, 0.8, -4.0);
  const Vec3 forward = glm::normalize(Vec3(0.1, 0.2, 0.0) - eye);
  const Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward));
  const Vec3 up = glm::cross(forward, right);
  TraceStats stats;
  int hits = 0;
  for (double spacing : {0.004 * R, 0.2 * R}) {  // near the last hit, and not
    begin_coherent_rays();
    for (int j = 0; j < 16; ++j) {
      for (int i = 0; i < 16; ++i) {
        const Vec3 aim = forward + (spacing / 4.0) * (double(i - 8) * right + double(j - 8) * up);
        const Ray ray{eye, glm::normalize(aim)};
        const auto fast = surface.first_hit(ray, 0.0, INFINITY, stats);
        const auto reference = reference_first_hit(surface, ray, 0.0, INFINITY, stats);
        ASSERT_EQ(fast.has_value(), reference.has_value()) << i << " " << j;
        if (!fast) continue;
        ++hits;
        EXPECT_NEAR(fast->t, reference->t, 1e-6 * R) << i << " " << j;
        EXPECT_LT(std::acos(std::min(1.0, glm::dot(fast->normal, reference->normal))), 1e-4)
            << i << " " << j;
      }
    }
  }
  EXPECT_GT(hits, 400);
}

// The march keeps each thread's batch lanes from ray to ray (a triangle's lane is not set
// again for the next ray that lists it there). Rays that alternate between two surfaces of
// the same shape and order of triangles, one of them made again where a freed one stood,
// each find their own surface's hits: the reference tracer's, to 1e-6 R.
TEST(WindowMarch, KeptLanesNeverServeAnotherSurface) {
  const double R = 0.5;
  std::mt19937_64 rng(73);
  TraceStats stats;
  int hits = 0, rays = 0;
  auto a = std::make_unique<ConvolutionSurface>(octahedron_object(R, 1.0));
  for (int round = 0; round < 3; ++round) {
    // A second surface, smaller: the same triangles' lanes hold other corners.
    const ConvolutionSurface b(octahedron_object(R, 0.8 + 0.05 * round));
    for (int i = 0; i < 60; ++i) {
      const Vec3 dir = random_unit(rng);
      const Ray ray{-5.0 * dir + 0.3 * glm::normalize(glm::cross(dir, random_unit(rng))), dir};
      for (const ConvolutionSurface* s : {static_cast<const ConvolutionSurface*>(a.get()), &b}) {
        const auto fast = s->first_hit(ray, 0.0, INFINITY, stats);
        const auto reference = reference_first_hit(*s, ray, 0.0, INFINITY, stats);
        ++rays;
        ASSERT_EQ(fast.has_value(), reference.has_value()) << "round " << round << " ray " << i;
        if (!fast) continue;
        ++hits;
        EXPECT_NEAR(fast->t, reference->t, 1e-6 * R) << "round " << round << " ray " << i;
      }
    }
    // The first surface freed and made again, larger: likely at the same address.
    a.reset();
    a = std::make_unique<ConvolutionSurface>(octahedron_object(R, 1.1 + 0.1 * round));
  }
  EXPECT_GT(hits, rays / 2);
}

}  // namespace
}  // namespace convray::implicit
