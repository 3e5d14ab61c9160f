// Objects convray cannot draw yet (ovus, lemon, sphere_sweep, ...): declaring one is accepted with a
// warning (include files declare many), but placing it in the scene, directly or inside CSG,
// is an error at the place of use that names the kind: never a silently missing object.
#include <gtest/gtest.h>

#include <string>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::run;
using core_testing::scene_error;

const char* kDeclared = "#declare Vase = ovus { 1, 0.5 }\n";

TEST(UnsupportedObjects, DeclaredAndNeverPlacedWarns) {
  const ParseResult result = run(std::string(kDeclared) +
                                 "#declare Scaled = object { Vase scale 2 }\n"
                                 "#declare Group = union { object { Vase } sphere { 0, 1 } }\n"
                                 "sphere { 0, 1 }\n");
  EXPECT_EQ(result.scene.objects.size(), 1u);
  bool warned = false;
  for (const std::string& w : result.warnings) warned |= w.find("'ovus' objects") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(UnsupportedObjects, PlacingOneIsAnErrorWhereItIsPlaced) {
  const auto direct = scene_error(std::string(kDeclared) + "object { Vase translate x }\n");
  EXPECT_EQ(direct.loc.line, 2);
  EXPECT_EQ(direct.loc.column, 1);
  EXPECT_NE(direct.first_line.find("'ovus' objects are not supported"), std::string::npos)
      << direct.first_line;
  EXPECT_NE(direct.first_line.find("declared at test.pov:1:17"), std::string::npos)
      << direct.first_line;
  // Inside CSG, through a declared group, or as a clipping object.
  const auto in_csg = scene_error(std::string(kDeclared) +
                                  "#declare Group = union { object { Vase } sphere { 0, 1 } }\n"
                                  "object { Group }\n");
  EXPECT_EQ(in_csg.loc.line, 3);
  EXPECT_NE(in_csg.first_line.find("'ovus'"), std::string::npos);
  const auto clipping =
      scene_error(std::string(kDeclared) + "sphere { 0, 1 clipped_by { object { Vase } } }\n");
  EXPECT_EQ(clipping.loc.line, 2);
  // Written in place, the object itself is the error.
  EXPECT_NE(scene_error("ovus { 1, 0.5 }").first_line.find("'ovus' objects"),
            std::string::npos);
}

}  // namespace
}  // namespace convray::sdl
