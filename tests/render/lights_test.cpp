// How lights reach a point: the spotlight profile and fading against the formulas of the
// POV-Ray manual (as measured on POV-Ray 3.7 renders, see lights.hpp), parallel lights, and
// the sample points of area lights.
#include "render/lights.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace convray::render {
namespace {

double radians(double degrees) { return degrees * kPi / 180.0; }

scene::Light spotlight(double radius, double falloff, double tightness) {
  scene::Light light;
  light.kind = scene::Light::Kind::spotlight;
  light.position = Vec3(0, 0, -3);
  light.point_at = Vec3(0, 0, 0);
  light.radius = radius;
  light.falloff = falloff;
  light.tightness = tightness;
  return light;
}

// The direction from the light at `angle` degrees off the spot axis (+z).
Vec3 off_axis(double degrees) {
  return Vec3(std::sin(radians(degrees)), 0.0, std::cos(radians(degrees)));
}

TEST(Lights, SpotlightFullInsideRadiusNothingBeyondFalloff) {
  const scene::Light light = spotlight(10, 25, 0);
  EXPECT_DOUBLE_EQ(spotlight_factor(light, off_axis(0)), 1.0);
  EXPECT_DOUBLE_EQ(spotlight_factor(light, off_axis(9.9)), 1.0);
  EXPECT_DOUBLE_EQ(spotlight_factor(light, off_axis(25.1)), 0.0);
  EXPECT_DOUBLE_EQ(spotlight_factor(light, off_axis(90)), 0.0);
}

TEST(Lights, SpotlightSmoothstepInCosineBetweenRadiusAndFalloff) {
  // Values read from a POV-Ray 3.7 render (radius 10, falloff 25): 0.92869 at 13.594 degrees,
  // 0.51345 at 18.869, 0.03203 at 23.833.
  const scene::Light light = spotlight(10, 25, 0);
  EXPECT_NEAR(spotlight_factor(light, off_axis(13.594)), 0.92869, 5e-5);
  EXPECT_NEAR(spotlight_factor(light, off_axis(18.869)), 0.51345, 5e-5);
  EXPECT_NEAR(spotlight_factor(light, off_axis(23.833)), 0.03203, 5e-5);
  // And the formula itself: smoothstep of t = (cos a - cos falloff) / (cos radius - cos falloff).
  const double a = 17.0;
  const double t = (std::cos(radians(a)) - std::cos(radians(25))) /
                   (std::cos(radians(10)) - std::cos(radians(25)));
  EXPECT_NEAR(spotlight_factor(light, off_axis(a)), t * t * (3 - 2 * t), 1e-14);
}

TEST(Lights, SpotlightTightnessIsAPowerOfTheCosine) {
  // POV-Ray 3.7: radius 30, falloff 30, tightness 5 gives 0.86756 at 13.594 degrees.
  EXPECT_NEAR(spotlight_factor(spotlight(30, 30, 5), off_axis(13.594)), 0.86756, 5e-5);
  EXPECT_NEAR(spotlight_factor(spotlight(10, 25, 10), off_axis(6.201)),
              std::pow(std::cos(radians(6.201)), 10.0), 1e-14);
  EXPECT_NEAR(spotlight_factor(spotlight(10, 25, 10), off_axis(15.383)), 0.57562, 5e-5);
}

TEST(Lights, FadeIsTwoOverOnePlusDistanceRatioToThePower) {
  scene::Light light;
  light.fade_distance = 1.5;
  light.fade_power = 2.0;
  EXPECT_NEAR(fade_factor(light, 3.0), 2.0 / (1.0 + 4.0), 1e-15);
  EXPECT_NEAR(fade_factor(light, 1.5), 1.0, 1e-15);  // 1 at the fade distance
  light.fade_distance = 0.0;                         // no fading without a distance
  EXPECT_EQ(fade_factor(light, 100.0), 1.0);
}

TEST(Lights, PointLightArrival) {
  scene::Light light;
  light.position = Vec3(0, 4, -3);
  light.color.rgb = Vec3(0.5, 1.0, 2.0);
  const auto arrival = light_arrival(light, Vec3(0));
  ASSERT_TRUE(arrival);
  EXPECT_NEAR(arrival->distance, 5.0, 1e-15);
  EXPECT_NEAR(glm::length(arrival->to_light - Vec3(0, 0.8, -0.6)), 0.0, 1e-15);
  EXPECT_EQ(arrival->color, Vec3(0.5, 1.0, 2.0));
}

TEST(Lights, ParallelLightComesFromOneDirectionEverywhere) {
  scene::Light light;
  light.kind = scene::Light::Kind::parallel;
  light.position = Vec3(0.3, 0.2, -3);
  light.point_at = Vec3(0, 1, 0);
  const Vec3 expected = glm::normalize(Vec3(0.3, -0.8, -3));
  for (const Vec3& p : {Vec3(0), Vec3(10, -5, 3), Vec3(-100, 0, 100)}) {
    const auto arrival = light_arrival(light, p);
    ASSERT_TRUE(arrival);
    EXPECT_TRUE(std::isinf(arrival->distance));
    EXPECT_NEAR(glm::length(arrival->to_light - expected), 0.0, 1e-15);
  }
}

TEST(Lights, NoArrivalOutsideTheSpotCone) {
  const scene::Light light = spotlight(10, 25, 0);
  EXPECT_FALSE(light_arrival(light, Vec3(3, 0, -3 + 1)));  // 71.6 degrees off axis
  EXPECT_TRUE(light_arrival(light, Vec3(0.1, 0, 0)));
}

scene::Light area_light(int n1, int n2) {
  scene::Light light;
  light.position = Vec3(1, 2, 3);
  scene::AreaLight area;
  area.axis1 = Vec3(2, 0, 0);
  area.axis2 = Vec3(0, 0, 4);
  area.size1 = n1;
  area.size2 = n2;
  light.area = area;
  return light;
}

TEST(Lights, AreaLightGridSpansTheAxesCentredOnThePosition) {
  const std::vector<Vec3> points = area_light_points(area_light(3, 2), Vec3(0), 0);
  ASSERT_EQ(points.size(), 6u);
  // size1 = 3 along axis1 (length 2): x = 0, 1, 2; size2 = 2 along axis2 (length 4): z = 1, 5.
  std::set<std::pair<double, double>> xz;
  for (const Vec3& p : points) {
    EXPECT_EQ(p.y, 2.0);
    xz.insert({p.x, p.z});
  }
  const std::set<std::pair<double, double>> expected = {{0, 1}, {1, 1}, {2, 1},
                                                        {0, 5}, {1, 5}, {2, 5}};
  EXPECT_EQ(xz, expected);
}

TEST(Lights, JitteredAreaLightStaysInItsCellsAndRepeatsForTheSameSeed) {
  scene::Light light = area_light(4, 4);
  light.area->jitter = true;
  const auto a = area_light_points(light, Vec3(0), 42);
  const auto b = area_light_points(light, Vec3(0), 42);
  const auto c = area_light_points(light, Vec3(0), 43);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (const Vec3& p : a) {
    EXPECT_GE(p.x, 0.0);
    EXPECT_LE(p.x, 2.0);
    EXPECT_GE(p.z, 1.0);
    EXPECT_LE(p.z, 5.0);
  }
}

TEST(Lights, CircularAreaLightFitsInTheEllipseOfItsAxes) {
  scene::Light light = area_light(5, 5);
  light.area->circular = true;
  for (const Vec3& p : area_light_points(light, Vec3(0), 0)) {
    const double u = (p.x - 1.0) / 2.0, v = (p.z - 3.0) / 4.0;
    EXPECT_LE(u * u + v * v, 0.25 + 1e-12);
  }
}

TEST(Lights, OrientedAreaLightFacesThePoint) {
  scene::Light light = area_light(3, 3);
  light.area->orient = true;
  light.area->axis2 = Vec3(0, 0, 2);
  const Vec3 point(1, -8, 3);  // straight below: the light's plane must be horizontal
  for (const Vec3& p : area_light_points(light, point, 0)) EXPECT_NEAR(p.y, 2.0, 1e-12);
}

}  // namespace
}  // namespace convray::render
