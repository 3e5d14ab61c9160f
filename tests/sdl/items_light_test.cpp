// Light sources and what surrounds the objects: background, fog, sky_sphere, global_settings.
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

scene::Light only_light(const ParseResult& result) {
  EXPECT_EQ(result.scene.lights.size(), 1u);
  return result.scene.lights.empty() ? scene::Light{} : result.scene.lights.front();
}

TEST(ItemsLight, PointLight) {
  const auto light = only_light(parse("light_source { <1, 2, 3> color red 1 green 0.5 }"));
  EXPECT_EQ(light.kind, scene::Light::Kind::point);
  expect_near(light.position, Vec3(1, 2, 3));
  expect_near(light.color.rgb, Vec3(1, 0.5, 0));
  EXPECT_FALSE(light.area.has_value());
}

TEST(ItemsLight, SpotlightWithItsSettingsAndTransforms) {
  const auto light = only_light(parse(R"(
    light_source { <0, 10, 0>, rgb 1
      spotlight point_at <0, 0, 0> radius 10 falloff 20 tightness 5
      fade_distance 4 fade_power 2 shadowless
      translate <1, 0, 0>
    })"));
  EXPECT_EQ(light.kind, scene::Light::Kind::spotlight);
  expect_near(light.position, Vec3(1, 10, 0));
  expect_near(light.point_at, Vec3(1, 0, 0));  // moved as a point
  EXPECT_EQ(light.radius, 10.0);
  EXPECT_EQ(light.falloff, 20.0);
  EXPECT_EQ(light.tightness, 5.0);
  EXPECT_EQ(light.fade_distance, 4.0);
  EXPECT_EQ(light.fade_power, 2.0);
  EXPECT_TRUE(light.shadowless);
}

TEST(ItemsLight, ParallelLightDefaultsToPovRaysSpotValues) {
  const auto light = only_light(parse("light_source { <0, 10, 0> rgb 1 parallel point_at 0 }"));
  EXPECT_EQ(light.kind, scene::Light::Kind::parallel);
  EXPECT_EQ(light.radius, 30.0);
  EXPECT_EQ(light.falloff, 45.0);
}

TEST(ItemsLight, AreaLightAxesTurnWithTheLight) {
  const auto light = only_light(parse(R"(
    light_source { 0, rgb 1
      area_light <2, 0, 0>, <0, 0, 2>, 4, 3 adaptive 1 jitter circular orient
      rotate 90*y
    })"));
  ASSERT_TRUE(light.area.has_value());
  expect_near(light.area->axis1, Vec3(0, 0, -2));
  expect_near(light.area->axis2, Vec3(2, 0, 0));
  EXPECT_EQ(light.area->size1, 4);
  EXPECT_EQ(light.area->size2, 3);
  EXPECT_EQ(light.area->adaptive, 1);
  EXPECT_TRUE(light.area->jitter);
  EXPECT_TRUE(light.area->circular);
  EXPECT_TRUE(light.area->orient);
}

TEST(ItemsLight, AreaSettingsMayComeFirstAndAreIgnoredWithoutAnAreaLight) {
  const auto first = only_light(parse("light_source { 0, 1 jitter area_light x, z, 2, 2 }"));
  ASSERT_TRUE(first.area.has_value());
  EXPECT_TRUE(first.area->jitter);
  const auto result = parse("light_source { 0, 1 jitter adaptive 1 }");
  EXPECT_FALSE(only_light(result).area.has_value());
  EXPECT_TRUE(has_warning(result, "area light settings without area_light are ignored"));
}

TEST(ItemsLight, DeclaredLightAndLooksLike) {
  const auto result = parse(R"(
    #declare L = light_source { <0, 5, 0> rgb 0.5 }
    light_source { L translate x looks_like { sphere { 0, 0.1 } } })");
  const auto light = only_light(result);
  expect_near(light.position, Vec3(1, 5, 0));
  expect_near(light.color.rgb, Vec3(0.5));
  EXPECT_TRUE(has_warning(result, "'looks_like' is ignored"));
}

TEST(ItemsLight, Errors) {
  EXPECT_TRUE(
      fails_with("light_source { 0, rgb 1 spotligth }", 1, 25, "did you mean 'spotlight'?"));
  EXPECT_TRUE(
      fails_with("light_source { 0, rgb 1 area_light x, y, 0, 2 }", 1, 25, "at least 1 light"));
  EXPECT_TRUE(fails_with("light_source { 0, rgb 1 spotlight point_at 0 }", 1, 1,
                         "point_at a point other than its location"));
}

TEST(ItemsAtmosphere, Background) {
  const auto result = parse("background { color rgb <0.1, 0.2, 0.3> }");
  expect_near(result.scene.background.rgb, Vec3(0.1, 0.2, 0.3));
}

TEST(ItemsAtmosphere, GroundFog) {
  const auto result = parse(R"(
    fog { fog_type 2 distance 20 color rgbt <1, 1, 1, 0.2> fog_offset 1 fog_alt 0.5
          turbulence 0.3 octaves 4 up <0, 0, 1> rotate 90*x })");
  ASSERT_EQ(result.scene.fogs.size(), 1u);
  const scene::Fog& fog = result.scene.fogs[0];
  EXPECT_EQ(fog.kind, scene::Fog::Kind::ground);
  EXPECT_EQ(fog.distance, 20.0);
  EXPECT_EQ(fog.color.transmit, 0.2);
  EXPECT_EQ(fog.offset, 1.0);
  EXPECT_EQ(fog.altitude, 0.5);
  expect_near(fog.turbulence.amount, Vec3(0.3));
  EXPECT_EQ(fog.turbulence.octaves, 4);
  expect_near(fog.up, Vec3(0, -1, 0));  // z turned 90 degrees about x
  // Fog turbulence is not rendered: the picture differs from POV-Ray's, so the scene is told.
  int told = 0;
  for (const std::string& warning : result.warnings) {
    told += warning.find("fog turbulence is not rendered") != std::string::npos;
  }
  EXPECT_EQ(told, 1);
}

TEST(ItemsAtmosphere, SkySphere) {
  const auto result = parse(R"(
    sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } }
                 pigment { bozo } rotate 10*x })");
  ASSERT_TRUE(result.scene.sky_sphere.has_value());
  EXPECT_EQ(result.scene.sky_sphere->pigments.size(), 2u);
  EXPECT_EQ(result.scene.sky_sphere->pigments[0].space.pattern, scene::Pattern::gradient);
  EXPECT_FALSE(result.scene.sky_sphere->transform.is_identity());
}

