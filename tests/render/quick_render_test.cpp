// Pictures of `convray quick`'s scene (scene/quick_scene.hpp) through the one renderer: the
// silhouette of a sphere against the cone worked out by hand, and the centre pixel against
// the Phong formula written out here.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/world.hpp"
#include "render/render_scene.hpp"
#include "scene/quick_scene.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

// A quick-looking scene (its texture, one white light) of a plain sphere on black.
scene::Scene sphere_scene(double radius, const Vec3& light, const scene::LookAtView& view) {
  scene::Scene scene;
  scene.camera = scene::look_at_camera(view);
  scene.lights.push_back(testing::point_light(light));
  scene.objects.push_back(testing::sphere(Vec3(0), radius, scene::quick_texture()));
  return scene;
}

Film render(const scene::Scene& scene, int w, int h, RenderStats* stats = nullptr) {
  const geometry::World world(scene);
  RenderSettings settings;
  settings.width = w;
  settings.height = h;
  RenderResult result = render_scene(scene, world, settings);
  if (stats) *stats = result.stats;
  return result.film;
}

// A sphere of radius r centred on the optical axis at distance d is seen under the half-angle
// asin(r / d): a disk on the image plane of radius dl tan(asin(r/d)), where dl is the
// direction's length; the image plane spans H pixels per unit.
TEST(QuickRender, SphereSilhouetteIsTheProjectedDisk) {
  const int w = 120, h = 90;
  const double d = 10.0, r = 1.3, angle = 40.0;
  RenderStats stats;
  const Film film =
      render(sphere_scene(r, Vec3(-5, 5, -10), {Vec3(0, 0, -d), Vec3(0), angle, w, h}), w, h,
             &stats);

  const double dl = 0.5 * (double(w) / h) / std::tan(angle * kPi / 360.0);
  const double half_angle = std::asin(r / d);
  const double rho = h * dl * std::tan(half_angle);  // disk radius in pixels (~18.5)
  int count = 0, misclassified = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const bool hit = film.at(i, j) != Vec3(0.0);  // ambient > 0 everywhere on the sphere
      count += hit;
      // Each pixel on its own: its centre ray, by hand, against the cone of the sphere.
      const Vec3 ray((i + 0.5 - 0.5 * w) / h, (0.5 * h - j - 0.5) / h, dl);
      const double off_axis = std::acos(ray.z / glm::length(ray));
      if (std::abs(off_axis - half_angle) > 1e-9) misclassified += hit != (off_axis < half_angle);
    }
  }
  EXPECT_EQ(misclassified, 0);
  // Counting pixel centres in a disk of radius rho misses its area pi rho^2 by the lattice
  // error of Gauss's circle problem, far below the perimeter 2 pi rho; rho/2 pixels still
  // catches a half-pixel shift of the sampling grid (which changes the count by about rho).
  EXPECT_NEAR(count, kPi * rho * rho, 0.5 * rho);
  EXPECT_EQ(stats.camera_rays, uint64_t(w * h));
  EXPECT_EQ(stats.hits, uint64_t(count));
}

TEST(QuickRender, ShadingAtTheCentreFollowsPhong) {
  // The centre pixel's ray meets the sphere at p = <0, 0, -r>, normal N = <0, 0, -1>,
  // looking back at the viewer: V = N.
  const double r = 2.0;
  const Vec3 light(-3, 4, -6);
  const Film film = render(sphere_scene(r, light, {Vec3(0, 0, -8), Vec3(0), 30.0, 11, 9}), 11, 9);

  // quick's clay: albedo <0.80, 0.60, 0.42>, ambient 0.08, diffuse 0.85, a white Phong
  // highlight 0.3 (R.V)^40.
  const Vec3 albedo(0.80, 0.60, 0.42);
  const Vec3 p(0, 0, -r), n(0, 0, -1), v(0, 0, -1);
  const Vec3 l = glm::normalize(light - p);  // <-3, 4, -4> / sqrt(41)
  const double n_dot_l = 4.0 / std::sqrt(41.0);
  ASSERT_NEAR(glm::dot(n, l), n_dot_l, 1e-15);
  const Vec3 mirror = 2.0 * n_dot_l * n - l;  // reflection of l about n
  const double highlight = 0.3 * std::pow(glm::dot(mirror, v), 40.0);
  const Vec3 expected = albedo * 0.08 + albedo * 0.85 * n_dot_l + Vec3(highlight);
  const Vec3 centre = film.at(5, 4);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected[c], 1e-6 * expected[c]) << c;
}

}  // namespace
}  // namespace convray::render
