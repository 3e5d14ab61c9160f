// light_sources inside a union, placed with it (and with an object { } that places the
// union), against the povray binary's picture.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayCsgLights : public PovRayPictureTest {};

TEST_F(PovRayCsgLights, LightsMoveWithTheirUnion) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 55 }\n"
      "#declare Lamps = union { light_source { <-3, 0, 0> color rgb <1, 0.3, 0.2> }\n"
      "  light_source { <3, 0, 0> color rgb <0.2, 0.4, 1> } translate <0, 0, -4> rotate 50 * x }\n"
      "object { Lamps }\n"
      "union { object { Lamps rotate 60 * y } sphere { <0, 0.5, 2>, 0.4 pigment { rgb 1 } }\n"
      "  light_source { <0, 6, 0> color rgb 0.5 spotlight point_at <0, 0, 0> radius 20\n"
      "  falloff 30 } translate 0.5 * x }\n"
      "plane { y, 0 pigment { checker rgb 1 rgb 0.6 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { rgb 0.9 } finish { phong 0.8 } }\n";
  EXPECT_GE(compare("csg_lights", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
