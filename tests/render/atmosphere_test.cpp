// Fog against POV-Ray 3.7's measured values, ground fog's optical depth against quadrature,
// and the sky sphere's layering.
#include "render/atmosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace convray::render {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

scene::Fog constant_fog(double filter, double transmit) {
  scene::Fog fog;
  fog.distance = 8.0;
  fog.color = scene::Color{Vec3(0.2, 0.4, 0.9), filter, transmit};
  return fog;
}

const Ray kRay{Vec3(0, 0, -10), Vec3(0, 0, 1)};
const Vec3 kSurface(0.7, 0.5, 0.3);

// POV-Ray 3.7 renders: a plane of colour <0.7,0.5,0.3> 10 units away through fog distance 8,
// colour <0.2,0.4,0.9>; pixels read from 16-bit linear output.
TEST(Fog, ConstantFogMatchesPovRay) {
  const Vec3 plain = apply_fog(constant_fog(0, 0), kRay, 10.0, kSurface);
  EXPECT_NEAR(plain.r, 0.34325, 2e-5);
  EXPECT_NEAR(plain.g, 0.42866, 2e-5);
  EXPECT_NEAR(plain.b, 0.72810, 2e-5);
  const Vec3 filtered = apply_fog(constant_fog(0.5, 0), kRay, 10.0, kSurface);
  EXPECT_NEAR(filtered.r, 0.26304, 2e-5);
  EXPECT_NEAR(filtered.g, 0.38567, 2e-5);
  EXPECT_NEAR(filtered.b, 0.72380, 2e-5);
  const Vec3 transmitted = apply_fog(constant_fog(0, 0.5), kRay, 10.0, kSurface);
  EXPECT_NEAR(transmitted.r, 0.45, 2e-5);
  EXPECT_NEAR(transmitted.b, 0.60, 2e-5);
  const Vec3 both = apply_fog(constant_fog(0.3, 0.4), kRay, 10.0, kSurface);
  EXPECT_NEAR(both.r, 0.33280, 2e-5);
  EXPECT_NEAR(both.g, 0.40400, 2e-5);
  EXPECT_NEAR(both.b, 0.65640, 2e-5);
}

TEST(Fog, RaysLeavingTheSceneSeeTheFogColourOverTheBackground) {
  const Vec3 background(0.9, 0.1, 0.1);
  EXPECT_NEAR(apply_fog(constant_fog(0, 0), kRay, kInfinity, background).b, 0.9, 1e-12);
  // POV-Ray 3.7: transmit 0.5 lets half the background through: red 0.55.
  EXPECT_NEAR(apply_fog(constant_fog(0, 0.5), kRay, kInfinity, background).r, 0.55, 1e-12);
  EXPECT_NEAR(apply_fog(constant_fog(0.3, 0.4), kRay, kInfinity, background).r, 0.39361, 2e-5);
}

// The optical depth by the midpoint rule over many small steps.
double ground_fog_quadrature(const scene::Fog& fog, const Ray& ray, double depth) {
  const int steps = 200000;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double s = (k + 0.5) * depth / steps;
    const double u = (ray.at(s).y - fog.offset) / fog.altitude;
    sum += u <= 0.0 ? 1.0 : 1.0 / (1.0 + u * u);
  }
  return sum * depth / steps;
}

TEST(Fog, GroundFogDepthIsTheIntegralOfItsDensity) {
  scene::Fog fog;
  fog.kind = scene::Fog::Kind::ground;
  fog.offset = 0.5;
  fog.altitude = 2.0;
  for (const Ray& ray :
       {Ray{Vec3(0, -1, 0), glm::normalize(Vec3(0, 1, 2))},
        Ray{Vec3(0, 6, 0), glm::normalize(Vec3(1, -1, 1))},
        Ray{Vec3(0, 3, 0), Vec3(1, 0, 0)}, Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}}) {
    EXPECT_NEAR(ground_fog_depth(fog, ray, 12.0), ground_fog_quadrature(fog, ray, 12.0), 1e-6);
  }
  // Rising to infinity the density decays like 1/u^2: finite depth. Straight up from the
  // offset: integral of 1 / (1 + (s/2)^2) = 2 atan(infinity) = pi.
  EXPECT_NEAR(ground_fog_depth(fog, Ray{Vec3(0, 0.5, 0), Vec3(0, 1, 0)}, kInfinity), kPi,
              1e-12);
}

