// The surface finder against analytic surfaces (a point's sphere, a big triangle's offset
// plane) and against the exact reference tracer on random skeletons of every kind.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "implicit/surface_impl.hpp"
#include "field/threshold.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// One point of radius R: (1 - d^2/R^2)^2 = T is the sphere d = R sqrt(1 - sqrt(T)).
TEST(ConvolutionSurface, SinglePointIsASphereOfKnownRadius) {
  scene::ConvolutionObject object;
  const double R = 2.0, T = 0.3;
  object.points.push_back({{1, 2, 3}, {1.0, R}});
  object.threshold = T;
  const ConvolutionSurface surface(object);
  const double radius = R * std::sqrt(1.0 - std::sqrt(T));
  std::mt19937_64 rng(31);
  TraceStats stats;
  for (int i = 0; i < 500; ++i) {
    const Vec3 origin = Vec3(1, 2, 3) + 6.0 * random_unit(rng);
    const Vec3 aim = Vec3(1, 2, 3) + 1.2 * radius * random_unit(rng);
    const Ray ray{origin, glm::normalize(aim - origin)};
    // Analytic intersections with the sphere.
    const Vec3 w = origin - Vec3(1, 2, 3);
    const double b = glm::dot(w, ray.direction), c = glm::dot(w, w) - radius * radius;
    const double disc = b * b - c;
    std::vector<double> roots;
    surface.roots(ray, 0.0, INFINITY, roots, stats);
    if (disc <= 1e-9) {
      EXPECT_TRUE(roots.empty()) << i;
      continue;
    }
    ASSERT_EQ(roots.size(), 2u) << i;
    EXPECT_NEAR(roots[0], -b - std::sqrt(disc), 1e-12 * R);
    EXPECT_NEAR(roots[1], -b + std::sqrt(disc), 1e-12 * R);
    const auto hit = surface.first_hit(ray, 0.0, INFINITY, stats);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(glm::length(hit->normal - glm::normalize(hit->point - Vec3(1, 2, 3))), 0.0, 1e-9);
  }
}

// A triangle much larger than R: away from its edges the surface is the plane at the offset.
TEST(ConvolutionSurface, LargeTriangleGivesThePlaneAtTheOffset) {
  scene::ConvolutionObject object;
  const double R = 1.0, offset = 0.4;
  object.meshes.push_back({{{{-100, -100, 0}, {100, -100, 0}, {0, 100, 0}}}, {1.0, R}});
  object.threshold = field::threshold_for_offset(1.0, R, offset);
  const ConvolutionSurface surface(object);
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-20, 20);
  TraceStats stats;
  for (int i = 0; i < 300; ++i) {
    const Vec3 origin(u(rng), u(rng), 30.0);
    const Vec3 target(u(rng), u(rng), 0.0);
    const Ray ray{origin, glm::normalize(target - origin)};
    std::vector<double> roots;
    surface.roots(ray, 0.0, INFINITY, roots, stats);
    ASSERT_EQ(roots.size(), 2u) << i;
    // Planes z = +offset and z = -offset.
    EXPECT_NEAR(roots[0], (30.0 - offset) / -ray.direction.z, 1e-9 * R);
    EXPECT_NEAR(roots[1], (30.0 + offset) / -ray.direction.z, 1e-9 * R);
    const auto hit = surface.first_hit(ray, 0.0, INFINITY, stats);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->normal.z, 1.0, 1e-9);
  }
}

// Random skeletons of every kind, negative strengths included, traced from random rays by
// the fast path and by the reference tracer: the same hits and misses, the same distances.
scene::ConvolutionObject random_skeleton(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.5, 1.5), r(0.4, 0.9), s(0.5, 1.5);
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  scene::ConvolutionObject o;
  for (int i = 0; i < 4; ++i) o.points.push_back({point(), {s(rng), r(rng)}});
  for (int i = 0; i < 3; ++i) o.segments.push_back({{point(), point()}, {s(rng), r(rng)}});
  for (int i = 0; i < 2; ++i) {
    field::Arc arc;
    if (field::arc_through(point(), point(), point(), arc)) o.arcs.push_back({arc, {s(rng), r(rng)}});
  }
  scene::MeshComponent mesh;
  for (int i = 0; i < 6; ++i) mesh.triangles.push_back({point(), point(), point()});
  mesh.weight = {1.0, 0.6};
  o.meshes.push_back(mesh);
  o.blob_spheres.push_back({point(), {2.0, 0.8}});
  o.blob_cylinders.push_back({point(), point(), {1.5, 0.5}});
  o.points.push_back({point(), {-1.0, 0.7}});  // subtracts
  o.threshold = 0.3;
  return o;
}

