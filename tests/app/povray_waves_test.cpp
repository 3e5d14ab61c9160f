// POV-Ray's wave types (ramp, triangle, sine, scallop, cubic, poly) reshape a pattern's value
// before the colour map: one stripe per wave over the same gradient, rendered by povray and
// by convray, must match.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayWaves : public PovRayPictureTest {};

TEST_F(PovRayWaves, EveryWaveTypeAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }\n";
  const char* waves[] = {"ramp_wave",  "triangle_wave", "sine_wave",      "scallop_wave",
                         "cubic_wave", "poly_wave 2.5", "poly_wave 0.4 frequency 2 phase 0.3",
                         "", "triangle_wave frequency 3"};
  for (int i = 0; i < 9; ++i) {
    // Marble's default is the triangle wave; an explicit wave replaces it (the last two rows).
    const std::string pattern = i < 7 ? "gradient x" : "marble";
    scene += "box { <-2, " + std::to_string(1.5 - i / 3.0) + ", 0>, <2, " +
             std::to_string(1.5 - (i + 1) / 3.0) + ", 1> pigment { " + pattern +
             " color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0.5, 1>] } " + waves[i] +
             " scale 1.3 } finish { ambient 1 diffuse 0 } }\n";
  }
  EXPECT_GE(compare("waves", scene), 40.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
