// A World built with a SupportCache (an animation's frames) hits what a World built without
// one hits, and a second World over the same scene reuses the meshes' hierarchies.
#include <glm/gtc/matrix_transform.hpp>

#include "geometry_test_support.hpp"
#include "implicit/support_cache.hpp"
#include "mesh/procedural.hpp"

namespace convray::geometry {
namespace {

using namespace testing;

// A convolution torus mesh (from its "file", rotated and moved) blended with a segment, moved
// as an object, beside a sphere.
scene::Scene mesh_scene() {
  const mesh::TriangleSoup soup = mesh::torus(1.0, 0.35, 40, 16);
  auto file = std::make_shared<std::vector<field::Triangle>>();
  for (size_t t = 0; t < soup.size(); ++t) {
    const auto c = soup.corners(t);
    file->push_back({c[0], c[1], c[2]});
  }
  Mat4 placement = glm::rotate(Mat4(1.0), 0.7, glm::normalize(Vec3(1, 0.5, 0)));
  placement[3] = glm::dvec4(0.3, -0.2, 0.1, 1.0);
  scene::MeshComponent mesh;
  for (const field::Triangle& t : *file) {
    mesh.triangles.push_back({transform_point(placement, t.a), transform_point(placement, t.b),
                              transform_point(placement, t.c)});
  }
  mesh.weight = {1.0, 0.3};
  mesh.source = scene::MeshSource{file, placement};
  scene::Implicit record;
  record.object.meshes.push_back(std::move(mesh));
  record.object.segments.push_back({{{0.8, 0, 0}, {2.0, 0.5, 0.2}}, {0.6, 0.4}});
  record.object.threshold = 0.05;
  record.component_order = {{scene::Implicit::Kind::mesh, 0}, {scene::Implicit::Kind::segment, 0}};
  scene::Scene s;
  s.objects.push_back(make_object(record, scene::Transform::translation({0, 0, 1})));
  s.objects.push_back(make_object(scene::Sphere{{4, 0, 0}, 0.5}));
  return s;
}

TEST(WorldCache, HitsWhatAWorldWithoutCacheHits) {
  const scene::Scene s = mesh_scene();
  implicit::SupportCache cache;
  const World cached(s, &cache);
  const World direct(s);
  EXPECT_EQ(cache.counts().builds, 1u);
  std::mt19937_64 rng(51);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = random_ray(rng, {1, 0, 1}, 8.0, 2.5);
    const auto a = cached.first_hit(ray, 1e-9, INFINITY, stats);
    const auto b = direct.first_hit(ray, 1e-9, INFINITY, stats);
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
    if (!a) continue;
    ++hits;
    EXPECT_NEAR(a->t, b->t, 1e-10 * b->t);
    EXPECT_NEAR(glm::length(a->normal - b->normal), 0.0, 1e-9);
  }
  EXPECT_GT(hits, 150);
}

TEST(WorldCache, ASecondWorldOverTheSameSceneReusesTheMesh) {
  const scene::Scene s = mesh_scene();
  implicit::SupportCache cache;
  { const World frame0(s, &cache); }
  cache.next_frame();
  const World frame1(s, &cache);
  EXPECT_EQ(cache.counts().builds, 1u);
  EXPECT_EQ(cache.counts().reuses, 1u);
  std::mt19937_64 rng(52);
  TraceStats stats;
  const World direct(s);
  for (int i = 0; i < 100; ++i) {
    const Ray ray = random_ray(rng, {1, 0, 1}, 8.0, 2.5);
    const auto a = frame1.first_hit(ray, 1e-9, INFINITY, stats);
    const auto b = direct.first_hit(ray, 1e-9, INFINITY, stats);
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
    if (a) EXPECT_NEAR(a->t, b->t, 1e-10 * b->t);
  }
}

}  // namespace
}  // namespace convray::geometry