// The fast window march and the paper's fits, each against the reference tracer.
class EveryFastTracer : public ::testing::TestWithParam<Tracer> {};

INSTANTIATE_TEST_SUITE_P(Tracers, EveryFastTracer, ::testing::Values(Tracer::fast, Tracer::fits),
                         [](const auto& info) {
                           return std::string(info.param == Tracer::fast ? "WindowMarch" : "Fits");
                         });

TEST_P(EveryFastTracer, AgreesWithTheReferenceTracerOnRandomSkeletons) {
  std::mt19937_64 rng(33);
  int rays = 0, disagreements = 0, hits = 0;
  double worst = 0.0, worst_normal = 0.0;
  TraceStats stats;
  for (int scene = 0; scene < 12; ++scene) {
    const ConvolutionSurface surface(random_skeleton(rng), nullptr, GetParam());
    const double R = 0.4;  // the smallest radius used
    for (int i = 0; i < 250; ++i) {
      const Vec3 origin = 5.0 * random_unit(rng);
      const Vec3 aim = 1.2 * random_unit(rng);
      const Ray ray{origin, glm::normalize(aim - origin)};
      const auto fast = surface.first_hit(ray, 0.0, INFINITY, stats);
      const auto exact = reference_first_hit(surface, ray, 0.0, INFINITY, stats);
      ++rays;
      if (fast.has_value() != exact.has_value()) {
        ++disagreements;
        continue;
      }
      if (!fast) continue;
      ++hits;
      worst = std::max(worst, std::abs(fast->t - exact->t) / R);
      // Normals come from the sphere sweep's own spheres or from the point query.
      worst_normal = std::max(worst_normal, glm::length(fast->normal - exact->normal));
    }
  }
  // The window march's normal is the exact gradient at its refiner's landing point, whose
  // error Newton's step squares (window_march.cpp's kLanding): within 2e-5 of a radian.
  EXPECT_LE(worst_normal, GetParam() == Tracer::fast ? 2e-5 : 1e-9);
  RecordProperty("worst_distance_over_R", std::to_string(worst));
  std::printf("rays %d, hits %d, hit/miss disagreements %d, worst |dt|/R %.3g, worst normal %.3g\n",
              rays, hits, disagreements, worst, worst_normal);
  EXPECT_GT(hits, rays / 5);
  EXPECT_LE(disagreements, rays * 5 / 10000 + 1);  // 0.05 % (one allowed in 3,000)
  EXPECT_LE(worst, 1e-6);
}

