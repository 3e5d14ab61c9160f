// Triangle meshes: the BVH against the brute-force loop over every triangle on random rays,
// flat and smooth normals, per-face textures, and solids by ray parity.
#include <gtest/gtest.h>

#include <chrono>

#include "core/bvh.hpp"
#include "geometry/triangle_mesh.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::make_object;

// A random soup of `count` small triangles in the cube [-1, 1]^3.
scene::TriangleMesh random_soup(size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), small(-0.08, 0.08);
  scene::TriangleMesh mesh;
  for (size_t i = 0; i < count; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const int first = int(mesh.vertices.size());
    for (int k = 0; k < 3; ++k)
      mesh.vertices.push_back(c + Vec3(small(rng), small(rng), small(rng)));
    mesh.faces.push_back({{first, first + 1, first + 2}});
  }
  return mesh;
}

// The cube [-1, 1]^3 as 12 triangles.
scene::TriangleMesh cube_mesh() {
  scene::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& q : quads) {
    mesh.faces.push_back({{q[0], q[1], q[2]}});
    mesh.faces.push_back({{q[0], q[2], q[3]}});
  }
  return mesh;
}

TEST(Mesh, BvhFindsWhatTheBruteForceLoopFinds) {
  const auto soup = random_soup(20000, 41);
  const TriangleMeshShape mesh(soup, {std::make_shared<SurfaceInfo>()});
  ASSERT_EQ(mesh.triangle_count(), 20000u);
  std::mt19937_64 rng(42);
  size_t total = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 3.0, 1.0);
    std::vector<Crossing> fast, slow;
    TraceStats stats;
    mesh.crossings(ray, 0.0, INFINITY, fast, stats);
    mesh.crossings_brute_force(ray, 0.0, INFINITY, slow);
    ASSERT_EQ(fast.size(), slow.size()) << i;
    for (size_t k = 0; k < fast.size(); ++k) {
      EXPECT_EQ(fast[k].t, slow[k].t);
      EXPECT_EQ(fast[k].normal, slow[k].normal);
    }
    total += fast.size();
    const auto first = mesh.first_crossing(ray, 0.0, INFINITY, stats);
    ASSERT_EQ(first.has_value(), !slow.empty());
    if (first) {
      EXPECT_EQ(first->t, slow.front().t);
    }
    // A limited interval too.
    fast.clear();
    slow.clear();
    mesh.crossings(ray, 2.5, 3.5, fast, stats);
    mesh.crossings_brute_force(ray, 2.5, 3.5, slow);
    EXPECT_EQ(fast.size(), slow.size());
  }
  EXPECT_GT(total, 500u);
}

TEST(Mesh, BvhOfManyBoxesIsWellFormed) {
  std::vector<Box3> boxes;
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int i = 0; i < 100000; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    boxes.push_back(Box3{c - 0.5, c + 0.5});
  }
  // Many identical boxes too (equal centroids: median splits).
  for (int i = 0; i < 1000; ++i) boxes.push_back(Box3{Vec3(0.0), Vec3(1.0)});
  const Bvh bvh(boxes);
  // Every box is visited by a ray through its centre.
  for (int i = 0; i < 200; ++i) {
    const size_t target = size_t(rng() % boxes.size());
    const Vec3 c = 0.5 * (boxes[target].lo + boxes[target].hi);
    const Ray ray{c - 300.0 * Vec3(0, 0, 1), Vec3(0, 0, 1)};
    bool seen = false;
    double reach = INFINITY;
    bvh.traverse(ray, 0.0, reach, [&](uint32_t k, double&) { seen |= k == target; });
    EXPECT_TRUE(seen) << target;
  }
  EXPECT_LT(bvh.node_count(), 2 * boxes.size());
}

TEST(Mesh, FlatAndSmoothNormals) {
  scene::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  mesh.normals = {{0, 0, 1}, glm::normalize(Vec3(1, 0, 1)), glm::normalize(Vec3(0, 1, 1))};
  mesh.faces.push_back({{0, 1, 2}});             // flat: the winding's normal, +z
  mesh.faces.push_back({{3, 4, 5}, {0, 1, 2}});  // smooth
  const ShapePtr shape = build_shape(*make_object(mesh));
  TraceStats stats;
  auto flat = shape->first_crossing(Ray{{0.25, 0.25, 2}, {0, 0, -1}}, 0.0, INFINITY, stats);
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->t, 2.0);
  EXPECT_EQ(flat->normal, Vec3(0, 0, 1));
  // At barycentric (u, v) = (0.5, 0.25): 0.25 n0 + 0.5 n1 + 0.25 n2, normalised.
  auto smooth = shape->first_crossing(Ray{{5.5, 0.25, 2}, {0, 0, -1}}, 0.0, INFINITY, stats);
  ASSERT_TRUE(smooth);
  const Vec3 expected =
      glm::normalize(0.25 * mesh.normals[0] + 0.5 * mesh.normals[1] + 0.25 * mesh.normals[2]);
  EXPECT_NEAR(glm::length(smooth->normal - expected), 0.0, 1e-15);
  EXPECT_FALSE(shape->inside({0.25, 0.25, 0}));  // no inside_vector: no inside
}

