// Textures: pigments (colours, patterns, colour maps), finishes, normals, interiors, declared
// items and the #default texture every new texture starts from.
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

scene::Texture texture_of(const ParseResult& result) { return *only_object(result)->texture; }

TEST(ItemsTexture, FullTexture) {
  const auto result = parse(R"(
    sphere { 0, 1 texture {
      pigment { rgb <1, 0.5, 0> }
      finish { ambient 0.2 diffuse 0.7 brilliance 2 phong 1 phong_size 60 specular 0.3
               roughness 0.01 reflection 0.25 metallic emission rgb <0, 0, 0.5> }
      normal { bumps 0.3 scale 0.1 }
    } })");
  const scene::Texture& texture = texture_of(result);
  EXPECT_EQ(texture.pigment.space.pattern, scene::Pattern::solid);
  expect_near(texture.pigment.color.rgb, Vec3(1, 0.5, 0));
  const scene::Finish& finish = texture.finish;
  expect_near(finish.ambient, Vec3(0.2));
  EXPECT_EQ(finish.diffuse, 0.7);
  EXPECT_EQ(finish.brilliance, 2.0);
  EXPECT_EQ(finish.phong, 1.0);
  EXPECT_EQ(finish.phong_size, 60.0);
  EXPECT_EQ(finish.specular, 0.3);
  EXPECT_EQ(finish.roughness, 0.01);
  expect_near(finish.reflection, Vec3(0.25));
  EXPECT_EQ(finish.metallic, 1.0);  // `metallic` alone means 1
  expect_near(finish.emission, Vec3(0, 0, 0.5));
  EXPECT_EQ(texture.normal.space.pattern, scene::Pattern::bumps);
  EXPECT_EQ(texture.normal.amount, 0.3);
  expect_near(texture.normal.space.transform.point(Vec3(1, 1, 1)), Vec3(0.1));
}

TEST(ItemsTexture, RipplesAndWavesNormalsWarnThatTheyAreApproximated) {
  // Their bump functions are POV-Ray's own (not the pattern's slope), not matched yet.
  for (const char* pattern : {"ripples", "waves"}) {
    const auto result = parse(std::string("sphere { 0, 1 normal { ") + pattern + " 0.6 } }");
    EXPECT_TRUE(has_warning(result, "ripples and waves as normals are approximated")) << pattern;
  }
  const auto pigment = parse("sphere { 0, 1 pigment { ripples } normal { bumps 0.5 } }");
  EXPECT_FALSE(has_warning(pigment, "approximated"));
}

TEST(ItemsTexture, UnsetFinishValuesArePovRayDefaults) {
  const scene::Finish& finish = texture_of(parse("sphere { 0, 1 finish { phong 1 } }")).finish;
  expect_near(finish.ambient, Vec3(0.1));
  EXPECT_EQ(finish.diffuse, 0.6);
  EXPECT_EQ(finish.phong_size, 40.0);
}

TEST(ItemsTexture, DeclaredTextureIsTheStartingPoint) {
  const auto result = parse(R"(
    #declare T = texture { pigment { rgb <0, 1, 0> } finish { phong 1 } }
    sphere { 0, 1 texture { T finish { diffuse 0.3 } } })");
  const scene::Texture& texture = texture_of(result);
  expect_near(texture.pigment.color.rgb, Vec3(0, 1, 0));
  EXPECT_EQ(texture.finish.phong, 1.0);  // kept: finish { } modifies T's finish
  EXPECT_EQ(texture.finish.diffuse, 0.3);
}

TEST(ItemsTexture, DeclaredPigmentFinishNormal) {
  const auto result = parse(R"(
    #declare P = pigment { checker rgb 1, rgb 0 }
    #declare F = finish { ambient 0 }
    #declare N = normal { dents 0.8 }
    sphere { 0, 1 pigment { P scale 2 } finish { F } normal { N } })");
  const scene::Texture& texture = texture_of(result);
  EXPECT_EQ(texture.pigment.space.pattern, scene::Pattern::checker);
  expect_near(texture.pigment.space.transform.point(Vec3(1, 0, 0)), Vec3(2, 0, 0));
  expect_near(texture.finish.ambient, Vec3(0.0));
  EXPECT_EQ(texture.normal.space.pattern, scene::Pattern::dents);
  EXPECT_EQ(texture.normal.amount, 0.8);
}