TEST(Fog, GroundFogDensityAsPovRay) {
  // POV-Ray 3.7, fog_type 2, distance 5, offset 0.2, alt 0.5, horizontal rays 10 units long
  // to a plane of colour <0.7,0.5,0.3>: red 0.57946 at y = 1.45, 0.30095 at y = 0.45 and
  // 0.26767 below the offset.
  scene::Fog fog;
  fog.kind = scene::Fog::Kind::ground;
  fog.distance = 5.0;
  fog.offset = 0.2;
  fog.altitude = 0.5;
  fog.color = scene::Color{Vec3(0.2, 0.4, 0.9)};
  auto red_at = [&](double y) {
    return apply_fog(fog, Ray{Vec3(0, y, -10), Vec3(0, 0, 1)}, 10.0, kSurface).r;
  };
  EXPECT_NEAR(red_at(1.45), 0.57946, 2e-5);
  EXPECT_NEAR(red_at(0.45), 0.30095, 2e-5);
  EXPECT_NEAR(red_at(-0.35), 0.26767, 2e-5);
}

TEST(Fog, SeveralFogsAddTheirColoursAsPovRay) {
  // POV-Ray 3.7: fogs of distance 8 and 20, colours <0.2,0.4,0.9> and <0.9,0.3,0.1>, over the
  // plane 10 units away: <0.61846, 0.49033, 0.73362> (fogging one fog with the other would
  // give <0.56232, 0.37803, 0.48096>).
  scene::Fog a = constant_fog(0, 0);
  scene::Fog b;
  b.distance = 20.0;
  b.color = scene::Color{Vec3(0.9, 0.3, 0.1)};
  const Vec3 seen = apply_fogs({a, b}, kRay, 10.0, kSurface);
  EXPECT_NEAR(seen.r, 0.61846, 2e-5);
  EXPECT_NEAR(seen.g, 0.49033, 2e-5);
  EXPECT_NEAR(seen.b, 0.73362, 2e-5);
}

TEST(SkySphere, LastPigmentOnTopOfTheRestAndTheBackground) {
  scene::Scene scene;
  scene.background.rgb = Vec3(0.0, 0.0, 1.0);
  EXPECT_EQ(sky_color(scene, Vec3(0, 0, 1)), Vec3(0, 0, 1));  // no sky sphere: background

  scene::SkySphere sky;
  scene::Pigment gradient;  // black at the horizon to white at the zenith
  gradient.space.pattern = scene::Pattern::gradient;
  gradient.space.gradient_axis = Vec3(0, 1, 0);
  gradient.color_map = {{0.0, scene::Color{Vec3(0.0), 0.0, 0.5}},
                        {1.0, scene::Color{Vec3(1.0), 0.0, 0.5}}};
  sky.pigments.push_back(gradient);
  scene.sky_sphere = sky;
  // Looking 30 degrees up: gradient 0.5, half transmitted: 0.5 * 0.5 + 0.5 * background.
  const Vec3 up30(0, 0.5, std::sqrt(0.75));
  const Vec3 seen = sky_color(scene, up30);
  EXPECT_NEAR(seen.r, 0.25, 1e-12);
  EXPECT_NEAR(seen.b, 0.75, 1e-12);

  scene::Pigment red;
  red.color.rgb = Vec3(1, 0, 0);
  // Below the gradient (listed first), hiding the background.
  scene.sky_sphere->pigments.insert(scene.sky_sphere->pigments.begin(), red);
  const Vec3 layered = sky_color(scene, up30);
  EXPECT_NEAR(layered.r, 0.75, 1e-12);  // 0.5 * 0.5 + 0.5 * 1
  EXPECT_NEAR(layered.b, 0.25, 1e-12);  // 0.5 * 0.5 + 0.5 * 0
}

}  // namespace
}  // namespace convray::render
