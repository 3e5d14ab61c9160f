// Blobs and convolution objects: a single blob sphere against its analytic sphere, placed
// implicit objects against ConvolutionSurface itself, the inside rules, and per-component
// textures.
#include "geometry/implicit_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field/arc.hpp"
#include "field/blob.hpp"
#include "field/point.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "implicit/convolution_surface.hpp"

#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using testing::make_object;

scene::Implicit single_blob_sphere(const Vec3& center, double strength, double radius,
                                   double threshold) {
  scene::Implicit blob;
  blob.object.blob_spheres.push_back({center, {strength, radius}});
  blob.object.threshold = threshold;
  blob.component_order = {{scene::Implicit::Kind::blob_sphere, 0}};
  blob.is_blob = true;
  return blob;
}

TEST(Implicit, OneBlobSphereIsTheAnalyticSphere) {
  // s (1 - d^2/r^2)^2 = T at d = r sqrt(1 - sqrt(T / s)).
  const double s = 2.0, r = 1.5, T = 0.6;
  const Vec3 c(0.3, -0.2, 1.0);
  const double radius = r * std::sqrt(1.0 - std::sqrt(T / s));
  const ShapePtr blob = testing::build(single_blob_sphere(c, s, r, T));
  std::mt19937_64 rng(51);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Ray ray = testing::random_ray(rng, c, 5.0, 1.2 * radius);
    const Vec3 w = ray.origin - c;
    const double b = glm::dot(w, ray.direction);
    const double disc = b * b - (glm::dot(w, w) - radius * radius);
    std::vector<Crossing> out;
    TraceStats stats;
    blob->crossings(ray, 0.0, INFINITY, out, stats);
    if (std::abs(disc) < 1e-8) continue;
    if (disc < 0) {
      EXPECT_TRUE(out.empty());
      continue;
    }
    ASSERT_EQ(out.size(), 2u) << i;
    ++hits;
    const double roots[2] = {-b - std::sqrt(disc), -b + std::sqrt(disc)};
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(out[size_t(k)].t, roots[k], 1e-9 * radius);
      const Vec3 expected = glm::normalize(ray.at(roots[k]) - c);
      EXPECT_NEAR(glm::length(out[size_t(k)].normal - expected), 0.0, 1e-9);
    }
  }
  EXPECT_GT(hits, 300);
  // Inside: F > T - 1e-6 (POV-Ray's blob rule).
  EXPECT_TRUE(blob->inside(c));
  EXPECT_TRUE(blob->inside(c + Vec3(radius * (1 - 1e-9), 0, 0)));
  EXPECT_FALSE(blob->inside(c + Vec3(radius * 1.001, 0, 0)));
}

TEST(Implicit, PlacedObjectAgreesWithConvolutionSurfaceInItsOwnSpace) {
  scene::Implicit record;
  scene::ConvolutionObject& o = record.object;
  o.points.push_back({{0, 0, 0}, {1.0, 1.0}});
  o.segments.push_back({{{0.5, 0, 0}, {1.5, 0.5, 0}}, {1.0, 0.7}});
  o.points.push_back({{0.6, 0.4, 0}, {-0.5, 0.5}});  // negative strengths subtract
  o.threshold = 0.25;
  const scene::Transform placement =
      scene::Transform::rotation({10, 20, 30}).then(scene::Transform::translation({2, 0, -1}));
  const ShapePtr shape = testing::build(record, placement);
  const implicit::ConvolutionSurface surface(o);
  std::mt19937_64 rng(52);
  int compared = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray world = testing::random_ray(rng, {2.7, 0.2, -1}, 5.0, 1.2);
    // A rotation keeps distances: the same ray in the object's space.
    const Ray local{placement.inverse_point(world.origin),
                    glm::normalize(placement.inverse_vector(world.direction))};
    std::vector<double> expected;
    TraceStats stats;
    surface.roots(local, 0.0, 20.0, expected, stats);
    std::vector<Crossing> out;
    shape->crossings(world, 0.0, 20.0, out, stats);
    ASSERT_EQ(out.size(), expected.size()) << i;
    for (size_t k = 0; k < out.size(); ++k) {
      EXPECT_NEAR(out[k].t, expected[k], 1e-12);
      const Vec3 local_normal = implicit::make_surface_hit(surface, local, expected[k]).normal;
      EXPECT_NEAR(glm::length(out[k].normal - placement.vector(local_normal)), 0.0, 1e-9);
      ++compared;
    }
    // inside() is F >= T at the placed point.
    const Vec3 p = world.at(5.0);
    EXPECT_EQ(shape->inside(p), surface.field(local.at(5.0)).value >= o.threshold);
  }
  EXPECT_GT(compared, 100);
}

TEST(Implicit, ImplicitObjectsInCsgAgreeWithInsideChanges) {
  scene::Implicit record = single_blob_sphere({0, 0, 0}, 1.0, 1.0, 0.2);
  record.object.blob_spheres.push_back({{0.8, 0, 0}, {1.0, 1.0}});
  record.component_order.push_back({scene::Implicit::Kind::blob_sphere, 1});
  // POV-Ray's blob rule F > T - 1e-6 moves the inside ~1e-6 off the surface; the
  // convolution rule F >= T is exact, so it is the one compared to the last bit here.
  record.is_blob = false;
  const ShapePtr shape = testing::build(
      scene::Csg{scene::CsgOperation::difference,
                 {make_object(record), make_object(scene::Box{{0.3, -2, -2}, {2, 2, 0}})}});
  std::mt19937_64 rng(53);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Ray ray = testing::random_ray(rng, {0.4, 0, 0}, 4.0, 1.0);
    checked += testing::check_crossings_against_inside(*shape, ray, 0.0, 8.0, 1e-9, 8000);
  }
  EXPECT_GT(checked, 150);
}