TEST(ItemsTexture, CheckerColorsAndPovRayDefaults) {
  const auto& listed = texture_of(parse("plane { y, 0 pigment { checker rgb 1, rgb <1,0,0> } }"));
  ASSERT_EQ(listed.pigment.block_colors.size(), 2u);
  expect_near(listed.pigment.block_colors[0].rgb, Vec3(1.0));
  expect_near(listed.pigment.block_colors[1].rgb, Vec3(1, 0, 0));
  // POV-Ray 3.7 renders `checker` alone in blue and green (checked with povray).
  const auto& unlisted = texture_of(parse("plane { y, 0 pigment { checker } }"));
  ASSERT_EQ(unlisted.pigment.block_colors.size(), 2u);
  expect_near(unlisted.pigment.block_colors[0].rgb, Vec3(0, 0, 1));
  expect_near(unlisted.pigment.block_colors[1].rgb, Vec3(0, 1, 0));
}

TEST(ItemsTexture, GradientWithColorMapAndPatternModifiers) {
  const auto& pigment = texture_of(parse(R"(
    plane { y, 0 pigment {
      gradient <0, 1, 0>
      color_map { [0 color rgb 0] [0.5, rgb <1, 0, 0>] [1 rgbf <1, 1, 1, 0.5>] }
      turbulence 0.5 octaves 3 omega 0.7 lambda 3 frequency 2 phase 0.25
      rotate 90*x
    } })"))
                            .pigment;
  EXPECT_EQ(pigment.space.pattern, scene::Pattern::gradient);
  expect_near(pigment.space.gradient_axis, Vec3(0, 1, 0));
  ASSERT_EQ(pigment.color_map.size(), 3u);
  EXPECT_EQ(pigment.color_map[1].value, 0.5);
  expect_near(pigment.color_map[1].color.rgb, Vec3(1, 0, 0));
  EXPECT_EQ(pigment.color_map[2].color.filter, 0.5);
  expect_near(pigment.space.turbulence.amount, Vec3(0.5));
  EXPECT_EQ(pigment.space.turbulence.octaves, 3);
  EXPECT_EQ(pigment.space.turbulence.omega, 0.7);
  EXPECT_EQ(pigment.space.turbulence.lambda, 3.0);
  EXPECT_EQ(pigment.space.frequency, 2.0);
  EXPECT_EQ(pigment.space.phase, 0.25);
  expect_near(pigment.space.transform.point(Vec3(0, 1, 0)), Vec3(0, 0, 1));
}

TEST(ItemsTexture, OldTwoValueColorMapEntriesAndDeclaredMaps) {
  const auto& old_form = texture_of(
      parse("plane { y, 0 pigment { marble colour_map { [0.0, 0.5 color rgb 0 color rgb 1] } } }"));
  ASSERT_EQ(old_form.pigment.color_map.size(), 2u);
  EXPECT_EQ(old_form.pigment.color_map[1].value, 0.5);
  expect_near(old_form.pigment.color_map[1].color.rgb, Vec3(1.0));
  const auto declared = parse(R"(
    #declare M = color_map { [0 rgb 0] [1 rgb 1] }
    plane { y, 0 pigment { wood color_map { M } turbulence <0.1, 0.2, 0.3> } })");
  const auto& pigment = texture_of(declared).pigment;
  EXPECT_EQ(pigment.space.pattern, scene::Pattern::wood);
  EXPECT_EQ(pigment.color_map.size(), 2u);
  expect_near(pigment.space.turbulence.amount, Vec3(0.1, 0.2, 0.3));
}

// POV-Ray scans a map for the first entry at or above v and blends it with the entry
// before, in the order written. The ascending map stored must give the same colours.
TEST(ItemsTexture, ColorMapThatStepsBackKeepsPovRaysColors) {
  // woods.inc's T_Wood32 ends [0.85 A] [0.95 B] [0.90 C] [1.00 D]: for v in (0.95, 1] POV-Ray
  // blends C (at 0.90) and D (at 1.00); C alone is never the entry the scan stops at.
  const auto map = texture_of(parse(R"(
    plane { y, 0 pigment { wood color_map {
      [0.85 rgb <1, 0, 0>] [0.95 rgb <0, 1, 0>] [0.90 rgb <0, 0, 1>] [1.00 rgb <1, 1, 1>] } } })"))
                       .pigment.color_map;
  ASSERT_EQ(map.size(), 4u);
  EXPECT_EQ(map[1].value, 0.95);
  expect_near(map[1].color.rgb, Vec3(0, 1, 0));
  // The blend of C and D taken at 0.95: halfway from <0, 0, 1> to <1, 1, 1>.
  EXPECT_EQ(map[2].value, 0.95);
  expect_near(map[2].color.rgb, Vec3(0.5, 0.5, 1), 1e-12);
  EXPECT_EQ(map[3].value, 1.0);
}

TEST(ItemsTexture, ColorMapWhoseLastEntryStepsBackHoldsItAbove) {
  // [0 A] [1 B] [0.5 C]: at or above 0.5 POV-Ray gives C; below, the blend of A and B.
  const auto map = texture_of(parse("plane { y, 0 pigment { bozo color_map { [0 rgb 0] [1 rgb 1] "
                                    "[0.5 rgb <1, 0, 0>] } } }"))
                       .pigment.color_map;
  ASSERT_EQ(map.size(), 3u);
  EXPECT_EQ(map[1].value, 0.5);
  expect_near(map[1].color.rgb, Vec3(0.5), 1e-12);
  EXPECT_EQ(map[2].value, 0.5);
  expect_near(map[2].color.rgb, Vec3(1, 0, 0));
}

TEST(ItemsTexture, EveryPatternKeyword) {
  const char* words[] = {"marble", "wood",    "granite", "agate", "bozo",     "spotted", "radial",
                         "onion",  "leopard", "ripples", "waves", "wrinkles", "bumps",   "dents"};
  for (const char* word : words) {
    const auto result = parse(std::string("plane { y, 0 pigment { ") + word + " } }");
    EXPECT_NE(texture_of(result).pigment.space.pattern, scene::Pattern::solid) << word;
  }
}

TEST(ItemsTexture, NormalDefaultAmountIsPovRays) {
  // POV-Ray 3.7 renders `bumps` and `bumps 0.5` identically (checked with povray).
  const auto& normal = texture_of(parse("sphere { 0, 1 normal { wrinkles } }")).normal;
  EXPECT_EQ(normal.space.pattern, scene::Pattern::wrinkles);
  EXPECT_EQ(normal.amount, 0.5);
  EXPECT_EQ(texture_of(parse("sphere { 0, 1 normal { ripples bump_size 2 } }")).normal.amount, 2.0);
}

TEST(ItemsTexture, ReflectionBlockMinimumMaximumAndFresnel) {
  const auto result = parse(
      "sphere { 0, 1 finish { reflection { 0.1, rgb <0.6, 0.5, 0.4> fresnel on metallic } } }");
  const scene::Finish& finish = texture_of(result).finish;
  expect_near(finish.reflection, Vec3(0.6, 0.5, 0.4));
  expect_near(finish.reflection_min, Vec3(0.1));
  EXPECT_TRUE(finish.variable_reflection);
  EXPECT_TRUE(finish.fresnel);
  EXPECT_EQ(finish.reflection_metallic, 1.0);
  EXPECT_EQ(finish.metallic, 0.0);  // the finish's own metallic (highlights) is not set
}

TEST(ItemsTexture, ReflectionBlockMinimumAndMaximumWithoutAComma) {
  // gamma_showcase.pov writes `reflection { 0.0 1.0 fresnel on }`; POV-Ray reads both.
  const auto result = parse("sphere { 0, 1 finish { reflection { 0.2 1.0 fresnel on } } }");
  expect_near(texture_of(result).finish.reflection, Vec3(1.0));
  expect_near(texture_of(result).finish.reflection_min, Vec3(0.2));
  const auto colours = parse("sphere { 0, 1 finish { reflection { rgb 0.1 rgb <0.5, 0.6, 0.7> } } }");
  expect_near(texture_of(colours).finish.reflection, Vec3(0.5, 0.6, 0.7));
  EXPECT_TRUE(texture_of(colours).finish.variable_reflection);
}

TEST(ItemsTexture, ReflectionOneValueIsConstantUnlessFresnel) {
  const scene::Finish plain = texture_of(parse(
      "sphere { 0, 1 finish { reflection { 0.6 falloff 2 } conserve_energy } }")).finish;
  EXPECT_FALSE(plain.variable_reflection);
  EXPECT_EQ(plain.reflection_falloff, 2.0);
  EXPECT_TRUE(plain.conserve_energy);
  // POV-Ray's `reflection { 0.6 fresnel on }` goes from 0 to 0.6 (measured with povray).
  const scene::Finish fresnel =
      texture_of(parse("sphere { 0, 1 finish { reflection { 0.6 fresnel on } } }")).finish;
  EXPECT_TRUE(fresnel.variable_reflection);
  expect_near(fresnel.reflection_min, Vec3(0.0));
}

TEST(ItemsTexture, InteriorAndFade) {
  const auto result = parse(
      "sphere { 0, 1 interior { ior 1.5 fade_distance 2 fade_power 1 fade_color rgb <1, 0, 0> } }");
  const scene::Interior& interior = *only_object(result)->interior;
  EXPECT_EQ(interior.ior, 1.5);
  EXPECT_EQ(interior.fade_distance, 2.0);
  EXPECT_EQ(interior.fade_power, 1.0);
  EXPECT_EQ(interior.fade_color, Vec3(1, 0, 0));
  EXPECT_FALSE(has_warning(result, "fade"));
}

TEST(ItemsTexture, DefaultDirectiveFeedsNewTextures) {
  const auto result = parse(R"(
    #default { texture { pigment { rgb <0.5, 0.5, 0.5> } finish { ambient 0 } } }
    sphere { 0, 1 texture { finish { phong 1 } } })");
  const scene::Texture& texture = texture_of(result);
  expect_near(texture.pigment.color.rgb, Vec3(0.5));
  expect_near(texture.finish.ambient, Vec3(0.0));
  EXPECT_EQ(texture.finish.phong, 1.0);
}

TEST(ItemsTexture, TextureTransformsMovePigmentAndNormal) {
  const auto& texture = texture_of(
      parse("sphere { 0, 1 texture { pigment { checker } normal { bumps } translate x } }"));
  expect_near(texture.pigment.space.transform.point(Vec3(0.0)), Vec3(1, 0, 0));
  expect_near(texture.normal.space.transform.point(Vec3(0.0)), Vec3(1, 0, 0));
}

TEST(ItemsTexture, Errors) {
  EXPECT_TRUE(fails_with("sphere { 0, 1 pigment { chcker } }", 1, 25,
                         "unexpected 'chcker' in pigment (did you mean 'checker'?)"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 pigment { tiling 1 } }", 1, 25, "not supported yet"));
  EXPECT_TRUE(
      fails_with("sphere { 0, 1 finish { phong_sise 3 } }", 1, 24, "did you mean 'phong_size'?"));
  EXPECT_TRUE(
      fails_with("sphere { 0, 1 pigment { bozo octaves 0 } }", 1, 38, "octaves must lie in 1..10"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 pigment { bozo color_map { 0 } } }", 1, 42,
                         "expected '[' to start a color_map entry"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 interior { ior -1 } }", 1, 26, "ior must be positive"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { pigment { rgb 1 } material_map } }", 1, 43,
                         "not supported yet"));
}

TEST(ItemsTexture, TextureMapsAverageAndTiles) {
  const auto mapped = parse(
      "#declare T = texture { pigment { rgb 1 } }\n"
      "sphere { 0, 1 texture { gradient y texture_map { [0.2 T] [0.6, pigment { rgb x }] } } }");
  const scene::TextureMap& map = *texture_of(mapped).map;
  EXPECT_EQ(map.kind, scene::TextureMap::Kind::map);
  EXPECT_EQ(map.space.pattern, scene::Pattern::gradient);
  EXPECT_EQ(map.values, (std::vector<double>{0.2, 0.6}));
  ASSERT_EQ(map.textures.size(), 2u);
  EXPECT_EQ(map.textures[1]->pigment.color.rgb, Vec3(1, 0, 0));
  // An average's weights may be left out (1); tiles { A tile2 B } are checker blocks B, A.
  const auto average =
      parse("sphere { 0, 1 texture { average texture_map { [pigment { rgb 1 }] [3 pigment { "
            "rgb 0 }] } } }");
  EXPECT_EQ(texture_of(average).map->kind, scene::TextureMap::Kind::average);
  EXPECT_EQ(texture_of(average).map->values, (std::vector<double>{1.0, 3.0}));
  const auto tiles = parse(
      "plane { y, 0 texture { tiles { texture { pigment { rgb x } } tile2 texture { pigment { "
      "rgb y } } } } }");
  const scene::TextureMap& blocks = *texture_of(tiles).map;
  EXPECT_EQ(blocks.kind, scene::TextureMap::Kind::blocks);
  ASSERT_EQ(blocks.textures.size(), 2u);
  EXPECT_EQ(blocks.textures[0]->pigment.color.rgb, Vec3(0, 1, 0));
  EXPECT_EQ(blocks.textures[1]->pigment.color.rgb, Vec3(1, 0, 0));
}

TEST(ItemsTexture, AveragePigmentWeightsInAnyOrder) {
  const auto result = parse(
      "sphere { 0, 1 pigment { average pigment_map { [3 rgb x] [rgb y] [0.5 rgb z] } } }");
  const scene::Pigment& pigment = texture_of(result).pigment;
  EXPECT_EQ(pigment.space.pattern, scene::Pattern::average);
  ASSERT_EQ(pigment.pigment_map.size(), 3u);
  EXPECT_EQ(pigment.pigment_map[0].value, 3.0);
  EXPECT_EQ(pigment.pigment_map[1].value, 1.0);
  EXPECT_EQ(pigment.pigment_map[2].value, 0.5);
  EXPECT_TRUE(fails_with("sphere { 0, 1 pigment { average } }", 1, 15,
                         "an average pigment needs a pigment_map"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 pigment { average pigment_map { [-2 rgb 1] } } }", 1, 48,
                         "must not be negative"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 normal { average } }", 1, 24, "not supported yet"));
}

TEST(ItemsTexture, TextureMapErrors) {
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { gradient x } }", 1, 15,
                         "this texture's pattern picks no textures"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { texture_map { [0 pigment { rgb 1 }] } } }", 1,
                         25, "a texture_map needs a pattern before it"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { bozo texture_map { [0.5 pigment { rgb 1 }] "
                         "[0.2 pigment { rgb 0 }] } } }",
                         1, 69, "ascending order"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { average texture_map { [-1 pigment { rgb 1 }] "
                         "} } }",
                         1, 48, "must not be negative"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { gradient x texture_map { } } }", 1, 36,
                         "texture_map has no entries"));
  EXPECT_TRUE(fails_with("sphere { 0, 1 texture { gradient x pigment { rgb 1 } } }", 1, 36,
                         "takes no pigment of its own"));
}

}  // namespace
}  // namespace convray::sdl

