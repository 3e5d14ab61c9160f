// Whole renders of small scenes built as records (no parser), traced against the World,
// checked against values worked out by hand: Lambert shading, shadows (opaque, transparent,
// no_shadow, shadowless), mirrors, refraction through a slab, total internal reflection.
#include "render/render_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/world.hpp"
#include "render/scene_camera.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;

Film render(const scene::Scene& scene, int width, int height) {
  const geometry::World world(scene);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  return render_scene(scene, world, settings).film;
}

void expect_color(const Vec3& actual, const Vec3& expected, double tol = 2e-6) {
  EXPECT_NEAR(actual.r, expected.r, tol);
  EXPECT_NEAR(actual.g, expected.g, tol);
  EXPECT_NEAR(actual.b, expected.b, tol);
}

TEST(RenderScene, DiffuseSphereLitHeadOnIsLambert) {
  const Vec3 pigment(0.8, 0.6, 0.4);
  const Vec3 light(0, 4, -4);
  scene::Scene scene;
  scene.camera = look_at_camera(Vec3(0, 0, -10), Vec3(0), 30, 11, 11);
  scene.lights.push_back(point_light(light));
  scene.objects.push_back(sphere(Vec3(0), 1.0, plain_texture(rgb(0.8, 0.6, 0.4), 0.1, 0.7)));
  const Film film = render(scene, 11, 11);

  // The centre ray meets <0,0,-1>, normal <0,0,-1>; L = <0,4,-3>/5: N.L = 0.6.
  expect_color(film.at(5, 5), 0.1 * pigment + 0.7 * 0.6 * pigment);

  // Another pixel, intersected by hand.
  const SceneCamera camera(scene.camera, 11, 11);
  const Ray ray = camera.primary_ray(6, 4);
  const double b = glm::dot(ray.origin, ray.direction);
  const double t = -b - std::sqrt(b * b - (glm::dot(ray.origin, ray.origin) - 1.0));
  const Vec3 p = ray.at(t);
  const double n_dot_l = glm::dot(glm::normalize(p), glm::normalize(light - p));
  ASSERT_GT(n_dot_l, 0.0);
  expect_color(film.at(6, 4), 0.1 * pigment + 0.7 * n_dot_l * pigment);
  expect_color(film.at(0, 0), Vec3(0.0));  // background
}

// A white floor (y = -1) under a light at <5, 10, 0>; the centre pixel sees the floor at the
// origin's foot <0, -1, 0>, whose path to the light passes through <2.5, 4.5, 0>.
scene::Scene floor_scene() {
  scene::Scene scene;
  scene.camera = look_at_camera(Vec3(0, 2, -10), Vec3(0, -1, 0), 20, 11, 11);
  scene.lights.push_back(point_light(Vec3(5, 10, 0)));
  scene.objects.push_back(plane(Vec3(0, 1, 0), -1.0, plain_texture(rgb(1, 1, 1), 0.2, 0.8)));
  return scene;
}

const double kFloorNdotL = 11.0 / std::sqrt(146.0);

TEST(RenderScene, ShadowedPointSeesOnlyAmbient) {
  scene::Scene scene = floor_scene();
  expect_color(render(scene, 11, 11).at(5, 5), Vec3(0.2 + 0.8 * kFloorNdotL));
  scene.objects.push_back(sphere(Vec3(2.5, 4.5, 0), 1.0, plain_texture(rgb(1, 0, 0), 0.1, 0.6)));
  expect_color(render(scene, 11, 11).at(5, 5), Vec3(0.2));
}

TEST(RenderScene, TransparentBlockerDimsTheLightTwice) {
  scene::Scene scene = floor_scene();
  scene.objects.push_back(
      sphere(Vec3(2.5, 4.5, 0), 1.0, plain_texture(rgb(0.9, 0.6, 0.3, 0.4, 0.2), 0.1, 0.6)));
  // Each crossing passes filter * colour + transmit = <0.56, 0.44, 0.32>: in and out.
  const Vec3 passed = Vec3(0.56, 0.44, 0.32) * Vec3(0.56, 0.44, 0.32);
  expect_color(render(scene, 11, 11).at(5, 5), Vec3(0.2) + 0.8 * kFloorNdotL * passed);
}

TEST(RenderScene, NoShadowObjectsAndShadowlessLightsCastNoShadow) {
  scene::Scene scene = floor_scene();
  auto blocker = std::make_shared<scene::Object>(
      *sphere(Vec3(2.5, 4.5, 0), 1.0, plain_texture(rgb(1, 0, 0), 0.1, 0.6)));
  blocker->no_shadow = true;
  scene.objects.push_back(blocker);
  const Vec3 lit(0.2 + 0.8 * kFloorNdotL);
  expect_color(render(scene, 11, 11).at(5, 5), lit);

  blocker->no_shadow = false;
  scene.lights[0].shadowless = true;
  expect_color(render(scene, 11, 11).at(5, 5), lit);
}

