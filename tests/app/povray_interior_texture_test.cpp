// interior_texture against POV-Ray 3.7: rays that meet a surface from inside its solid see the
// interior_texture (bumped as seen from there), and light leaving the solid passes it; from
// outside the texture is seen. Rendered by povray and convray, compared by PSNR.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayInteriorTexture : public PovRayPictureTest {};

TEST_F(PovRayInteriorTexture, TheInsideOfASurfaceWearsTheInteriorTexture) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
      "camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 45 }\n"
      "light_source { <5, 10, -4> color rgb 1 }\n"
      "plane { y, -1 pigment { rgb 0.8 } }\n"
      // Cut open: the inside shows, bumped.
      "sphere { <-1.2, 0, 0>, 1 pigment { rgb <0.5, 0.4, 1> }\n"
      "  interior_texture { pigment { rgb <1, 0.7, 0> } normal { bumps 0.7 scale 0.15 } }\n"
      "  clipped_by { plane { y, 0.3 } } translate 0.1 * x }\n"
      // Striped clear: the shadow passes both textures' clear stripes.
      "sphere { <1.3, 0, 0>, 1\n"
      "  texture { pigment { gradient x color_map { [0.5 rgb 1] [0.5 rgbt 1] } scale 0.5 } }\n"
      "  interior_texture { pigment { gradient z color_map { [0.5 rgb <1, 0, 0>] [0.5 rgbt 1] }\n"
      "    scale 0.4 } } }\n";
  EXPECT_GE(compare("interior_texture", scene), 35.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