// Every root of roots() is a crossing of the exact field, and F at its sides differs in sign.
TEST_P(EveryFastTracer, AllRootsArePolishedCrossings) {
  std::mt19937_64 rng(34);
  TraceStats stats;
  int checked = 0;
  for (int scene = 0; scene < 6; ++scene) {
    const ConvolutionSurface surface(random_skeleton(rng), nullptr, GetParam());
    for (int i = 0; i < 100; ++i) {
      const Vec3 origin = 5.0 * random_unit(rng);
      const Ray ray{origin, glm::normalize(random_unit(rng) - origin)};
      std::vector<double> roots, reference;
      surface.roots(ray, 0.0, INFINITY, roots, stats);
      reference_roots(surface, ray, 0.0, INFINITY, reference, stats);
      EXPECT_EQ(roots.size(), reference.size());
      for (size_t k = 0; k < std::min(roots.size(), reference.size()); ++k) {
        EXPECT_NEAR(roots[k], reference[k], 1e-6 * 0.4);
      }
      for (double t : roots) {
        const double step = 1e-9;
        const double before = surface.field(ray.at(t - step)).value - surface.threshold();
        const double after = surface.field(ray.at(t + step)).value - surface.threshold();
        EXPECT_LE(before * after, 0.0);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// An arc's support interval along a ray is conservative (a ball of radius rho + R cut by the
// slab |h| <= R), so on rings much wider than R most of it lies outside the support and the
// field is a couple of narrow bumps where the ray crosses the tube. Full rings and half rings,
// rays close to the ring's plane through the hole and across the tube, against the reference.
TEST_P(EveryFastTracer, ArcsWideAgainstTheirRadiusAgreeWithTheReferenceTracer) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TraceStats stats;
  int rays = 0, disagreements = 0, roots_found = 0;
  for (double rho : {1.0, 3.0, 6.0, 12.0}) {
    for (double angle : {2.0 * kPi, kPi}) {
      scene::ConvolutionObject o;
      const double R = 0.5;
      field::Arc arc;
      arc.center = Vec3(0.3, -0.2, 0.1);
      arc.axis = glm::normalize(Vec3(0.2, 1.0, 0.1));
      arc.start = glm::normalize(glm::cross(arc.axis, Vec3(0.0, 0.0, 1.0)));
      arc.radius = rho;
      arc.angle = angle;
      o.arcs.push_back({arc, {1.0, R}});
      o.threshold = 0.3 * 16.0 / 15.0 * R;  // 0.3 of the field on a long straight skeleton
      const ConvolutionSurface surface(o, nullptr, GetParam());
      const Vec3 second = glm::cross(arc.axis, arc.start);
      for (int i = 0; i < 60; ++i) {
        // From outside the ring towards a point of the ring's disc, tilted a little out of
        // its plane: the ray crosses the tube on both sides of the hole.
        const double a = 2.0 * kPi * unit(rng), b = 2.0 * kPi * unit(rng);
        const Vec3 in_disc = std::cos(b) * arc.start + std::sin(b) * second;
        const Vec3 around = std::cos(a) * arc.start + std::sin(a) * second;
        const Vec3 target =
            arc.center + rho * unit(rng) * in_disc + R * (unit(rng) - 0.5) * arc.axis;
        const Vec3 origin = arc.center + 3.0 * (rho + R) * around +
                            (rho + R) * 0.3 * (unit(rng) - 0.5) * arc.axis;
        const Ray ray{origin, glm::normalize(target - origin)};
        std::vector<double> roots, reference;
        surface.roots(ray, 0.0, INFINITY, roots, stats);
        reference_roots(surface, ray, 0.0, INFINITY, reference, stats);
        ++rays;
        if (roots.size() != reference.size()) {
          ++disagreements;
          continue;
        }
        for (size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(roots[k], reference[k], 1e-6 * R);
        roots_found += int(roots.size());
      }
    }
  }
  std::printf("rays %d, roots %d, disagreements %d\n", rays, roots_found, disagreements);
  EXPECT_GT(roots_found, rays);
  EXPECT_LE(disagreements, 1);
}

TEST(ConvolutionSurface, RejectsBadThresholdsAndWeights) {
  scene::ConvolutionObject o;
  o.threshold = 0.0;
  EXPECT_THROW(ConvolutionSurface{o}, std::invalid_argument);
  o.threshold = 1.0;
  o.points.push_back({{0, 0, 0}, {1.0, -1.0}});
  EXPECT_THROW(ConvolutionSurface{o}, std::invalid_argument);
}

// The chunks of a first-root search are at least two mean support widths long: the widths
// by hand for a point, a segment and an equilateral triangle.
TEST(ConvolutionSurface, MeanSupportWidthIsTheSupportsHalfWidthsTwice) {
  scene::ConvolutionObject o;
  o.points.push_back({{0, 0, 0}, {1.0, 0.5}});                 // half-width 0.5
  o.segments.push_back({{{0, 0, 0}, {2, 0, 0}}, {1.0, 0.3}});  // 0.3 + 1
  const double s = std::sqrt(3.0);  // corners 2 from the centroid at the origin
  o.meshes.push_back({{{{2, 0, 0}, {-1, s, 0}, {-1, -s, 0}}}, {1.0, 0.2}});  // 0.2 + 2
  o.threshold = 0.5;
  const ConvolutionSurface surface(o);
  // The triangle's half-width comes from the index's bounding ball, stored in floats rounded
  // outwards (accel::BoundingBall): exact to a few parts in 10^7.
  const double width = 2.0 * (0.5 + 1.3 + 2.2) / 3.0;
  EXPECT_NEAR(surface.impl().mean_support_width(), width, 1e-6 * width);
  EXPECT_GE(surface.impl().mean_support_width(), width);
  EXPECT_NEAR(surface.impl().min_chunk, 2.0 * width, 2e-6 * width);
}

}  // namespace
}  // namespace convray::implicit
