// brick and hexagon, POV-Ray's block patterns, as pigments (with their default colours, given
// colours, brick_size and mortar, pigments in the blocks) and as texture patterns, against the
// povray binary's pictures.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayBlockPatterns : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n";

TEST_F(PovRayBlockPatterns, BrickAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { z, 1 pigment { brick scale 0.12 } }\n"
      "box { <-2.8, 0, -1>, <-1.2, 1.6, 0.6> pigment { brick rgb <0.9, 0.9, 0.8>, rgb <0.5, 0.1, 0>\n"
      "  brick_size <1, 0.5, 0.7> mortar 0.1 rotate 30 * y } }\n"
      "sphere { <0.2, 1, -0.5>, 1 pigment { brick pigment { gradient y } pigment { rgb <0.2, 0.3, 1> }\n"
      "  brick_size 0.6 mortar 0.15 } }\n"
      "box { <1.3, 0, -1>, <2.8, 1.5, 0.3> texture { brick texture { pigment { rgb 1 } }\n"
      "  texture { pigment { rgb <0.6, 0.2, 0.1> } finish { phong 0.8 } } scale 0.2 } }\n";
  EXPECT_GE(compare("brick", scene), 40.0) << convray_err;
}

TEST_F(PovRayBlockPatterns, BrickFacesOnAMortarBoundaryAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // The box's faces lie at x = ±7.5 (and y, z = ±7.5) in the pattern's space, where mortar
  // begins: POV-Ray's 1e-10 tolerance decides for the whole face, the hit points' rounding
  // for none of it.
  const std::string scene =
      kSetting +
      "box { -1, 1 scale 0.75 texture { pigment { brick rgb 1, rgb <0.5, 0.1, 0> scale 0.1 } }\n"
      "  rotate <-30, 30, 0> translate <-1.2, 1, 0> }\n"
      "box { -1, 1 scale 0.75 texture { pigment { brick rgb 1, rgb <0.5, 0.1, 0> scale 0.1 } }\n"
      "  rotate <20, -40, 0> translate <1.2, 1, 0> }\n";
  EXPECT_GE(compare("brick_boundary", scene), 40.0) << convray_err;
}

TEST_F(PovRayBlockPatterns, HexagonAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 pigment { hexagon scale 0.4 } }\n"
      "plane { z, 1.5 pigment { hexagon rgb 1, rgb <0.5, 0.5, 0.6>, rgb 0.1 scale 0.3 "
      "rotate <-90, 0, 20> } }\n"
      "sphere { <-1.5, 1, 0>, 0.9 pigment { hexagon pigment { checker scale 0.1 } pigment { rgb <1, 0.8, 0> }\n"
      "  scale 0.35 rotate 40 * x } }\n"
      "sphere { <1.5, 1, 0>, 0.9 texture { hexagon texture { pigment { rgb <1, 0, 0> } }\n"
      "  texture { pigment { rgb <0, 0.8, 0.2> } } texture { pigment { rgb 1 } finish { phong 1 } }\n"
      "  scale 0.3 } }\n";
  EXPECT_GE(compare("hexagon", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
