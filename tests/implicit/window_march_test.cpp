// The window march's certificate: the bound on |F''| of each primitive along any line
// (implicit/window_march.hpp) against central second differences of the exact field along
// random lines, for every kind of primitive; and the march itself, through tangent rays that
// graze the surface, against the reference tracer.
#include "implicit/window_march.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "field/threshold.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// One primitive of each kind, big and small against R, with strengths of both signs.
scene::ConvolutionObject one_of_each(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  scene::ConvolutionObject o;
  o.points.push_back({point(), {1.3, 0.7}});
  o.blob_spheres.push_back({point(), {-0.8, 0.9}});
  o.blob_cylinders.push_back({point(), point(), {1.1, 0.6}});
  o.segments.push_back({{point(), point()}, {0.9, 0.5}});
  o.segments.push_back({{point(), 5.0 * point()}, {1.0, 0.4}});  // much longer than 2R
  field::Arc arc;
  if (field::arc_through(point(), point(), 2.0 * point(), arc)) o.arcs.push_back({arc, {1.2, 0.5}});
  scene::MeshComponent small, large;
  small.triangles.push_back({point(), point(), point()});
  small.weight = {1.0, 0.8};
  large.triangles.push_back({4.0 * point(), 4.0 * point(), 4.0 * point()});  // area >> pi R^2
  large.weight = {-0.7, 0.3};
  o.meshes.push_back(small);
  o.meshes.push_back(large);
  o.threshold = 0.5;
  return o;
}

TEST(WindowMarch, CurvatureBoundHoldsForEveryKindAlongRandomLines) {
  std::mt19937_64 rng(71);
  int checked = 0;
  double tightest = 0.0;  // the largest measured |f''| / bound: the bound must keep it <= 1
  for (int object = 0; object < 8; ++object) {
    const ConvolutionSurface surface(one_of_each(rng));
    const ConvolutionSurface::Impl& s = surface.impl();
    for (uint32_t id = 0; id < surface.primitive_count(); ++id) {
      const double bound = curvature_bound(s, id);
      for (int line = 0; line < 300; ++line) {
        const Vec3 p = 1.5 * Vec3(random_unit(rng)) * std::uniform_real_distribution<>(0, 1)(rng);
        const Vec3 d = random_unit(rng);
        const double h = 1e-4;
        // The kernel's second derivative jumps where the line leaves a support (it is C1
        // there), so a difference across that point sees a value between the two sides: still
        // bounded by the larger.
        const double second =
            (s.value(id, p + h * d) - 2.0 * s.value(id, p) + s.value(id, p - h * d)) / (h * h);
        tightest = std::max(tightest, std::abs(second) / bound);
        EXPECT_LE(std::abs(second), bound * (1.0 + 1e-4) + 1e-5) << "primitive " << id;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10000);
  // A bound that is far too loose would make the march crawl: it should be within a factor
  // of a few of what random lines reach.
  EXPECT_GT(tightest, 0.05);
  std::printf("lines %d, largest |f''| / bound %.3f\n", checked, tightest);
}

// Triangles far wider than the kernel's ball get the integral bound 4 pi instead of
// 8/R^2 times their area: second differences of the exact field along random lines near the
// plane stay below it, and the plane's own normal direction (|F''| = 2 pi at height 0, from
// the plane's field (pi R^2/3)(1 - h^2/R^2)^3) comes within a factor 2 of it.
TEST(WindowMarch, WideTrianglesKeepTheIntegralCurvatureBound) {
  const double R = 0.2;
  scene::ConvolutionObject object;
  scene::MeshComponent mesh;
  mesh.triangles.push_back({{-3, -3, 0}, {3, -3, 0}, {0, 3, 0}});
  mesh.weight = {1.0, R};
  object.meshes.push_back(mesh);
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  const ConvolutionSurface surface(object);
  const ConvolutionSurface::Impl& s = surface.impl();
  const double bound = curvature_bound(s, s.triangle_base);
  EXPECT_NEAR(bound, 4.0 * kPi, 1e-12);
  std::mt19937_64 rng(73);
  double tightest = 0.0;
  const double h = 1e-4;
  for (int line = 0; line < 3000; ++line) {
    std::uniform_real_distribution<> u(-1.0, 1.0);
    const Vec3 p(u(rng), u(rng), R * u(rng));
    const Vec3 d = line % 10 == 0 ? Vec3(0, 0, 1) : Vec3(random_unit(rng));
    const double second =
        (s.value(s.triangle_base, p + h * d) - 2.0 * s.value(s.triangle_base, p) +
         s.value(s.triangle_base, p - h * d)) / (h * h);
    tightest = std::max(tightest, std::abs(second) / bound);
    EXPECT_LE(std::abs(second), bound * (1.0 + 1e-4)) << "line " << line;
  }
  EXPECT_GT(tightest, 0.45);  // 2 pi of 4 pi, reached along the normal at height 0
}

// Rays that graze a blob of triangles (an octahedron's) 10^-2 R and 10^-3 R inside and outside
// the tangent ray (found by bisection on the reference tracer): the march finds the same hits
// and misses as the reference tracer, and the same distances.
TEST(WindowMarch, GrazingRaysAgreeWithTheReferenceTracer) {
  const double R = 0.5;
  scene::ConvolutionObject object;
  scene::MeshComponent octahedron;
  const Vec3 v[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& f : faces) octahedron.triangles.push_back({v[f[0]], v[f[1]], v[f[2]]});
  octahedron.weight = {1.0, R};
  object.meshes.push_back(octahedron);
  object.threshold = field::threshold_for_offset(1.0, R, 0.5 * R);
  const ConvolutionSurface fast(object);
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

}  // namespace
}  // namespace convray::implicit
