// A declared sky_sphere (as skies.inc declares them) used by name, with a further pigment
// layered on and a rotation: rendered by povray and by convray, the pictures must match.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRaySkySphere : public PovRayPictureTest {};

TEST_F(PovRaySkySphere, DeclaredSkySphereUsedByNameAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 1, -4> look_at <0, 1.5, 0> angle 70 }\n"
      "#declare Sky = sky_sphere {\n"
      "  pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.1, 0.3, 0.8>] } }\n"
      "}\n"
      "#declare Turned = sky_sphere { Sky rotate 30 * z }\n"
      "sky_sphere { Turned\n"
      "  pigment { gradient x color_map { [0 rgbt 1] [0.5 rgbt 1] [0.5 rgbt <1, 1, 1, 0.5>]\n"
      "    [1 rgbt <1, 1, 1, 0.5>] } scale 0.3 }\n"
      "}\n"
      "plane { y, 0 pigment { color rgb 0.5 } }\n"
      "light_source { <3, 5, -3> color rgb 1 }\n";
  EXPECT_GE(compare("declared_sky", scene), 40.0);
}

}  // namespace
}  // namespace convray::testing
