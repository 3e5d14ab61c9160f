// bicubic_patch against the povray binary's pictures: a curved patch at several subdivisions
// (commas between the points and none), a closed surface of patches (part of Newell's teapot,
// with the degenerate points of its lid), under transforms and textures.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayBicubicPatch : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "plane { y, -1 pigment { checker rgb 0.9 rgb 0.6 } }\n";

const std::string kPoints =
    "< 0.0, 0.0, 2.0>, < 1.0, 0.0, 0.0>, < 2.0, 0.0, 0.0>, < 3.0, 0.0, -2.0>,\n"
    "< 0.0, 1.0, 0.0>, < 1.0, 1.0, 0.0>, < 2.0, 1.0, 0.0>, < 3.0, 1.0,  0.0>,\n"
    "< 0.0, 2.0, 0.0>, < 1.0, 2.0, 0.0>, < 2.0, 2.0, 0.0>, < 3.0, 2.0,  0.0>,\n"
    "< 0.0, 3.0, 2.0>, < 1.0, 3.0, 0.0>, < 2.0, 3.0, 0.0>, < 3.0, 3.0, -2.0>\n";

TEST_F(PovRayBicubicPatch, CurvedPatchAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "bicubic_patch { type 1 flatness 0 u_steps 4 v_steps 3\n" + kPoints +
      "  pigment { checker rgb <1, 0, 0> rgb 1 rotate 90 * x scale 0.5 }\n"
      "  finish { phong 1 } translate <-1.5, -1.5, 0> scale 0.6 rotate <30, -60, 0> "
      "translate <-1.5, 1, 0> }\n"
      "bicubic_patch { type 0 u_steps 6 v_steps 6\n" + kPoints +
      "  pigment { rgb <0.3, 0.6, 1> } finish { specular 0.6 }\n"
      "  translate <-1.5, -1.5, 0> scale 0.5 rotate <-20, 200, 10> translate <1.6, 1, 0> }\n";
  EXPECT_GE(compare("curved", scene), 35.0) << convray_err;
}

TEST_F(PovRayBicubicPatch, TeapotLidAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // Two of teapot.inc's lid patches, points without commas; the top row is one point.
  const std::string scene =
      kSetting +
      "union {\n"
      "bicubic_patch { type 1 flatness 0.0001 u_steps 5 v_steps 5\n"
      "  <0.0 0.0 3.15> <0.8 0.0 3.15> <0.0 0.0 3.15> <0.0 0.0 3.15>\n"
      "  <0.8 0.0 3.15> <0.8 -0.45 3.15> <0.45 -0.8 3.15> <0.0 -0.8 3.15>\n"
      "  <0.0 0.0 2.85> <0.2 0.0 2.7> <0.2 -0.112 2.7> <0.112 -0.2 2.7>\n"
      "  <0.2 0.0 2.55> <0.2 -0.112 2.55> <0.112 -0.2 2.55> <0.0 -0.2 2.55> }\n"
      "bicubic_patch { type 1 flatness 0.0001 u_steps 5 v_steps 5\n"
      "  <0.1 0.0 3.15> <0.1 0.0 3.15> <0.0 0.0 3.15> <-0.1 0.0 3.15>\n"
      "  <0.8 0.0 3.15> <0.8 0.45 3.15> <0.45 0.8 3.15> <0.0 0.8 3.15>\n"
      "  <0.0 0.0 2.85> <0.2 0.0 2.7> <0.2 0.112 2.7> <0.112 0.2 2.7>\n"
      "  <0.2 0.0 2.55> <0.2 0.112 2.55> <0.112 0.2 2.55> <0.0 0.2 2.55> }\n"
      "  pigment { rgb <1, 0.7, 0.2> } finish { phong 0.8 }\n"
      "  rotate -90 * x translate -2.8 * y scale 1.8 }\n";
  EXPECT_GE(compare("lid", scene), 35.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
