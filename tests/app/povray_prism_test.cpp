// Linear prisms against the povray binary's pictures: overlapping and nested polygons of
// either orientation (inside where an odd number enclose a point), heights given in either
// order, the point count written without a comma before the first point, in CSG; and the
// camera of POV-Ray's prism scenes (`up z` with the default direction, which POV-Ray
// mirrors).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayPrism : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <1, 5, -6> look_at <0, 0, 0> angle 45 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "light_source { <5, 3, -2> color rgb 0.4 }\n"
    "plane { y, -1 pigment { rgb 0.6 } }\n";

TEST_F(PovRayPrism, PolygonsInsideWhereAnOddNumberEncloseAPoint) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "prism { linear_sweep linear_spline 0.5, -0.2, 14 <-2, -1.5>, <2, -1.5>, <2, 1.5>,\n"
      "  <-2, 1.5>, <-2, -1.5>,\n"
      "  <-1.5, -1>, <-1.5, 1>, <0.5, 1>, <0.5, -1>, <-1.5, -1>,\n"  // the other way round
      "  <0, -0.5>, <1.5, -0.5>, <1.5, 0.5>, <0, 0.5>\n"  // overlaps the hole, left open
      "  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } rotate 20 * y }\n";
  EXPECT_GE(compare("prism_polygons", scene), 40.0) << convray_err;
}

TEST_F(PovRayPrism, PrismInCsg) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "difference {\n"
      "  prism { -0.5, 0.5, 4, <-1.5, -1>, <1.5, 0>, <-1.5, 1>, <-1.5, -1> }\n"
      "  sphere { <-0.5, 0.5, 0>, 0.6 }\n"
      "  pigment { rgb <0.3, 0.5, 0.9> } rotate -30 * y\n"
      "}\n";
  EXPECT_GE(compare("prism_csg", scene), 40.0) << convray_err;
}

TEST_F(PovRayPrism, CameraWithUpAlongTheDefaultDirection) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <-10, 10, -10> right x * 4 / 3 up z look_at 0 angle 20 }\n"
      "light_source { <0, 50, 10> rgb 1 }\n"
      "plane { y, -1 pigment { checker color rgb 0.2 color rgb 0.8 } }\n"
      "box { <-1, -1, -1>, <2, 0, 0.5> pigment { rgb <1, 0, 0> } }\n"
      "sphere { <0, 0, 2>, 0.7 pigment { rgb <0, 0, 1> } }\n";
  EXPECT_GE(compare("up_z_camera", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
