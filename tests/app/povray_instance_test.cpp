// A declared union placed many times is traced as shared instances (scene/instance.hpp):
// pictures against the povray binary's, and against convray's own picture of the copies (the
// same union written out at each placement, whose textures the parser moves member by member).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

// Members with patterned pigments and normals, placed by turns, moves and stretches.
const char* const kScene = R"(
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -14> look_at <0, 1, 0> }
light_source { <5, 15, -10> color rgb 1.2 }
plane { y, -1 pigment { color rgb <0.3, 0.35, 0.3> } }
#macro Members()
  sphere { <0, 0, 0>, 0.5 pigment { checker rgb <1, 0.2, 0.2> rgb <0.2, 0.2, 1> scale 0.25 }
           normal { bumps 0.5 scale 0.15 } finish { phong 0.4 } }
  box { <0.6, -0.3, -0.3>, <1.2, 0.3, 0.3>
        pigment { gradient x color_map { [0 rgb 0.1] [1 rgb <1, 1, 0.2>] } } rotate y * 20 }
  cylinder { <-1.2, 0, 0>, <-0.6, 0.5, 0>, 0.2 pigment { rgb <0.2, 0.8, 0.3> } }
  sphere { <0, 1, 0>, 0.35 pigment { wood color_map { [0 rgb <0.7, 0.4, 0.1>] [1 rgb 1] }
                                     scale 0.2 } }
#end
#macro Placement(i)
  scale <1, 1.3, 0.9> rotate <0, i * 37, i * 8> translate <mod(i, 4) * 3 - 4.5, div(i, 4) * 2.5, 0>
#end
)";

std::string placed_scene(bool instances) {
  std::string text = kScene;
  if (instances) text += "#declare U = union { Members() rotate z * 15 }\n";
  text += "#declare i = 0;\n#while (i < 12)\n";
  text += instances ? "  object { U Placement(i) }\n"
                    : "  union { Members() rotate z * 15 Placement(i) }\n";
  text += "  #declare i = i + 1;\n#end\n";
  return text;
}

class PovRayInstances : public PovRayPictureTest {};

TEST_F(PovRayInstances, PlacementsMatchPovRay) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("instances", placed_scene(true)), 40.0) << convray_err;
}

TEST_F(PovRayInstances, PlacementsMatchTheirCopies) {
  const std::string switches = " +W160 +H120 -A -D +WT1";
  for (const bool instances : {true, false}) {
    const std::string name = instances ? "instances" : "copies";
    std::ofstream(file(name + ".pov")) << placed_scene(instances);
    const CliRun run = run_convray_after("cd '" + dir_.string() + "' && ",
                                         "+I" + name + ".pov +O" + name + ".png" + switches);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  // The copies' textures were moved by the parser, the instances' are evaluated at points
  // carried back through the placement: the same up to rounding.
  EXPECT_GE(psnr(read_rgb8(file("instances.png")), read_rgb8(file("copies.png"))), 60.0);
}

}  // namespace
}  // namespace convray::testing
