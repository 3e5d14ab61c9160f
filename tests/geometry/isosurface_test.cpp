// Isosurfaces (geometry/isosurface.hpp) against exact intersections: a sphere and planes
// written as functions, whose crossings along random rays are known in closed form. Each
// crossing is reported as POV-Ray reports it (tests/app/povray_isosurface_test.cpp holds it
// against the binary's numbers): past the exact root by less than the accuracy, with the
// forward difference of f as its normal.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

#include "geometry/isosurface.hpp"
#include "geometry_test_support.hpp"

namespace convray::geometry {
namespace {

using scene::FunctionNode;
using scene::FunctionOp;

std::uint32_t parameter(scene::Function& f, std::uint32_t index) {
  FunctionNode n;
  n.op = FunctionOp::parameter;
  n.index = index;
  return f.add(n);
}

std::uint32_t binary(scene::Function& f, FunctionOp op, std::uint32_t a, std::uint32_t b) {
  FunctionNode n;
  n.op = op;
  const std::uint32_t operands[2] = {a, b};
  return f.add(n, operands);
}

// x*x + y*y + z*z - 1, built node by node.
std::shared_ptr<const scene::Function> unit_sphere_function() {
  auto f = std::make_shared<scene::Function>(std::vector<std::string>{"x", "y", "z"});
  std::uint32_t sum = f->add_constant(-1.0);
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t p = parameter(*f, i);
    sum = binary(*f, FunctionOp::add, sum, binary(*f, FunctionOp::multiply, p, p));
  }
  f->set_root(sum);
  return f;
}

std::shared_ptr<const scene::Function> y_function() {
  auto f = std::make_shared<scene::Function>(std::vector<std::string>{"x", "y", "z"});
  f->set_root(parameter(*f, 1));
  return f;
}

IsosurfaceShape make(const scene::Isosurface& iso) {
  auto surface = std::make_shared<SurfaceInfo>();
  surface->texture = testing::make_texture(1.0);
  return IsosurfaceShape(iso, surface);
}

// The exact crossings of the unit sphere, or none.
std::vector<double> sphere_roots(const Ray& ray) {
  const double b = glm::dot(ray.origin, ray.direction);
  const double c = glm::dot(ray.origin, ray.origin) - 1.0;
  const double d = b * b - c;
  if (d <= 0.0) return {};
  return {-b - std::sqrt(d), -b + std::sqrt(d)};
}

TEST(Isosurface, UnitSphereFunctionMatchesTheExactSphere) {
  scene::Isosurface iso;
  iso.function = unit_sphere_function();
  iso.box_lo = Vec3(-2.0);
  iso.box_hi = Vec3(2.0);
  iso.max_gradient = 7.0;  // |grad f| = 2 |p| <= 2 sqrt(12) in the box
  const IsosurfaceShape shape = make(iso);
  std::mt19937_64 rng(16);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const Ray ray = testing::random_ray(rng, Vec3(0.0), 5.0, 1.3);
    const std::vector<double> exact = sphere_roots(ray);
    const std::vector<Crossing> found = testing::crossings_of(shape, ray);
    // A ray that only grazes the sphere (a chord shorter than the accuracy) may be missed.
    if (exact.size() == 2 && exact[1] - exact[0] < 2e-3) continue;
    ASSERT_EQ(found.size(), exact.size()) << "ray " << i;
    for (std::size_t k = 0; k < exact.size(); ++k) {
      EXPECT_GE(found[k].t, exact[k] - 1e-12) << "ray " << i;  // never before the root
      EXPECT_LE(found[k].t, exact[k] + iso.accuracy) << "ray " << i;
      // The forward difference (2x + h, 2y + h, 2z + h) at the point reported, h = 0.001.
      const Vec3 p = ray.at(found[k].t);
      const Vec3 forward = glm::normalize(2.0 * p + Vec3(iso.accuracy));
      EXPECT_NEAR(glm::dot(found[k].normal, forward), 1.0, 1e-12) << "ray " << i;
      EXPECT_NEAR(glm::dot(found[k].normal, glm::normalize(p)), 1.0, 1e-6) << "ray " << i;
    }
    hits += exact.empty() ? 0 : 1;
  }
  EXPECT_GT(hits, 100);
  EXPECT_TRUE(shape.inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(shape.inside(Vec3(0.6, 0.6, 0.6)));
}

TEST(Isosurface, ClosedContainerShowsItsFacesWhereTheSolidReachesThem) {
  scene::Isosurface iso;  // f = y in the default box { -1, 1 }: the solid is y < 0
  iso.function = y_function();
  const IsosurfaceShape closed = make(iso);
  // From below: the container's bottom face, then the plane y = 0.
  const Ray up{Vec3(0.2, -3.0, 0.1), Vec3(0.0, 1.0, 0.0)};
  std::vector<Crossing> found = testing::crossings_of(closed, up);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].t, 2.0, 1e-12);
  EXPECT_NEAR(found[0].normal.y, -1.0, 1e-12);
  EXPECT_NEAR(found[1].t, 3.0, 1e-9);
  EXPECT_NEAR(found[1].normal.y, 1.0, 1e-6);
  // A slanted ray through the side of the solid: the side face x = 1, then y = 0.
  const Ray slanted{Vec3(3.0, -0.8, 0.0), glm::normalize(Vec3(-1.0, 0.25, 0.0))};
  found = testing::crossings_of(closed, slanted);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(slanted.at(found[0].t).x, 1.0, 1e-12);
  EXPECT_NEAR(slanted.at(found[1].t).y, 0.0, iso.accuracy);
  // open: only the plane.
  iso.open = true;
  found = testing::crossings_of(make(iso), up);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].t, 3.0, 1e-9);
}

