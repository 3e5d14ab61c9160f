// Pictures of analytic shapes, checked against geometry and the Phong formula worked out
// independently here, and against themselves under different thread counts.
#include "render/render_image.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "analytic_shapes.hpp"

namespace convray::render {
namespace {

using testing::FloorShape;
using testing::ShapeGroup;
using testing::SphereShape;

Lighting black_background_lighting(const Vec3& light) {
  Lighting lighting;
  lighting.light.position = light;
  lighting.background = Vec3(0.0);  // every hit is brighter: ambient > 0, albedo > 0
  return lighting;
}

bool is_background(const Film& film, int i, int j) { return film.at(i, j) == Vec3(0.0); }

// A sphere of radius r centred on the optical axis at distance d is seen under the half-angle
// asin(r / d): a disk on the image plane of radius dl tan(asin(r/d)), where dl is the
// direction's length; the image plane spans H pixels per unit.
TEST(RenderImage, SphereSilhouetteIsTheProjectedDisk) {
  const int w = 120, h = 90;
  const double d = 10.0, r = 1.3, angle = 40.0;
  const SphereShape sphere(Vec3(0), r);
  const Camera camera({Vec3(0, 0, -d), Vec3(0), angle, w, h});
  const RenderResult result =
      render_image(sphere, camera, black_background_lighting(Vec3(-5, 5, -10)));

  const double dl = 0.5 * (double(w) / h) / std::tan(angle * kPi / 360.0);
  const double half_angle = std::asin(r / d);
  const double rho = h * dl * std::tan(half_angle);  // disk radius in pixels (~18.5)
  int count = 0, misclassified = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const bool hit = !is_background(result.film, i, j);
      count += hit;
      // Each pixel on its own: its centre ray, by hand, against the cone of the sphere.
      const Vec3 ray((i + 0.5 - 0.5 * w) / h, (0.5 * h - j - 0.5) / h, dl);
      const double off_axis = std::acos(ray.z / glm::length(ray));
      if (std::abs(off_axis - half_angle) > 1e-9) misclassified += hit != (off_axis < half_angle);
    }
  }
  EXPECT_EQ(misclassified, 0);
  // Counting pixel centres in a disk of radius rho misses its area pi rho^2 by the lattice
  // error of Gauss's circle problem, which stays far below the perimeter 2 pi rho (it grows
  // like rho^(2/3)); rho/2 pixels (~0.8% of the area here) is a tolerance that still catches
  // a half-pixel shift of the sampling grid (which changes the count by about rho).
  EXPECT_NEAR(count, kPi * rho * rho, 0.5 * rho);
  EXPECT_EQ(result.stats.camera_rays, uint64_t(w * h));
  EXPECT_EQ(result.stats.hits, uint64_t(count));
}

TEST(RenderImage, ShadingAtTheCentreFollowsPhong) {
  // The centre pixel's ray meets the sphere at p = <0, 0, -r>, normal N = <0, 0, -1>,
  // looking back at the viewer: V = N.
  const double r = 2.0;
  const Vec3 light(-3, 4, -6);
  const Lighting lighting = black_background_lighting(light);
  const Material& m = lighting.material;
  const SphereShape sphere(Vec3(0), r);
  const Camera camera({Vec3(0, 0, -8), Vec3(0), 30.0, 11, 9});
  const RenderResult result = render_image(sphere, camera, lighting);

  const Vec3 p(0, 0, -r), n(0, 0, -1), v(0, 0, -1);
  const Vec3 l = glm::normalize(light - p);  // <-3, 4, -4> / sqrt(41)
  const double n_dot_l = 4.0 / std::sqrt(41.0);
  ASSERT_NEAR(glm::dot(n, l), n_dot_l, 1e-15);
  const Vec3 mirror = 2.0 * n_dot_l * n - l;  // reflection of l about n
  const double highlight = m.specular * std::pow(glm::dot(mirror, v), m.shininess);
  const Vec3 expected = m.color * m.ambient + m.color * m.diffuse * n_dot_l + Vec3(highlight);
  const Vec3 centre = result.film.at(5, 4);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected[c], 1e-6 * expected[c]) << c;
}

// A ball above a floor, lit from straight above: the floor under the ball is in its shadow.
std::unique_ptr<ShapeGroup> ball_on_floor() {
  auto group = std::make_unique<ShapeGroup>();
  group->add(std::make_unique<SphereShape>(Vec3(0), 0.5));
  group->add(std::make_unique<FloorShape>(-1.0, 4.0));
  return group;
}