TEST(ItemsAtmosphere, GlobalSettings) {
  const auto result = parse(R"(
    global_settings { assumed_gamma 1.0 max_trace_level 10 ambient_light rgb <0.5, 0.5, 1>
                      adc_bailout 0.01 number_of_waves 5 radiosity { count 100 } })");
  const scene::GlobalSettings& settings = result.scene.settings;
  EXPECT_EQ(settings.assumed_gamma, 1.0);
  EXPECT_EQ(settings.max_trace_level, 10);
  expect_near(settings.ambient_light, Vec3(0.5, 0.5, 1));
  EXPECT_EQ(settings.adc_bailout, 0.01);
  EXPECT_TRUE(has_warning(result, "global setting 'number_of_waves' is ignored"));
  EXPECT_TRUE(has_warning(result, "global setting 'radiosity' is ignored"));
  EXPECT_FALSE(has_warning(result, "assumed_gamma"));
}

TEST(ItemsLight, MediaAttenuationSaysWhatIsLeftOut) {
  // convray renders no media: shadows dimmed by media cannot be drawn, and the warning says so.
  EXPECT_TRUE(has_warning(parse("light_source { <0, 5, 0> rgb 1 media_attenuation on }"),
                          "shadow rays are not dimmed by media"));
  EXPECT_FALSE(has_warning(parse("light_source { <0, 5, 0> rgb 1 media_attenuation off }"),
                           "media"));
  EXPECT_FALSE(has_warning(parse("light_source { <0, 5, 0> rgb 1 media_interaction off }"),
                           "media"));
}

TEST(ItemsAtmosphere, OlderScenesWithoutAssumedGammaAreNotGammaCorrected) {
  // POV-Ray 3.7's rule (tests/app/povray_gamma_test.cpp compares the pictures with povray's).
  const auto no_version = parse("sphere { 0, 1 }");
  EXPECT_FALSE(no_version.scene.settings.gamma_correction);
  EXPECT_TRUE(has_warning(no_version, "assumed_gamma not specified, so gamma_correction is "
                                      "turned off"));
  EXPECT_FALSE(parse("#version 3.6; sphere { 0, 1 }").scene.settings.gamma_correction);
  EXPECT_TRUE(parse("#version 3.6; sphere { 0, 1 } #version 3.7;").scene.settings.gamma_correction);
  EXPECT_TRUE(parse("#version 3.7; sphere { 0, 1 }").scene.settings.gamma_correction);
  const auto given = parse("#version 3.5; global_settings { assumed_gamma 1 }");
  EXPECT_TRUE(given.scene.settings.gamma_correction);
  EXPECT_FALSE(has_warning(given, "gamma_correction"));
}

TEST(ItemsAtmosphere, AssumedGammaOtherThanOneIsRenderedSoNotWarnedAbout) {
  // tests/app/povray_gamma_test.cpp renders assumed_gamma 2.2 as povray does.
  const auto result = parse("global_settings { assumed_gamma 2.2 }");
  EXPECT_EQ(result.scene.settings.assumed_gamma, 2.2);
  EXPECT_TRUE(result.warnings.empty());
}

TEST(ItemsAtmosphere, Errors) {
  EXPECT_TRUE(fails_with("fog { color rgb 1 }", 1, 1, "fog needs a distance"));
  EXPECT_TRUE(fails_with("fog { distance 1 fog_type 3 }", 1, 18, "fog_type must be 1"));
  EXPECT_TRUE(
      fails_with("global_settings { max_trace_lvl 3 }", 1, 19, "did you mean 'max_trace_level'?"));
  EXPECT_TRUE(fails_with("sky_sphere { }", 1, 1, "needs at least one pigment"));
}

}  // namespace
}  // namespace convray::sdl
