// A SupportCache keeps mesh components' hierarchies from one surface to the next (animation
// frames): surfaces built with it find the same roots and fields as surfaces built without,
// and the cache builds only what it has not seen (a file placed rigidly is built once).
#include "implicit/support_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "implicit/surface_impl.hpp"
#include "mesh/procedural.hpp"

namespace convray::implicit {
namespace {

using Triangles = std::vector<field::Triangle>;

std::shared_ptr<const Triangles> torus_file() {
  const mesh::TriangleSoup soup = mesh::torus(1.0, 0.35, 40, 16);
  auto triangles = std::make_shared<Triangles>();
  for (size_t t = 0; t < soup.size(); ++t) {
    const auto corners = soup.corners(t);
    triangles->push_back({corners[0], corners[1], corners[2]});
  }
  return triangles;
}

Mat4 rigid(double degrees, const Vec3& axis, const Vec3& translation) {
  Mat4 m = glm::rotate(Mat4(1.0), glm::radians(degrees), glm::normalize(axis));
  m[3] = glm::dvec4(translation, 1.0);
  return m;
}

// What the parser makes of `mesh { "torus" <transform> }`: the placed triangles and their source.
scene::MeshComponent placed_mesh(const std::shared_ptr<const Triangles>& file, const Mat4& placement) {
  scene::MeshComponent mesh;
  for (const field::Triangle& t : *file) {
    mesh.triangles.push_back({transform_point(placement, t.a), transform_point(placement, t.b),
                              transform_point(placement, t.c)});
  }
  mesh.weight = {1.0, 0.3};
  mesh.source = scene::MeshSource{file, placement};
  return mesh;
}

// A mesh blended with a segment and an arc that reach into it.
scene::ConvolutionObject limb_and_mesh(const std::shared_ptr<const Triangles>& file,
                                const Mat4& placement) {
  scene::ConvolutionObject o;
  o.meshes.push_back(placed_mesh(file, placement));
  const Vec3 at = transform_point(placement, Vec3(0.0));
  o.segments.push_back({{at + Vec3(0.8, 0, 0), at + Vec3(2.0, 0.5, 0.2)}, {0.6, 0.4}});
  field::Arc arc;
  EXPECT_TRUE(field::arc_through(at + Vec3(-1.0, 0.2, 0), at + Vec3(-1.5, 1.0, 0.3),
                                 at + Vec3(-0.6, 1.6, 0.1), arc));
  o.arcs.push_back({arc, {0.5, 0.35}});
  o.threshold = 0.05;  // the sheet alone gives up to (pi/3) R^2 = 0.094
  return o;
}

// How many mesh groups the surface's index places as instances of a prebuilt hierarchy.
size_t instances(const ConvolutionSurface& surface) {
  return surface.impl().index->instance_count();
}

// The same object without sources: what a surface built from scratch sees.
scene::ConvolutionObject without_sources(scene::ConvolutionObject o) {
  for (scene::MeshComponent& m : o.meshes) m.source.reset();
  return o;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

// Roots and fields on random rays and points around `center`, within `tolerance` relative.
void expect_same_surface(const ConvolutionSurface& got, const ConvolutionSurface& expected,
                         const Vec3& center, uint64_t seed, double tolerance = 1e-10) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  TraceStats stats;
  size_t roots = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 origin = center + Vec3(u(rng), u(rng), u(rng)) * 2.0;
    const Vec3 aim = center + Vec3(u(rng), u(rng), u(rng)) * 0.6;
    const Ray ray{origin, glm::normalize(aim - origin)};
    std::vector<double> a, b;
    got.roots(ray, 0.0, INFINITY, a, stats);
    expected.roots(ray, 0.0, INFINITY, b, stats);
    ASSERT_EQ(a.size(), b.size()) << "ray " << i;
    for (size_t k = 0; k < a.size(); ++k) EXPECT_LE(relative(a[k], b[k]), tolerance);
    roots += a.size();
    const Vec3 p = center + Vec3(u(rng), u(rng), u(rng)) * 0.8;
    const field::FieldSample fa = got.field(p), fb = expected.field(p);
    EXPECT_LE(relative(fa.value, fb.value), 1e-12);
    EXPECT_LE(glm::length(fa.gradient - fb.gradient), 1e-12 * (1.0 + glm::length(fb.gradient)));
  }
  EXPECT_GT(roots, 200u);
}

TEST(SupportCache, CachedSurfaceFindsTheRootsAndFieldsOfADirectBuild) {
  const auto file = torus_file();
  const Mat4 placement = rigid(30, {1, 1, 0}, {2, -1, 0.5});
  const scene::ConvolutionObject object = limb_and_mesh(file, placement);
  SupportCache cache;
  const ConvolutionSurface cached(object, &cache);
  const ConvolutionSurface direct(without_sources(object));
  EXPECT_EQ(cached.primitive_count(), direct.primitive_count());
  EXPECT_EQ(cached.bounds().lo, direct.bounds().lo);
  EXPECT_EQ(cached.bounds().hi, direct.bounds().hi);
  EXPECT_EQ(instances(cached), 1u);
  EXPECT_EQ(instances(direct), 0u);
  expect_same_surface(cached, direct, {2, -1, 0.5}, 41);
  EXPECT_EQ(cache.counts().builds, 1u);
}

TEST(SupportCache, CachedSurfaceAgreesWithTheReferenceTracer) {
  const auto file = torus_file();
  const scene::ConvolutionObject object = limb_and_mesh(file, rigid(-50, {0, 1, 1}, {0.5, 0.2, -1}));
  SupportCache cache;
  const ConvolutionSurface surface(object, &cache);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 40; ++i) {
    const Vec3 origin = Vec3(0.5, 0.2, -1) + 5.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Vec3 aim = Vec3(0.5, 0.2, -1) + Vec3(u(rng), u(rng), u(rng));
    const Ray ray{origin, glm::normalize(aim - origin)};
    const auto fast = surface.first_hit(ray, 0.0, INFINITY, stats);
    const auto exact = reference_first_hit(surface, ray, 0.0, INFINITY, stats);
    ASSERT_EQ(fast.has_value(), exact.has_value()) << "ray " << i;
    if (!fast) continue;
    ++hits;
    EXPECT_NEAR(fast->t, exact->t, 1e-9);
  }
  EXPECT_GT(hits, 10);
}

