// Text objects against the povray binary's pictures: POV-Ray's own fonts, kerned pairs
// (AV), a first glyph with a negative left side bearing (j), descenders, a vector offset,
// a font named without its .ttf, CSG with text, all seen at an angle so the sides show.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayText : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <1.6, 0.8, -4> look_at <1.6, 0.2, 0> angle 60 }\n"
    "light_source { <-3, 5, -10> color rgb 1 }\n"
    "background { rgb <0.2, 0.3, 0.5> }\n";

TEST_F(PovRayText, GlyphsPlacedAsPovRayPlacesThem) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "text { ttf \"timrom.ttf\" \"jAVHg\" 0.5, 0 pigment { rgb <1, 0.6, 0.2> }\n"
      "  finish { phong 0.5 } rotate 25 * y }\n"
      "text { ttf \"cyrvetic\" \"Wo ly!\" 0.2, <0.05, -0.03, 0> pigment { rgb <0.3, 0.9, 0.4> }\n"
      "  rotate -20 * x translate <0, -0.9, -0.5> }\n";
  EXPECT_GE(compare("text_glyphs", scene), 35.0) << convray_err;
}

TEST_F(PovRayText, TextInCsgAndItsShadows) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, -0.3 pigment { rgb 0.8 } }\n"
      "difference {\n"
      "  box { <-0.2, -0.2, 0.1>, <3.4, 0.9, 0.3> }\n"
      "  text { ttf \"crystal.ttf\" \"POV\" 1, 0 scale 1.1 }\n"
      "  pigment { rgb <0.9, 0.8, 0.3> } rotate -30 * y\n"
      "}\n";
  EXPECT_GE(compare("text_csg", scene), 35.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
