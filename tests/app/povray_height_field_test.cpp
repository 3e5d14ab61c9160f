// height_field, polygon and sor against the povray binary's pictures: POV-Ray's plasma2.png and
// fract003.png (palette images in its include folder, which both programs search) as
// height fields, flat and smooth, with a water level and cut by CSG; polygons with holes.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayHeightField : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 4, -6> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n";

TEST_F(PovRayHeightField, FromPaletteImagesAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "height_field { png \"plasma2.png\" translate <-0.5, 0, -0.5> scale <3, 1, 3>\n"
      "  translate <-1.6, 0, 0> pigment { gradient y color_map { [0 rgb <0, 0.3, 0>]\n"
      "  [1 rgb 1] } } }\n"
      "height_field { png \"fract003.png\" smooth water_level 0.3 translate <-0.5, 0, -0.5>\n"
      "  scale <3, 1.5, 3> translate <1.6, 0, 0> pigment { rgb <0.9, 0.7, 0.5> } }\n";
  EXPECT_GE(compare("height_fields", scene), 30.0) << convray_err;
}

TEST_F(PovRayHeightField, InCsgAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "intersection { height_field { png \"plasma2.png\" translate <-0.5, 0, -0.5> }\n"
      "  sphere { 0, 0.45 } scale <5, 2, 5> pigment { rgb <0.6, 0.8, 1> } }\n"
      "difference { box { <-2.5, 0, -0.5>, <2.5, 1, 0.5> } height_field { png \"plasma2.png\"\n"
      "  translate <-0.5, 0, -0.5> scale <6, 1.2, 2> } translate 1.5 * z\n"
      "  pigment { rgb <1, 0.6, 0.3> } }\n";
  EXPECT_GE(compare("height_field_csg", scene), 30.0) << convray_err;
}

TEST_F(PovRayHeightField, PolygonsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1, 0>, <0, 0>,\n"
      "  <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4> scale 0.4 translate <-2.5, 0, 0>\n"
      "  pigment { rgb <1, 0, 0.3> } }\n"
      "polygon { 10, <0, 0>, <0, 6>, <4, 6>, <4, 0>, <0, 0>, <1, 1>, <1, 5>, <3, 5>, <3, 1>,\n"
      "  <1, 1> scale 0.4 rotate <20, -30, 0> pigment { rgb <0.2, 0.5, 1> } }\n"
      "polygon { 5, <1, 0, 0>, <2, 0.5, 0.5>, <2, 1.5, 0.5>, <1, 1, 0>, <1, 0, 0>\n"
      "  pigment { rgb <0.3, 1, 0.2> } translate <0.5, 0, -1> }\n"
      "plane { y, -0.01 pigment { rgb 0.7 } }\n";
  EXPECT_GE(compare("polygons", scene), 40.0) << convray_err;
}

TEST_F(PovRayHeightField, SorsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "sor { 6, <0.5, -0.5>, <1, 0>, <0.6, 0.7>, <1.2, 1.1>, <0.4, 2>, <0.9, 2.6>\n"
      "  translate <-1.6, 0, 0> pigment { rgb <1, 0.6, 0.3> } }\n"
      "sor { 7, <0, 0>, <0.118143, 0>, <0.620253, 0.540084>, <0.210970, 0.827004>,\n"
      "  <0.194093, 0.962025>, <0.286920, 1>, <0.468354, 1.033755> open scale 2\n"
      "  translate <1.4, 0, 0> pigment { rgb <0.3, 0.6, 1> } }\n"
      "plane { y, -0.01 pigment { rgb 0.7 } }\n";
  EXPECT_GE(compare("sors", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
