// Declared items that need a feature convray cannot render yet (a texture with a crackle
// pigment, as stones2.inc declares dozens): the declaration is accepted with one warning per
// feature, since POV-Ray's include files declare far more than a scene uses (also as a
// further layer of a declared texture); using the item,
// directly or through another declaration, is an error where it is used that names the
// feature and the declaration. Never a silently wrong picture.
#include <gtest/gtest.h>

#include <string>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::run;
using core_testing::scene_error;

const char* kDeclared =
    "#declare Stone = texture {\n"
    "  pigment { crackle turbulence 0.3 color_map { [0 rgb 0] [1 rgb 1] } }\n"
    "  finish { phong 1 }\n"
    "}\n";

int warnings_naming(const ParseResult& result, const std::string& text) {
  int count = 0;
  for (const std::string& w : result.warnings) count += w.find(text) != std::string::npos;
  return count;
}

TEST(UnsupportedItems, DeclaredAndNeverUsedIsAcceptedWithOneWarning) {
  const ParseResult result = run(std::string(kDeclared) +
                                 "#declare Other = pigment { crackle scale 2 }\n"
                                 "#declare After = 3;\n"
                                 "sphere { 0, 1 pigment { rgb 1 } }\n");
  EXPECT_EQ(result.scene.objects.size(), 1u);
  EXPECT_EQ(warnings_naming(result, "'crackle' is not supported yet"), 1);
  // What follows the skipped declaration is read as usual.
  EXPECT_EQ(core_testing::global_float(result, "After"), 3.0);
}

TEST(UnsupportedItems, UsingOneFailsWhereItIsUsed) {
  const auto used = scene_error(std::string(kDeclared) + "sphere { 0, 1 texture { Stone } }\n");
  EXPECT_EQ(used.loc.line, 5);
  EXPECT_EQ(used.loc.column, 25);
  EXPECT_NE(used.first_line.find("'crackle' is not supported yet by convray (at test.pov:2:13)"),
            std::string::npos)
      << used.first_line;
  EXPECT_NE(used.first_line.find("'Stone', declared at test.pov:1:10"), std::string::npos)
      << used.first_line;
}

TEST(UnsupportedItems, ADeclarationThatUsesOneStandsUntilItIsUsed) {
  const std::string text = std::string(kDeclared) +
                           "#declare Polished = texture { Stone finish { reflection 0.5 } }\n"
                           "#declare Material = material { texture { Polished } }\n";
  EXPECT_EQ(run(text + "sphere { 0, 1 }\n").scene.objects.size(), 1u);
  const auto used = scene_error(text + "box { 0, 1 material { Material } }\n");
  EXPECT_EQ(used.loc.line, 7);
  EXPECT_NE(used.first_line.find("'crackle' is not supported yet"), std::string::npos)
      << used.first_line;
  EXPECT_NE(used.first_line.find("'Material'"), std::string::npos) << used.first_line;
}

TEST(UnsupportedItems, WrittenInPlaceTheFeatureItselfIsTheError) {
  const auto in_place = scene_error("sphere { 0, 1 pigment { crackle } }\n");
  EXPECT_EQ(in_place.loc.column, 25);
  EXPECT_NE(in_place.first_line.find("'crackle' is not supported yet"), std::string::npos);
  // Outside braces of its own an expression has no end to skip to: still an error.
  const auto expression = scene_error("#declare M = min_extent(X);\n");
  EXPECT_NE(expression.first_line.find("'min_extent' is not supported yet"), std::string::npos);
}

TEST(UnsupportedItems, ALayerThatNeedsOneMakesTheDeclaredTextureUnusable) {
  const std::string text =
      "#declare Layered = texture { pigment { rgb 1 } }\n"
      "texture { pigment { crackle color_map { [0 rgbt 1] [1 rgb 0] } } }\n";
  EXPECT_EQ(run(text + "sphere { 0, 1 }\n").scene.objects.size(), 1u);
  const auto used = scene_error(text + "sphere { 0, 1 texture { Layered } }\n");
  EXPECT_EQ(used.loc.line, 3);
  EXPECT_NE(used.first_line.find("'crackle' is not supported yet"), std::string::npos)
      << used.first_line;
}

TEST(UnsupportedItems, SkySpheresAndCamerasToo) {
  const std::string sky =
      "#declare Sky = sky_sphere { pigment { gradient y warp { black_hole 0, 1 } } "
      "}\n";
  EXPECT_EQ(run(sky + "sphere { 0, 1 }\n").scene.objects.size(), 1u);
  EXPECT_NE(scene_error(sky + "sky_sphere { Sky }\n").first_line.find("black_hole"),
            std::string::npos);
  const std::string camera = "#declare Wide = camera { omnimax location -5 * z }\n";
  EXPECT_EQ(run(camera + "camera { location -3 * z }\n").scene.objects.size(), 0u);
  EXPECT_NE(scene_error(camera + "camera { Wide }\n").first_line.find("omnimax"),
            std::string::npos);
}

}  // namespace
}  // namespace convray::sdl