TEST(RenderScene, AreaLightHalfHiddenGivesAPenumbra) {
  // A 2 x 1 area light over the floor point: a wall hides exactly the lights on one side.
  scene::Scene scene = floor_scene();
  scene.lights[0].position = Vec3(0, 10, 0);
  scene::AreaLight area;
  area.axis1 = Vec3(4, 0, 0);
  area.size1 = 2;
  area.size2 = 1;
  scene.lights[0].area = area;  // lights at x = -2 and x = +2
  // A wall at x in [0.95, 1.2], y in [4, 6]: the path to <2, 10, 0> (x = 2 (y + 1) / 11)
  // goes through it, the path to <-2, 10, 0> stays at x < 0.
  scene.objects.push_back(
      box(Vec3(0.95, 4, -1), Vec3(1.2, 6, 1), plain_texture(rgb(1, 1, 1), 0, 0)));
  // The lighting direction is the centre's (straight up, N.L = 1); visibility 1/2.
  expect_color(render(scene, 11, 11).at(5, 5), Vec3(0.2 + 0.8 * 0.5));
}

TEST(RenderScene, MirrorShowsReflectionTimesTheReflectedColour) {
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 4, 3);
  auto mirror = plain_texture(rgb(0, 0, 0), 0.0, 0.0);
  mirror->finish.reflection = Vec3(0.5, 0.25, 1.0);
  scene.objects.push_back(plane(Vec3(0, 0, -1), 0.0, mirror));                        // z = 0
  scene.objects.push_back(plane(Vec3(0, 0, 1), -20.0, glowing(rgb(0.2, 0.4, 0.6))));  // z = -20
  expect_color(render(scene, 4, 3).at(1, 1), Vec3(0.5 * 0.2, 0.25 * 0.4, 1.0 * 0.6));
}

// Two facing mirrors (z = 0 and z = -30, colours 0.1 and 0.2, reflection 0.5, ambient only):
// POV-Ray 3.7 gives 0.1, 0.2, 0.225, 0.25 for max_trace_level 1 to 4.
TEST(RenderScene, MaxTraceLevelCutsMirrorRecursionLikePovRay) {
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -20), 4, 3);
  auto a = glowing(rgb(0.1, 0.1, 0.1));
  a->finish.reflection = Vec3(0.5);
  auto b = glowing(rgb(0.2, 0.2, 0.2));
  b->finish.reflection = Vec3(0.5);
  scene.objects.push_back(plane(Vec3(0, 0, -1), 0.0, a));
  scene.objects.push_back(plane(Vec3(0, 0, 1), -30.0, b));
  const double expected[] = {0.1, 0.2, 0.225, 0.25};
  for (int level = 1; level <= 4; ++level) {
    scene.settings.max_trace_level = level;
    EXPECT_NEAR(render(scene, 4, 3).at(1, 1).r, expected[level - 1], 1e-6) << level;
  }
}

// Stacked transparent planes (colour 0.5, transmit 0.8, ambient 1) over a red background:
// POV-Ray 3.7 counts a straight-through ray as the same trace level, a bent one as the next.
TEST(RenderScene, TransparencyRecursionAndBailoutLikePovRay) {
  auto planes = [](int count, double ior, int max_level, double bailout) {
    scene::Scene scene;
    scene.camera = orthographic_camera(Vec3(0, 0, -20), 4, 3);
    scene.background = rgb(0.9, 0.1, 0.1);
    scene.settings.max_trace_level = max_level;
    scene.settings.adc_bailout = bailout;
    for (int k = 0; k < count; ++k) {
      scene.objects.push_back(plane(Vec3(0, 0, -1), 0.5 * k, glowing(rgb(0.5, 0.5, 0.5, 0, 0.8)),
                                    scene::Interior{ior}));
    }
    return render(scene, 4, 3).at(1, 1).r;
  };
  const double bailout = 1.0 / 255.0;
  EXPECT_NEAR(planes(3, 1.0, 1, bailout), 0.1, 1e-6);
  EXPECT_NEAR(planes(3, 1.0, 2, bailout), 0.7048, 1e-6);
  EXPECT_NEAR(planes(2, 1.5, 2, bailout), 0.18, 1e-6);
  EXPECT_NEAR(planes(3, 1.5, 3, bailout), 0.7048, 1e-6);
  EXPECT_NEAR(planes(3, 1.0, 5, 0.5), 0.7048, 1e-6);
  EXPECT_NEAR(planes(3, 1.0, 5, 0.7), 0.18, 1e-6);
  EXPECT_NEAR(planes(3, 1.0, 5, 0.9), 0.1, 1e-6);
}

