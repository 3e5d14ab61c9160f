// Mirrors with bumped normals against the povray binary's pictures: where a bump turns the
// normal away from the incoming ray, or would send the mirrored ray into the surface, POV-Ray
// 3.7 mirrors by the surface's own normal and plane (render/integrator.cpp's
// bumped_reflection); without those rules both pictures below are 18-19 dB off.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayBumpedMirror : public PovRayPictureTest {};

TEST_F(PovRayBumpedMirror, QuiltedMirrorSphereOverAChecker) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 1, -6> look_at 0 angle 40 }\n"
      "light_source { <-5, 5, -5> color rgb 1 }\n"
      "plane { y, -2 pigment { checker rgb <0.2, 0.3, 0.8> rgb <0.9, 0.8, 0.6> } }\n"
      "sphere { 0, 2 pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 }\n"
      "  normal { quilted 1 control0 0.5 control1 1 scale 0.45 } }\n";
  EXPECT_GE(compare("quilted_mirror", scene), 45.0) << convray_err;
}

TEST_F(PovRayBumpedMirror, BumpyMirrorFloorSeenAtGrazingAngles) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 0.6, -6> look_at <0, 0, 2> angle 50 }\n"
      "light_source { <-5, 5, -5> color rgb 1 }\n"
      "sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.5, 0.2>]\n"
      "  [1 rgb <0.1, 0.2, 0.8>] } } }\n"
      "box { <-3, 1, 4>, <3, 3, 5> pigment { checker rgb <0.9, 0.9, 0.2>\n"
      "  rgb <0.2, 0.6, 0.3> scale 0.3 } }\n"
      "plane { y, 0 pigment { rgb 0.1 } finish { reflection 0.9 ambient 0 diffuse 0.1 }\n"
      "  normal { bumps 0.8 scale 0.2 } }\n";
  EXPECT_GE(compare("bumpy_floor", scene), 45.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
