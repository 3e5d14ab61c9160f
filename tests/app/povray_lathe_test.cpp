// Lathes of the four splines and superellipsoids against the povray binary's pictures: the
// spline definitions (which points only set slopes) and the exponents' roles are POV-Ray's
// only if the pictures agree.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayLathe : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 4, -9> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "light_source { <5, 3, -2> color rgb 0.4 }\n"
    "plane { y, -1 pigment { checker rgb 0.3 rgb 0.7 } }\n";

TEST_F(PovRayLathe, TheFourSplines) {
  SKIP_WITHOUT_POVRAY();
  const std::string points = "<0.2, -0.9>, <1, -1>, <1.2, 0>, <0.5, 0.6>, <0.9, 1.4>, <0.2, 1.6>\n";
  const std::string scene =
      kSetting + "lathe { linear_spline 6, " + points +
      "  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } translate <-3, 0, 1> }\n" +
      "lathe { quadratic_spline 6, " + points +
      "  pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } translate <-1, 0, 0> }\n" +
      "lathe { cubic_spline 6, " + points +
      "  pigment { rgb <0.3, 0.4, 0.9> } finish { phong 0.6 } translate <1, 0, 0> }\n" +
      "lathe { bezier_spline 8, <0, -1>, <2, -1>, <1, 1>, <0.5, 1>, <0.5, 1>, <0.2, 1.5>,\n"
      "  <0.1, 1>, <0, -1> pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.6 }\n"
      "  translate <3, 0, 1> }\n";
  EXPECT_GE(compare("lathe_splines", scene), 35.0) << convray_err;
}

TEST_F(PovRayLathe, LatheInCsgAndTurned) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "difference {\n"
      "  lathe { cubic_spline 7, <0, -1>, <0, -1>, <1.5, -0.5>, <1, 1>, <0.3, 1.5>, <0, 1.5>,\n"
      "    <0, 1.5> }\n"
      "  box { <0, -2, -2>, <2, 2, 0> rotate 30 * y }\n"
      "  pigment { rgb <0.3, 0.5, 0.9> } rotate <20, 0, 10>\n"
      "}\n";
  EXPECT_GE(compare("lathe_csg", scene), 35.0) << convray_err;
}

TEST_F(PovRayLathe, Superellipsoids) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "superellipsoid { <0.3, 0.8> pigment { rgb <0.9, 0.3, 0.2> } rotate <-20, 30, 0>\n"
      "  translate <-2.5, 0.5, 0> }\n"
      "superellipsoid { <1.5, 0.4> pigment { rgb <0.2, 0.8, 0.3> } rotate <-20, 30, 0>\n"
      "  translate <0, 0.5, 0> }\n"
      "intersection { superellipsoid { <2.5, 2.5> } sphere { 0, 0.8 inverse }\n"
      "  pigment { rgb <0.3, 0.4, 0.9> } rotate <-20, 30, 0> translate <2.5, 0.5, 0> }\n";
  EXPECT_GE(compare("superellipsoids", scene), 35.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
