// The patterns made of a distance (planar, spherical, cylindrical, boxed), spiral1 and mandel, as
// pigments with their maps, frequency and phase, and as normals, against the povray binary's
// pictures. (The normals avoid the seams where a ramp wave wraps and where spiral1's angle
// does: POV-Ray's normal shows a line there, which convray's does not draw alike.)
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayDistancePatterns : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2.5, -7> look_at <0, 0.6, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n";

TEST_F(PovRayDistancePatterns, PigmentsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string map = " color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <1, 0.8, 0.2>]"
                          " [1 rgb <0.8, 0.1, 0.1>] } ";
  const std::string scene =
      kSetting + "plane { y, 0 pigment { planar" + map + "rotate 90 * z scale 2 } }\n" +
      "sphere { <-2, 1, 0>, 1 pigment { spherical" + map + "frequency 2 translate 0.5 * y\n"
      "  translate <-2, 1, -0.4> } }\n"
      "sphere { <0, 1, 0>, 1 pigment { cylindrical" + map + "phase 0.3 scale 0.8 rotate 40 * x\n"
      "  translate y } }\n"
      "box { <1.2, 0, -0.8>, <2.8, 1.6, 0.8> pigment { boxed" + map + "scale 0.9\n"
      "  translate <2, 0.8, -0.8> } }\n"
      "sphere { <0, 2.6, 0>, 0.6 pigment { spiral1 3" + map + "scale 0.3 rotate 70 * x\n"
      "  translate 2.6 * y } }\n"
      "sphere { <-2, 2.6, 0>, 0.6 pigment { spiral1 2 ramp_wave frequency 2 " + map +
      "scale 0.5 translate <-2, 2.6, 0> } }\n";
  EXPECT_GE(compare("distance_pigments", scene), 40.0) << convray_err;
}

TEST_F(PovRayDistancePatterns, MandelAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { z, 1 pigment { mandel 40 color_map { [0 rgb 0] [0.3 rgb <1, 0.5, 0>]\n"
      "  [1 rgb <0.2, 0.3, 1>] } translate 0.5 * x scale 1.5 translate y } }\n"
      "sphere { <1.8, 1, -1>, 0.8 pigment { rgb 0.9 } normal { mandel 30, 0.8 scale 0.5\n"
      "  translate <1.8, 1, 0> } }\n";
  // The pigment is POV-Ray's pixel for pixel; the bumps differ at a few escape-time steps.
  EXPECT_GE(compare("mandel", scene), 35.0) << convray_err;
}

TEST_F(PovRayDistancePatterns, MandelsOwnColourMapAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // Without a colour map mandel has a map of its own (black, cyan, yellow, magenta, cyan
  // over the first tenth of its value).
  const std::string scene =
      kSetting +
      "plane { z, 1 pigment { mandel 256 translate 0.5 * x scale 1.5 translate y }\n"
      "  finish { ambient 1 diffuse 0 } }\n"
      "sphere { <1.8, 1, -1>, 0.8 pigment { mandel 20 scale 0.6 translate <1.8, 1, 0> } }\n"
      "sphere { <-1.8, 1, -1>, 0.8 pigment { mandel 1000 scale 0.8 translate <-1.5, 1, 0> }"
      " }\n";
  EXPECT_GE(compare("mandel_map", scene), 40.0) << convray_err;
}

TEST_F(PovRayDistancePatterns, NormalsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 pigment { rgb 0.8 } normal { spiral1 4 0.6 scale 0.5 rotate 90 * x\n"
      "  translate <0.3, 0, 0.2> } }\n"
      "sphere { <-1.5, 1, 0>, 1 pigment { rgb <1, 0.6, 0.3> } normal { boxed 0.8 scale 0.4 } }\n"
      "sphere { <1.5, 1, 0>, 1 pigment { rgb <0.3, 0.6, 1> } normal { spherical 0.7\n"
      "  scale 1.2 translate <1.5, 1, -1> } }\n";
  EXPECT_GE(compare("distance_normals", scene), 30.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
