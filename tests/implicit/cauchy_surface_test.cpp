// The Cauchy-kernel surface: its truncation (each primitive's field exactly zero just outside
// its box, the closed form inside), its field against a brute-force sum, its tracer against
// analytic surfaces (a point's sphere, a box face where the truncation cuts the surface) and
// against the slow exact twin (dense sampling of the brute-force field, then bisection).
#include "implicit/cauchy_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "field/cauchy.hpp"
#include "core/box.hpp"

namespace convray::implicit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

scene::ConvolutionObject cauchy_object(double s, double threshold) {
  scene::ConvolutionObject object;
  object.kernel = {field::KernelType::cauchy, s};
  object.threshold = threshold;
  return object;
}

// A soup of every primitive kind, overlapping, with a positive and a negative strength.
scene::ConvolutionObject mixed_object() {
  scene::ConvolutionObject object = cauchy_object(1.5, 1.0);
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  scene::MeshComponent mesh;
  mesh.weight = {1.0, 1.2};
  for (int i = 0; i < 12; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    mesh.triangles.push_back({c, c + 0.8 * random_unit(rng), c + 0.8 * random_unit(rng)});
  }
  object.meshes.push_back(mesh);
  object.segments.push_back({{{-1.0, 0.5, 0.0}, {1.2, -0.4, 0.3}}, {1.3, 0.9}});
  object.points.push_back({{0.3, 0.9, -0.6}, {2.0, 1.5}});
  object.points.push_back({{-0.5, -0.2, 0.4}, {-0.4, 0.7}});
  return object;
}

TEST(CauchySurface, FieldIsExactlyZeroJustOutsideTheBoxAndTheClosedFormInside) {
  scene::ConvolutionObject object = cauchy_object(1.0, 0.5);
  const field::Triangle t{{0.0, 0.0, 0.0}, {1.0, 0.2, 0.0}, {0.3, 1.0, 0.1}};
  const double margin = 0.75;
  object.meshes.push_back({{t}, {2.0, margin}});
  const CauchySurface surface(object);
  ASSERT_EQ(surface.support_boxes().size(), 1u);
  const Box3 box = surface.support_boxes()[0];
  EXPECT_EQ(box.lo, Vec3(-margin, -margin, -margin));
  EXPECT_EQ(box.hi, Vec3(1.0 + margin, 1.0 + margin, 0.1 + margin));
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool high : {false, true}) {
      Vec3 face(0.5, 0.4, 0.05);
      face[axis] = high ? box.hi[axis] : box.lo[axis];
      const double out = high ? 1e-9 : -1e-9;
      Vec3 outside = face, inside = face;
      outside[axis] += out;
      inside[axis] -= out;
      EXPECT_EQ(surface.field(outside).value, 0.0);
      EXPECT_EQ(surface.field(outside).gradient, Vec3(0.0));
      const double untruncated = 2.0 * field::cauchy_triangle_value(inside, t, 1.0);
      EXPECT_GT(untruncated, 1e-3);
      EXPECT_DOUBLE_EQ(surface.field(inside).value, untruncated);
      EXPECT_DOUBLE_EQ(surface.field(face).value, 2.0 * field::cauchy_triangle_value(face, t, 1.0));
    }
  }
}

TEST(CauchySurface, FieldMatchesBruteForce) {
  const CauchySurface surface(mixed_object());
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(surface.field(p).value, cauchy_brute_force_value(surface, p), 1e-13);
  }
}

