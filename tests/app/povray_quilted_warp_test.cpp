// quilted (its controls, as a pigment and under a texture map) and the turbulence and repeat
// warps (offset, flip, between transforms), against the povray binary's pictures. The
// formulas were fitted to the binary's values (render/patterns.cpp, render/warps.cpp); these
// pictures check them where the scene language puts them.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayQuiltedWarp : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n";

TEST_F(PovRayQuiltedWarp, QuiltedAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { z, 1.5 pigment { quilted scale 0.5 } }\n"
      "plane { y, 0 pigment { quilted control0 0.5 control1 0.2\n"
      "  color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb 1] [1 rgb <0.8, 0.2, 0>] } scale 0.3 } }\n"
      "sphere { <-1.5, 1, 0>, 0.9 pigment { quilted control0 -1 control1 2 scale 0.4 "
      "rotate 30 * x } }\n"
      "sphere { <1.5, 1, 0>, 0.9 texture { quilted texture_map {\n"
      "  [0 pigment { rgb <1, 0.8, 0> }] [1 pigment { rgb <0, 0.3, 0.8> }] } scale 0.3 } }\n";
  EXPECT_GE(compare("quilted", scene), 40.0) << convray_err;
}

TEST_F(PovRayQuiltedWarp, RepeatWarpAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "#declare P = pigment { gradient <1, 1, 0> color_map { [0 rgb <1, 0, 0>] [0.5 rgb 1]\n"
      "  [1 rgb <0, 0, 1>] } scale 0.7 rotate 20 * z }\n"
      "plane { z, 1.5 pigment { P warp { repeat x * 0.8 } } }\n"
      "plane { y, 0 pigment { P warp { repeat z * 0.6 offset <0.3, 0.1, 0> flip x } } }\n"
      "sphere { <-1.5, 1, 0>, 0.9 pigment { P warp { repeat y * 0.5 flip <1, 1, 1> } "
      "scale 0.8 } }\n"
      "sphere { <1.5, 1, 0>, 0.9 pigment { checker rgb 1 rgb 0 scale 0.3 warp { repeat x * 0.7 "
      "offset <0, 0.15, 0.15> } rotate 15 * y } }\n";
  EXPECT_GE(compare("repeat", scene), 40.0) << convray_err;
}

TEST_F(PovRayQuiltedWarp, TurbulenceWarpAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // The warp sits between the transforms: `scale` before it is undone inside it, the one
  // after it outside; marble's warp is a real warp, unlike its plain turbulence.
  const std::string scene =
      kSetting +
      "plane { z, 1.5 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 0.5\n"
      "  warp { turbulence 0.4 octaves 3 omega 0.6 lambda 2.5 } scale 2 } }\n"
      "plane { y, 0 pigment { marble warp { turbulence <0.5, 0.2, 0.8> } scale 0.6 } }\n"
      "sphere { <-1.5, 1, 0>, 0.9 pigment { checker rgb 1 rgb <0.2, 0.5, 0> scale 0.3\n"
      "  warp { turbulence 0.3 } rotate 40 * y warp { repeat x * 0.4 } } }\n"
      "sphere { <1.5, 1, 0>, 0.9 pigment { wood turbulence 0.2 warp { turbulence 0.1 } "
      "scale 0.3 } }\n";
  EXPECT_GE(compare("turbulence", scene), 40.0) << convray_err;
}

TEST_F(PovRayQuiltedWarp, OtherWarpsAreRefusedByName) {
  std::ofstream(file("hole.pov"))
      << "camera { location -5 * z look_at 0 }\n"
         "plane { z, 0 pigment { gradient x\n"
         "  warp { black_hole 0, 1 } } }\n";
  const CliRun run = run_convray("+I" + file("hole.pov") + " +O" + file("hole.png") + " +W8 +H8");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("hole.pov:3:10"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("'warp { black_hole }' is not supported yet"), std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace convray::testing
