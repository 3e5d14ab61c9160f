// POV-Ray's wide cameras (fisheye, panoramic, spherical, cylinder 1 to 4, ultra_wide_angle)
// against POV-Ray's pictures of one small scene: a checkered floor, coloured balls all
// around and a sky gradient, seen through each projection.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

const char* kWorld =
    "light_source { <10, 20, -10> color rgb 1 }\n"
    "sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 0.7>] "
    "[1 rgb <0.2, 0.4, 0.9>] } } }\n"
    "plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.3, 0.5, 0.3> } }\n"
    "#for (I, 0, 7)\n"
    "  sphere { <4, 0.5 * mod(I, 3), 0>, 0.8 rotate I * 45 * y\n"
    "    pigment { color rgb <mod(I, 2), I / 7, 1 - I / 7> } finish { phong 0.5 } }\n"
    "#end\n";

class PovRayCameras : public PovRayPictureTest,
                      public ::testing::WithParamInterface<const char*> {};

TEST_P(PovRayCameras, SameRaysAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = std::string("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n") +
                            "camera { " + GetParam() +
                            " location <0, 1, -1> right x * image_width / image_height "
                            "look_at <1, 1, 2> }\n" + kWorld;
  EXPECT_GE(compare("camera", scene), 35.0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(WideProjections, PovRayCameras,
                         ::testing::Values("fisheye angle 180", "fisheye angle 300",
                                           "panoramic", "spherical angle 360, 180",
                                           "spherical angle 240", "cylinder 1 angle 120",
                                           "cylinder 2 angle 90", "cylinder 3 angle 150",
                                           "cylinder 4 angle 100", "cylinder 1",
                                           "ultra_wide_angle angle 220",
                                           "ultra_wide_angle angle 100 up 1.5 * y",
                                           "ultra_wide_angle"));

// An orthographic camera shows the perspective camera's area at the point looked at when it
// is given an angle or neither right nor up (textures/pigments/transmitfx.pov); right and up
// written out give the area themselves.
class PovRayOrthographic : public PovRayPictureTest,
                           public ::testing::WithParamInterface<const char*> {};

TEST_P(PovRayOrthographic, SameAreaAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = std::string("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n") +
                            "camera { orthographic location <0, 6, -3> " + GetParam() +
                            " look_at <0, 0, 1> }\n" + kWorld;
  EXPECT_GE(compare("orthographic", scene), 35.0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Areas, PovRayOrthographic,
                         ::testing::Values("", "angle 40", "direction 2 * z",
                                           "right 8 * x up 6 * y", "up 3 * y"));

}  // namespace
}  // namespace convray::testing
