// double_illuminate against POV-Ray 3.7: a light behind a surface lights its far side too
// (diffuse and highlights as if that side faced the light), through the surface's own
// shadow; without the flag such a light adds nothing. Rendered by povray and convray, PSNR.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayDoubleIlluminate : public PovRayPictureTest {};

TEST_F(PovRayDoubleIlluminate, LightsBehindASurfaceLightItsFarSide) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "camera { location <0, 1, -5> look_at <0, 0.5, 0> angle 50 }\n"
      "light_source { <3, 4, 8> color rgb 1.2 }\n"
      "light_source { <-6, 3, -8> color rgb 0.3 }\n"
      "background { color rgb <0.1, 0.1, 0.2> }\n"
      "plane { y, -1 pigment { rgb 0.6 } }\n"
      "box { <-2.2, -1, 0>, <-0.2, 2, 0.05> pigment { rgbf <1, 0.9, 0.6, 0.6> }\n"
      "  finish { phong 0.8 specular 0.4 } double_illuminate }\n"
      "box { <0.2, -1, 0>, <2.2, 2, 0.05> pigment { rgbf <1, 0.9, 0.6, 0.6> }\n"
      "  finish { phong 0.8 specular 0.4 } }\n"
      "union { sphere { <-1.2, 0.3, -1>, 0.4 } sphere { <1.2, 0.3, 1>, 0.4 }\n"
      "  pigment { rgb <0.3, 0.8, 1> } double_illuminate }\n";
  EXPECT_GE(compare("double_illuminate", scene), 40.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