TEST(Isosurface, SphereContainer) {
  scene::Isosurface iso;  // f = y within the sphere of radius 2 about (0, 1, 0)
  iso.function = y_function();
  iso.sphere_container = true;
  iso.center = Vec3(0.0, 1.0, 0.0);
  iso.radius = 2.0;
  const IsosurfaceShape shape = make(iso);
  // Straight down the axis: the plane y = 0 at t = 5, the sphere's bottom at y = -1 (t = 6).
  const Ray down{Vec3(0.0, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)};
  const std::vector<Crossing> found = testing::crossings_of(shape, down);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].t, 5.0, 1e-9);
  EXPECT_NEAR(found[1].t, 6.0, 1e-12);
  EXPECT_NEAR(found[1].normal.y, -1.0, 1e-12);
  TraceStats stats;
  const auto first = shape.first_crossing(down, 0.0, INFINITY, stats);
  ASSERT_TRUE(first.has_value());
  EXPECT_NEAR(first->t, 5.0, 1e-9);
}

// POV-Ray's minimum depth: a crossing within 5 accuracies of the ray's start is not reported
// (a shadow ray leaves a crossing from just past the root, inside the solid).
TEST(Isosurface, NoCrossingWithinFiveAccuraciesOfTheRayStart) {
  scene::Isosurface iso;
  iso.function = unit_sphere_function();
  iso.box_lo = Vec3(-2.0);
  iso.box_hi = Vec3(2.0);
  iso.max_gradient = 7.0;
  const IsosurfaceShape shape = make(iso);
  const Ray shallow{Vec3(0.0, 1.0 - 4.0 * iso.accuracy, 0.0), Vec3(0.0, 1.0, 0.0)};
  EXPECT_TRUE(testing::crossings_of(shape, shallow).empty());
  const Ray deeper{Vec3(0.0, 1.0 - 6.0 * iso.accuracy, 0.0), Vec3(0.0, 1.0, 0.0)};
  const std::vector<Crossing> found = testing::crossings_of(shape, deeper);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GE(found[0].t, 6.0 * iso.accuracy - 1e-12);
  EXPECT_LE(found[0].t, 7.0 * iso.accuracy);
}

TEST(Isosurface, ThreadsEvaluateOneShapeAtOnce) {
  scene::Isosurface iso;
  iso.function = unit_sphere_function();
  iso.max_gradient = 4.0;
  const IsosurfaceShape shape = make(iso);
  std::vector<double> first(4, 0.0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      const Ray ray{Vec3(0.0, 0.0, -5.0), Vec3(0.0, 0.0, 1.0)};
      for (int i = 0; i < 2000; ++i) first[std::size_t(k)] = testing::crossings_of(shape, ray)[0].t;
    });
  }
  for (std::thread& t : threads) t.join();
  for (double t : first) EXPECT_NEAR(t, 4.0, 1e-9);
}

}  // namespace
}  // namespace convray::geometry