TEST(SupportCache, TheSameObjectTwiceIsBuiltOnce) {
  const auto file = torus_file();
  const scene::ConvolutionObject object = limb_and_mesh(file, rigid(10, {0, 0, 1}, {1, 2, 3}));
  SupportCache cache;
  const ConvolutionSurface first(object, &cache);
  const ConvolutionSurface second(object, &cache);
  EXPECT_EQ(cache.counts().builds, 1u);
  EXPECT_EQ(cache.counts().reuses, 1u);
  EXPECT_EQ(cache.size(), 1u);
  expect_same_surface(second, first, {1, 2, 3}, 43);
}

TEST(SupportCache, ARigidMoveReusesTheFilesHierarchy) {
  const auto file = torus_file();
  SupportCache cache;
  const ConvolutionSurface before(limb_and_mesh(file, rigid(0, {0, 0, 1}, {0, 0, 0})), &cache);
  cache.next_frame();
  const Mat4 moved = rigid(65, {0.3, 1, 0.2}, {1.5, -0.5, 2});
  const scene::ConvolutionObject object = limb_and_mesh(file, moved);
  const ConvolutionSurface after(object, &cache);
  EXPECT_EQ(cache.counts().builds, 1u);
  EXPECT_EQ(cache.counts().reuses, 1u);
  EXPECT_EQ(instances(after), 1u);
  // A surface built from scratch over the moved triangles.
  expect_same_surface(after, ConvolutionSurface(without_sources(object)), {1.5, -0.5, 2}, 44);
}

TEST(SupportCache, AScaledPlacementIsBuiltOverThePlacedTriangles) {
  const auto file = torus_file();
  SupportCache cache;
  const ConvolutionSurface plain(limb_and_mesh(file, Mat4(1.0)), &cache);
  const Mat4 scaled = glm::scale(rigid(20, {1, 0, 0}, {0, 1, 0}), Vec3(1.5));
  const scene::ConvolutionObject object = limb_and_mesh(file, scaled);
  const ConvolutionSurface first(object, &cache);
  EXPECT_EQ(cache.counts().builds, 2u);
  const ConvolutionSurface again(object, &cache);
  EXPECT_EQ(cache.counts().builds, 2u);
  EXPECT_EQ(cache.counts().reuses, 1u);
  EXPECT_EQ(instances(again), 1u);  // placed by the identity
  expect_same_surface(again, ConvolutionSurface(without_sources(object)), {0, 1, 0}, 45);
}

TEST(SupportCache, NextFrameDropsWhatTheLastFrameDidNotUse) {
  const auto file = torus_file();
  SupportCache cache;
  const Mat4 scale2 = glm::scale(Mat4(1.0), Vec3(2.0)), scale3 = glm::scale(Mat4(1.0), Vec3(3.0));
  { const ConvolutionSurface frame0(limb_and_mesh(file, scale2), &cache); }
  cache.next_frame();
  { const ConvolutionSurface frame1(limb_and_mesh(file, scale3), &cache); }
  EXPECT_EQ(cache.size(), 2u);  // frame 0's is kept until a frame goes by without it
  cache.next_frame();
  EXPECT_EQ(cache.size(), 1u);
  { const ConvolutionSurface frame2(limb_and_mesh(file, scale3), &cache); }
  EXPECT_EQ(cache.counts().builds, 2u);
  EXPECT_EQ(cache.counts().reuses, 1u);
  cache.next_frame();
  cache.next_frame();
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.memory_bytes(), 0u);
}

TEST(SupportCache, ComponentsWithoutSourceAreBuiltAsBefore) {
  const auto file = torus_file();
  SupportCache cache;
  const scene::ConvolutionObject object = without_sources(limb_and_mesh(file, Mat4(1.0)));
  const ConvolutionSurface surface(object, &cache);
  EXPECT_EQ(cache.counts().builds, 0u);
  EXPECT_EQ(cache.size(), 0u);
  expect_same_surface(surface, ConvolutionSurface(object), {0, 0, 0}, 46);
}

}  // namespace
}  // namespace convray::implicit
