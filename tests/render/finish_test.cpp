// POV-Ray 3.7's lighting formulas at a chosen normal, light and view, against values worked
// out by hand (and, for the constants, against POV-Ray renders: see finish.hpp).
#include "render/finish.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace convray::render {
namespace {

constexpr double kTol = 1e-12;

void expect_near(const Vec3& actual, const Vec3& expected, double tol = kTol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

// A surface facing -z seen head-on (view along +z), light up and to the side: 3-4-5 angles.
const Vec3 kNormal(0, 0, -1);
const Vec3 kView(0, 0, 1);
const Vec3 kToLight = glm::normalize(Vec3(0, 3, -4));  // N.L = 0.8

TEST(Finish, AmbientIsAmbientTimesLightTimesPigment) {
  scene::Finish finish;
  finish.ambient = Vec3(0.2, 0.1, 0.4);
  expect_near(ambient_term(finish, Vec3(1.0, 0.5, 2.0), Vec3(0.5, 0.6, 0.25)),
              Vec3(0.2 * 1.0 * 0.5, 0.1 * 0.5 * 0.6, 0.4 * 2.0 * 0.25));
}

TEST(Finish, DiffuseIsLambertRaisedToTheBrilliance) {
  scene::Finish finish;
  finish.diffuse = 0.6;
  EXPECT_NEAR(diffuse_factor(finish, 0.8), 0.48, kTol);
  finish.brilliance = 3.0;
  EXPECT_NEAR(diffuse_factor(finish, 0.8), 0.6 * 0.512, kTol);
  EXPECT_EQ(diffuse_factor(finish, 0.0), 0.0);
  EXPECT_EQ(diffuse_factor(finish, -0.3), 0.0);
}

TEST(Finish, PhongUsesTheMirroredViewDirection) {
  scene::Finish finish;
  finish.phong = 0.5;
  finish.phong_size = 10.0;
  // Head-on view: the mirrored view is <0, 0, -1>, so R.L = 0.8.
  const Vec3 mirrored = kView - 2.0 * glm::dot(kView, kNormal) * kNormal;
  expect_near(mirrored, Vec3(0, 0, -1));
  EXPECT_NEAR(phong_factor(finish, mirrored, kToLight), 0.5 * std::pow(0.8, 10.0), kTol);
  EXPECT_EQ(phong_factor(finish, mirrored, Vec3(0, 0, 1)), 0.0);  // light behind R
}

TEST(Finish, SpecularUsesTheHalfVectorAndOneOverRoughness) {
  scene::Finish finish;
  finish.specular = 0.7;
  finish.roughness = 0.01;
  // H = normalize(L + V) with V = <0,0,-1>: L + V = <0, 0.6, -1.8>; N.H = 1.8 / sqrt(3.6).
  const double n_dot_h = 1.8 / std::sqrt(0.36 + 3.24);
  EXPECT_NEAR(specular_factor(finish, kNormal, kToLight, -kView), 0.7 * std::pow(n_dot_h, 100.0),
              1e-15);
}

TEST(Finish, MetallicFresnelCurve) {
  // Head-on light: x = 0, F = 0.014567225 / 1.2544 - 0.011612903 ~ 0 (clamped at 0).
  EXPECT_NEAR(metallic_fresnel(1.0), 0.0, 1e-6);
  // Grazing light: x = 1, F = 0.014567225 / 0.0144 - 0.011612903 = 1.0 (clamped).
  EXPECT_NEAR(metallic_fresnel(0.0), 1.0, 1e-6);
  // x = 0.5 (45 degrees): 0.014567225 / 0.3844 - 0.011612903.
  EXPECT_NEAR(metallic_fresnel(std::cos(kPi / 4)), 0.014567225 / 0.3844 - 0.011612903, 1e-12);
}

TEST(Finish, MetallicTintsHighlightsByThePigment) {
  scene::Finish finish;
  finish.metallic = 1.0;
  const Vec3 pigment(0.7, 0.5, 0.3);
  const double f = metallic_fresnel(0.8);
  expect_near(highlight_color(finish, Vec3(1.0), pigment, 0.8),
              Vec3(1.0) + (1.0 - f) * (pigment - Vec3(1.0)));
  finish.metallic = 0.0;
  expect_near(highlight_color(finish, Vec3(0.9), pigment, 0.8), Vec3(0.9));
}

TEST(Finish, OneLightAddsDiffuseAndHighlightsSeparately) {
  scene::Finish finish;
  finish.diffuse = 0.7;
  finish.phong = 1.0;
  const Vec3 pigment(0.5, 0.25, 1.0), light(1.0, 0.8, 0.6);
  const LightContribution lit =
      light_contribution(finish, pigment, kNormal, kView, kToLight, light);
  expect_near(lit.diffuse, 0.7 * 0.8 * light * pigment);
  expect_near(lit.highlight, std::pow(0.8, 40.0) * light);
}

TEST(Finish, NothingFromALightBehindTheSurface) {
  scene::Finish finish;
  finish.phong = 1.0;
  finish.specular = 1.0;
  const LightContribution lit =
      light_contribution(finish, Vec3(1.0), kNormal, kView, Vec3(0, 0.6, 0.8), Vec3(1.0));
  expect_near(lit.diffuse, Vec3(0.0));
  expect_near(lit.highlight, Vec3(0.0));
}

}  // namespace
}  // namespace convray::render
