// interior { fade_distance fade_power fade_color } against POV-Ray 3.7: light seen through a
// solid, and light reaching a shadowed surface through it, dims with the depth crossed
// (render/interior_fade.hpp). Rendered by povray and convray, compared by PSNR.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

// Four clear spheres, one per fade_power (0, 1, 3, 1000), over a lit checkered wall that
// shows both what is seen through them and their shadows.
std::string scene(const std::string& fade_color) {
  std::string text =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
      "camera { orthographic location <0, 0, -20> look_at 0 right 12 * x up 9 * y }\n"
      "light_source { <300, 300, -300> color rgb 1 }\n"
      "plane { z, 2.5 pigment { checker color rgb <1, 1, 0> color rgb <0, 0.8, 0> } }\n";
  const char* powers[] = {"0", "1", "3", "1000"};
  for (int k = 0; k < 4; ++k) {
    text += "sphere { <" + std::to_string(-4.5 + 3 * k) + ", 1, 0>, 1.3\n"
            "  pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 1 }\n"
            "  interior { ior 1.05 fade_distance 1.5 fade_power " + std::string(powers[k]) +
            fade_color + " } }\n";
  }
  return text;
}

class PovRayInteriorFade : public PovRayPictureTest {};

TEST_F(PovRayInteriorFade, LightDimsWithTheDepthCrossed) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("fade", scene("")), 35.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

TEST_F(PovRayInteriorFade, LightFadesTowardTheFadeColor) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("fade_color", scene(" fade_color rgb <1, 0.3, 0.1>")), 35.0);
}

}  // namespace
}  // namespace convray::testing