TEST(Implicit, DominantComponentGivesTheTexture) {
  scene::Implicit record = single_blob_sphere({-2, 0, 0}, 1.0, 1.0, 0.3);
  record.object.blob_spheres.push_back({{2, 0, 0}, {1.0, 1.0}});
  record.object.blob_spheres.push_back({{0, 3, 0}, {1.0, 1.0}});
  record.component_order.push_back({scene::Implicit::Kind::blob_sphere, 1});
  record.component_order.push_back({scene::Implicit::Kind::blob_sphere, 2});
  const auto left = testing::make_texture(0.2), right = testing::make_texture(0.8);
  record.component_textures = {{0, left}, {1, right}};
  auto object = make_object(record);
  const auto own = testing::make_texture(0.5);
  object->texture = own;
  const ShapePtr blob = build_shape(*object);
  TraceStats stats;
  const auto a = blob->first_crossing(Ray{{-2, 0, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  const auto b = blob->first_crossing(Ray{{2, 0, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  const auto c = blob->first_crossing(Ray{{0, 3, 5}, {0, 0, -1}}, 0, INFINITY, stats);
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(a->surface->texture, left);
  EXPECT_EQ(b->surface->texture, right);
  EXPECT_EQ(c->surface->texture, own);  // no texture of its own: the object's
  // A component texture for a component that does not exist is an input error.
  record.component_textures.push_back({7, left});
  EXPECT_THROW(build_shape(*make_object(record)), InputError);
}

// The dominant component at a point, found through the support index, is the one a brute-force
// sum of every component's closed-form field names (a mesh's field is the sum over all its
// triangles; no index involved).
TEST(Implicit, DominantComponentMatchesBruteForceSums) {
  using Kind = scene::Implicit::Kind;
  scene::Implicit record;
  scene::ConvolutionObject& o = record.object;
  scene::MeshComponent sheet;  // a wavy 12 x 12 grid of triangles around z = 0
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 12; ++j) {
      auto at = [](int u, int v) {
        return Vec3(-1.5 + 0.25 * u, -1.5 + 0.25 * v, 0.1 * std::sin(u + 0.5 * v));
      };
      sheet.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      sheet.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  sheet.weight = {1.0, 0.4};
  o.meshes.push_back(sheet);
  o.segments.push_back({{{-1, -1, 0.3}, {1, 1, 0.4}}, {2.0, 0.5}});
  field::Arc arc;
  ASSERT_TRUE(field::arc_through({-1, 1, -0.2}, {0, 1.4, -0.3}, {1, 1, -0.2}, arc));
  o.arcs.push_back({arc, {1.5, 0.5}});
  o.points.push_back({{0.5, -0.8, 0.2}, {3.0, 0.6}});
  o.blob_cylinders.push_back({{-1, 0.5, 0}, {-0.2, -0.6, 0.1}, {1.2, 0.5}});
  o.threshold = 0.3;
  const Kind kinds[] = {Kind::mesh, Kind::segment, Kind::arc, Kind::point, Kind::blob_cylinder};
  std::vector<scene::TexturePtr> textures;
  for (size_t k = 0; k < 5; ++k) {
    record.component_order.push_back({kinds[k], 0});
    textures.push_back(testing::make_texture(0.1 + 0.15 * double(k)));
    record.component_textures.push_back({k, textures.back()});
  }
  auto own = std::make_shared<SurfaceInfo>();
  own->texture = testing::make_texture(0.99);
  const ImplicitShape shape(record, own);

  auto brute_force = [&](const Vec3& p) {
    double sums[5] = {0, 0, 0, 0, 0};
    for (const field::Triangle& t : sheet.triangles) sums[0] += field::triangle_value(p, t, 0.4);
    sums[1] = 2.0 * field::segment_value(p, o.segments[0].segment, 0.5);
    sums[2] = 1.5 * field::arc_value(p, arc, 0.5);
    sums[3] = 3.0 * field::point_value(p, o.points[0].center, 0.6);
    sums[4] = field::blob_cylinder_field(p, o.blob_cylinders[0].base, o.blob_cylinders[0].apex,
                                         0.5, 1.2).value;
    size_t best = 5;
    double largest = 0.0;
    for (size_t k = 0; k < 5; ++k) {
      if (sums[k] > largest) largest = sums[k], best = k;
    }
    return best == 5 ? own->texture : textures[best];
  };
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1.8, 1.8);
  int checked = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 p(coordinate(random), coordinate(random), 0.4 * coordinate(random));
    EXPECT_EQ(shape.surface_at(p)->texture, brute_force(p)) << p.x << " " << p.y << " " << p.z;
    checked += brute_force(p) != own->texture;
  }
  EXPECT_GT(checked, 1500);  // most points lie in some support
}

TEST(Implicit, ConvolutionInsideIsFieldAtLeastThreshold) {
  scene::Implicit record;
  record.object.points.push_back({{0, 0, 0}, {1.0, 2.0}});
  record.object.threshold = 0.5;
  const ShapePtr shape = testing::build(record);
  const double radius = 2.0 * std::sqrt(1.0 - std::sqrt(0.5));
  EXPECT_TRUE(shape->inside({radius * 0.999, 0, 0}));
  EXPECT_FALSE(shape->inside({radius * 1.001, 0, 0}));
  // A bad radius or threshold is an input error at the object.
  record.object.threshold = 0.0;
  try {
    testing::build(record);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 7);
  }
}

}  // namespace
}  // namespace convray::geometry