TEST(Mesh, PerFaceTexturesAndTheObjectsOwn) {
  scene::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  const auto red = testing::make_texture(1.0), own = testing::make_texture(0.5);
  mesh.textures = {red};
  mesh.faces.push_back({{0, 1, 2}, {-1, -1, -1}, 0});
  mesh.faces.push_back({{3, 4, 5}});
  auto object = make_object(mesh);
  object->texture = own;
  const ShapePtr shape = build_shape(*object);
  TraceStats stats;
  auto a = shape->first_crossing(Ray{{0.25, 0.25, 2}, {0, 0, -1}}, 0.0, INFINITY, stats);
  auto b = shape->first_crossing(Ray{{5.25, 0.25, 2}, {0, 0, -1}}, 0.0, INFINITY, stats);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->surface->texture, red);
  EXPECT_EQ(b->surface->texture, own);
}

TEST(Mesh, InsideVectorMakesASolidByParity) {
  auto mesh = cube_mesh();
  mesh.inside_vector = Vec3(0.3, 0.7, 0.2);
  const ShapePtr cube = build_shape(*make_object(mesh));
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const bool expected = std::abs(p.x) < 1 && std::abs(p.y) < 1 && std::abs(p.z) < 1;
    EXPECT_EQ(cube->inside(p), expected) << p.x << " " << p.y << " " << p.z;
  }
  // As a solid it works in CSG: the cube minus a sphere has the sphere's dimple.
  const ShapePtr cut = build_shape(
      *make_object(scene::Csg{scene::CsgOperation::difference,
                              {make_object(mesh), make_object(scene::Sphere{{0, 1, 0}, 0.5})}}));
  const auto t = testing::crossing_distances(*cut, Ray{{0.01, 5, 0.02}, {0, -1, 0}}, 0, INFINITY);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 4.5, 1e-3);
  EXPECT_EQ(t[1], 6.0);
}

// A UV sphere of radius 1 with 2 * rings * segments triangles (poles included).
scene::TriangleMesh uv_sphere(int rings, int segments) {
  scene::TriangleMesh mesh;
  for (int i = 0; i <= rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      mesh.vertices.push_back(
          Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  }
  auto at = [&](int i, int j) { return i * segments + (j % segments); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      mesh.faces.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
      mesh.faces.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
  }
  return mesh;
}

TEST(Mesh, LargeClosedMeshIsFastAndASolid) {
  auto mesh = uv_sphere(300, 350);  // 210,000 faces (the poles' slivers have no area)
  mesh.inside_vector = Vec3(0.1, 0.2, 1.0);
  const auto start = std::chrono::steady_clock::now();
  const ShapePtr sphere = build_shape(*make_object(mesh));
  const double build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(build_seconds, 2.0);
  std::mt19937_64 rng(45);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Ray ray = testing::random_ray(rng, {0, 0, 0}, 3.0, 0.9);
    const auto hit = sphere->first_crossing(ray, 0.0, INFINITY, stats);
    // The chords' sagitta is below 1e-4: hits lie on the unit sphere to that.
    ASSERT_TRUE(hit) << i;
    ++hits;
    EXPECT_NEAR(glm::length(ray.at(hit->t)), 1.0, 1e-4);
    const auto all = testing::crossing_distances(*sphere, ray, 0.0, INFINITY);
    EXPECT_EQ(all.size() % 2, 0u) << i;
    EXPECT_TRUE(sphere->inside(ray.at(0.5 * (all.front() + all.back()))) || all.size() != 2);
  }
  EXPECT_EQ(hits, 5000);
}

TEST(Mesh, BadIndicesAreInputErrors) {
  scene::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.faces.push_back({{0, 1, 3}});
  EXPECT_THROW(build_shape(*make_object(mesh)), InputError);
  mesh.faces = {{{0, 1, 2}, {0, 1, 2}}};  // normals that are not there
  EXPECT_THROW(build_shape(*make_object(mesh)), InputError);
  mesh.faces = {{{0, 1, 2}, {-1, -1, -1}, 4}};  // a texture that is not there
  EXPECT_THROW(build_shape(*make_object(mesh)), InputError);
}

}  // namespace
}  // namespace convray::geometry