TEST(RenderScene, GlassSlabShiftsTheRayByTheAnalyticAmount) {
  const double theta = 30.0 * kPi / 180.0, ior = 1.5, thickness = 2.0;
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 1, 1);
  scene.camera.direction = Vec3(std::sin(theta), 0, std::cos(theta));
  scene.objects.push_back(box(Vec3(-100, -100, 0), Vec3(100, 100, thickness),
                              plain_texture(rgb(1, 1, 1, 0, 1), 0, 0), scene::Interior{ior}));
  // The target z = 10 shows x as a grey level: (x + 20) / 40.
  auto target = glowing(rgb(0, 0, 0));
  target->pigment.space.pattern = scene::Pattern::gradient;
  target->pigment.space.transform =
      scene::Transform::scaling(Vec3(40)).then(scene::Transform::translation(Vec3(-20, 0, 0)));
  target->pigment.color_map = {{0.0, rgb(0, 0, 0)}, {1.0, rgb(1, 1, 1)}};
  scene.objects.push_back(plane(Vec3(0, 0, -1), -10.0, target));

  // Straight, the ray would meet the target at x = 20 tan(theta); the slab moves it back by
  // thickness (tan theta - tan phi), sin phi = sin theta / ior, and it leaves parallel.
  const double phi = std::asin(std::sin(theta) / ior);
  const double x = 20.0 * std::tan(theta) - thickness * (std::tan(theta) - std::tan(phi));
  const double seen_x = 40.0 * render(scene, 1, 1).at(0, 0).r - 20.0;
  EXPECT_NEAR(seen_x, x, 1e-5);
  EXPECT_GT(std::abs(seen_x - 20.0 * std::tan(theta)), 0.4);  // it did bend
}

// A glass wedge: entered head-on through z = 0, then the tilted face at `tilt` degrees of
// incidence from inside. Beyond the critical angle (41.81 degrees for ior 1.5) the ray
// reflects towards a green target; below it, it leaves the glass and misses the target.
Vec3 wedge_pixel(double tilt_degrees) {
  const double a = tilt_degrees * kPi / 180.0;
  scene::Csg wedge{scene::CsgOperation::intersection,
                   {plane(Vec3(0, 0, -1), 0.0, nullptr),
                    plane(Vec3(-std::sin(a), 0, std::cos(a)), 3.0, nullptr)}};
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 1, 1);
  scene.background = rgb(1, 0, 0);
  scene.objects.push_back(
      object(wedge, plain_texture(rgb(1, 1, 1, 0, 1), 0, 0), scene::Interior{1.5}));
  scene.objects.push_back(box(Vec3(5, -1, 0), Vec3(6, 1, 4.5), glowing(rgb(0, 1, 0))));
  return render(scene, 1, 1).at(0, 0);
}

TEST(RenderScene, TotalInternalReflectionBeyondTheCriticalAngle) {
  expect_color(wedge_pixel(45.0), Vec3(0, 1, 0));
  expect_color(wedge_pixel(42.6), Vec3(0, 1, 0));
  expect_color(wedge_pixel(41.0), Vec3(1, 0, 0));
}

TEST(RenderScene, FogAndBackgroundOnMissedRays) {
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 4, 3);
  scene.background = rgb(0.9, 0.1, 0.1);
  scene::Fog fog;
  fog.distance = 8.0;
  fog.color = rgb(0.2, 0.4, 0.9, 0.3, 0.4);
  scene.fogs.push_back(fog);
  scene.objects.push_back(box(Vec3(-10, -10, 0), Vec3(0, 10, 1), glowing(rgb(0.7, 0.5, 0.3))));
  const Film film = render(scene, 4, 3);
  // POV-Ray 3.7: 0.3328 red on the surface 10 units away, 0.39361 on the background.
  EXPECT_NEAR(film.at(0, 1).r, 0.3328, 2e-5);
  EXPECT_NEAR(film.at(3, 1).r, 0.39361, 2e-5);
}

TEST(RenderScene, AssumedGammaIsDecodedAtTheEndLikePovRay) {
  // POV-Ray 3.7, assumed_gamma 2.2: background <0.5,0.2,0.9> is written as the sRGB bytes of
  // <0.5^2.2, 0.2^2.2, 0.9^2.2> (128, 48, 230).
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), 4, 3);
  scene.background = rgb(0.5, 0.2, 0.9);
  scene.settings.assumed_gamma = 2.2;
  expect_color(render(scene, 4, 3).at(2, 1),
               Vec3(std::pow(0.5, 2.2), std::pow(0.2, 2.2), std::pow(0.9, 2.2)));
}

}  // namespace
}  // namespace convray::render