TEST(RenderImage, HardShadowsLeaveOnlyTheAmbientTerm) {
  const auto scene = ball_on_floor();
  const Lighting lighting = black_background_lighting(Vec3(0, 10, 0));
  const Material& m = lighting.material;
  // Look at two floor points from in front: one in the ball's shadow, one well outside it.
  // The shadow ray from <0, -1, -0.3> to the light passes z = -0.27 at y = 0: inside the ball.
  // The view ray from <0, 0, -6> passes below the ball (y = -0.96 at z = -0.5).
  const Camera shadowed({Vec3(0, 0, -6), Vec3(0, -1, -0.3), 20.0, 9, 9});
  const Vec3 dark = render_image(*scene, shadowed, lighting).film.at(4, 4);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(dark[c], m.color[c] * m.ambient, 1e-6) << c;

  const Vec3 floor_point(2.5, -1, -0.3);
  const Camera lit({Vec3(0, 0, -6), floor_point, 20.0, 9, 9});
  const Vec3 bright = render_image(*scene, lit, lighting).film.at(4, 4);
  const Vec3 l = glm::normalize(Vec3(0, 10, 0) - floor_point);
  const Vec3 v = glm::normalize(Vec3(0, 0, -6) - floor_point);
  const Vec3 mirror = 2.0 * l.y * Vec3(0, 1, 0) - l;
  const Vec3 expected =
      m.color * (m.ambient + m.diffuse * l.y) +
      Vec3(m.specular * std::pow(std::max(glm::dot(mirror, v), 0.0), m.shininess));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(bright[c], expected[c], 1e-6) << c;
}

TEST(RenderImage, ShadowsCanBeTurnedOff) {
  const auto scene = ball_on_floor();
  Lighting lighting = black_background_lighting(Vec3(0, 10, 0));
  lighting.shadows = false;
  const Camera shadowed({Vec3(0, 0, -6), Vec3(0, -1, -0.3), 20.0, 9, 9});
  const RenderResult result = render_image(*scene, shadowed, lighting);
  EXPECT_GT(result.film.at(4, 4).g, 2.0 * lighting.material.color.g * lighting.material.ambient);
  EXPECT_EQ(result.stats.shadow_rays, 0u);
}

TEST(RenderImage, SameBytesForAnyThreadCountAndTileSize) {
  const auto scene = ball_on_floor();
  const Lighting lighting = black_background_lighting(Vec3(-4, 6, -5));
  const Camera camera({Vec3(1, 1.5, -5), Vec3(0, -0.5, 0), 45.0, 97, 61});
  const auto render_with = [&](int threads, int tile) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return render_image(*scene, camera, lighting, nullptr, tile);
  };
  const RenderResult one = render_with(1, 16);
  for (const auto& [threads, tile] : {std::pair{2, 16}, std::pair{2, 7}, std::pair{8, 1}}) {
    const RenderResult other = render_with(threads, tile);
    ASSERT_EQ(one.film.rgb().size(), other.film.rgb().size());
    EXPECT_TRUE(std::equal(one.film.rgb().begin(), one.film.rgb().end(), other.film.rgb().begin()))
        << threads << " threads, tile " << tile;
    EXPECT_EQ(one.stats.shadow_rays, other.stats.shadow_rays);
    EXPECT_EQ(one.stats.trace.rays, other.stats.trace.rays);
  }
  EXPECT_GT(one.stats.hits, 0u);
  EXPECT_GT(one.stats.shadow_rays, 0u);
}

TEST(RenderImage, RaysMissingTheBoundsNeverReachTheSurface) {
  // A sphere far to the side: every camera ray misses its box, so the surface is never asked.
  const SphereShape sphere(Vec3(100, 0, 0), 1.0);
  const Camera camera({Vec3(0, 0, -5), Vec3(0), 40.0, 16, 12});
  const RenderResult result =
      render_image(sphere, camera, black_background_lighting(Vec3(0, 5, -5)));
  EXPECT_EQ(result.stats.queries, 0u);
  EXPECT_EQ(result.stats.trace.rays, 0u);
  EXPECT_EQ(result.stats.camera_rays, 16u * 12u);
}

}  // namespace
}  // namespace convray::render