namespace convray::sdl {
namespace {

// POV-Ray: a top-level object without a texture takes the #default texture in force where it
// ends; objects before the #default keep the built-in one (black); CSG children without a
// texture are left to inherit their parent's.
TEST(ItemsTexture, DefaultTextureReachesUntexturedObjects) {
  const ParseResult result = testing::parse(R"(
    plane { y, 0 }
    #default { texture { pigment { rgb 0.8 } finish { phong 0.5 } } }
    plane { y, 1 }
    union { sphere { 0, 1 } sphere { x, 1 } }
    sphere { 0, 1 pigment { rgb <1, 0, 0> } })");
  ASSERT_EQ(result.scene.objects.size(), 4u);
  const auto& objects = result.scene.objects;
  ASSERT_TRUE(objects[0]->texture);
  EXPECT_EQ(objects[0]->texture->pigment.color.rgb, Vec3(0.0));
  ASSERT_TRUE(objects[1]->texture);
  EXPECT_EQ(objects[1]->texture->pigment.color.rgb, Vec3(0.8));
  EXPECT_EQ(objects[1]->texture->finish.phong, 0.5);
  ASSERT_TRUE(objects[2]->texture);
  EXPECT_EQ(objects[2]->texture->pigment.color.rgb, Vec3(0.8));
  const auto& children = std::get<scene::Csg>(objects[2]->shape).children;
  EXPECT_FALSE(children[0]->texture);  // inherits the union's
  EXPECT_EQ(objects[3]->texture->pigment.color.rgb, Vec3(1, 0, 0));
  EXPECT_EQ(objects[3]->texture->finish.phong, 0.5);  // started from the #default
}

}  // namespace
}  // namespace convray::sdl