// One point with margin R: where 1/(1 + s^2 r^2)^2 = T has its sphere r_T inside the box the
// surface is that sphere; where the box is smaller, the surface is the box itself.
TEST(CauchySurface, PointGivesItsSphereOrItsTruncationBox) {
  const double s = 2.0, T = 0.2;
  const double sphere = std::sqrt(1.0 / std::sqrt(T) - 1.0) / s;
  const Vec3 center(0.5, -1.0, 2.0);
  std::mt19937_64 rng(43);
  TraceStats stats;
  int face_hits = 0;
  for (const double margin : {1.5 * sphere, 0.7 * sphere}) {
    scene::ConvolutionObject object = cauchy_object(s, T);
    object.points.push_back({center, {1.0, margin}});
    const CauchySurface surface(object);
    for (int i = 0; i < 300; ++i) {
      // Straight at the centre from a random side: the first hit is at the sphere, or on the
      // face of the box (a cube of half-width margin) the ray enters.
      const Vec3 d = random_unit(rng);
      const Ray ray{center - 4.0 * d, d};
      const auto hit = surface.first_hit(ray, 0.0, 10.0, stats);
      ASSERT_TRUE(hit);
      // The ray enters the cube where it crosses the face of its largest component, at
      // margin / |d[axis]| from the centre; if the ball is already around there, that face is
      // the surface, else the ball (the solid is cube and ball).
      const int axis = std::abs(d.x) >= std::max(std::abs(d.y), std::abs(d.z))
                           ? 0
                           : (std::abs(d.y) >= std::abs(d.z) ? 1 : 2);
      const double face = margin / std::abs(d[axis]);
      if (face >= sphere) {
        EXPECT_NEAR(hit->t, 4.0 - sphere, 1e-11);
        EXPECT_NEAR(glm::length(hit->normal + d), 0.0, 1e-9);
      } else {
        EXPECT_NEAR(hit->t, 4.0 - face, 1e-11);
        Vec3 face_normal(0.0);
        face_normal[axis] = d[axis] > 0.0 ? -1.0 : 1.0;
        EXPECT_EQ(hit->normal, face_normal);
        ++face_hits;
      }
      std::vector<double> roots;
      surface.roots(ray, 0.0, 10.0, roots, stats);
      ASSERT_EQ(roots.size(), 2u);
      EXPECT_NEAR(roots[1] - 4.0, 4.0 - roots[0], 1e-10);  // symmetric about the centre
      EXPECT_TRUE(surface.occluded(ray, 0.0, 10.0, stats));
      EXPECT_FALSE(surface.occluded(ray, 0.0, roots[0] - 1e-6, stats));
    }
  }
  EXPECT_GT(face_hits, 100);
}

// The fast tracer (box sweep, Lipschitz march, Illinois refinement) against the slow twin
// (every primitive asked at every sample, bisection), ray by ray.
TEST(CauchySurface, TracerMatchesTheSlowTwin) {
  const CauchySurface surface(mixed_object());
  std::mt19937_64 rng(44);
  TraceStats stats;
  int with_roots = 0, face_roots = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 origin = 5.0 * random_unit(rng);
    const Vec3 aim = 1.2 * random_unit(rng);
    const Ray ray{origin, glm::normalize(aim - origin)};
    std::vector<double> fast, slow;
    surface.roots(ray, 0.0, 12.0, fast, stats);
    // The twin samples only where the field can be non-zero (it is 0 < T elsewhere), from
    // just outside, so that a jump on the bounds' faces is a sign change it sees.
    double t0 = 0.0, t1 = 12.0;
    if (clip_to_box(ray, surface.bounds(), t0, t1)) {
      cauchy_reference_roots(surface, ray, std::max(0.0, t0 - 1e-3), std::min(12.0, t1 + 1e-3),
                             5e-4, slow);
    }
    ASSERT_EQ(fast.size(), slow.size()) << "ray " << i;
    for (size_t k = 0; k < fast.size(); ++k) EXPECT_NEAR(fast[k], slow[k], 1e-9) << "ray " << i;
    with_roots += !fast.empty();
    std::vector<SurfaceHit> hits;
    surface.hits(ray, 0.0, 12.0, hits, stats);
    ASSERT_EQ(hits.size(), fast.size());
    for (const SurfaceHit& h : hits) {
      EXPECT_NEAR(glm::length(h.normal), 1.0, 1e-12);
      // Axis-aligned normals are the box faces': F - T jumps there, it does not pass zero.
      face_roots +=
          std::abs(h.normal.x) == 1.0 || std::abs(h.normal.y) == 1.0 || std::abs(h.normal.z) == 1.0;
    }
    const auto first = surface.first_hit(ray, 0.0, 12.0, stats);
    ASSERT_EQ(first.has_value(), !fast.empty());
    if (first) EXPECT_EQ(first->t, fast.front());
  }
  EXPECT_GT(with_roots, 50);
  EXPECT_GT(face_roots, 10);  // the test does see the truncation's discontinuities
}

TEST(CauchySurface, RefusesWhatItCannotDescribe) {
  scene::ConvolutionObject arcs = cauchy_object(1.0, 1.0);
  field::Arc arc;
  ASSERT_TRUE(field::arc_through({1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, arc));
  arcs.arcs.push_back({arc, {1.0, 1.0}});
  EXPECT_THROW(CauchySurface{arcs}, std::invalid_argument);
  scene::ConvolutionObject flat = cauchy_object(0.0, 1.0);
  flat.points.push_back({{0, 0, 0}, {1.0, 1.0}});
  EXPECT_THROW(CauchySurface{flat}, std::invalid_argument);
  scene::ConvolutionObject quartic;
  quartic.points.push_back({{0, 0, 0}, {1.0, 1.0}});
  quartic.kernel.type = field::KernelType::cauchy;
  EXPECT_NO_THROW(CauchySurface{quartic});
}

}  // namespace
}  // namespace convray::implicit
