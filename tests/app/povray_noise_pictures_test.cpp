// The noise-based patterns, the turbulence warp, wood's and marble's own turbulence and the
// bumps, dents and wrinkles normals (render/noise.hpp, render/noise_patterns.hpp), in whole pictures against the
// povray binary's.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayNoisePictures : public PovRayPictureTest {};

const std::string kStage =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 0, -6> look_at <0, 0, 0> angle 60 }\n"
    "light_source { <-4, 6, -8> color rgb 1 }\n";

// Six boxes, one pattern each, seen face on.
std::string patterned_boxes(const std::string (&pigments)[6]) {
  std::string scene = kStage;
  for (int k = 0; k < 6; ++k) {
    const double x = -2.6 + 2.6 * (k % 3), y = k < 3 ? 1.3 : -1.3;
    scene += "box { <-1.2, -1.2, 0>, <1.2, 1.2, 1> pigment { " + pigments[k] +
             " color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb 1] } }"
             " finish { ambient 0.3 } translate <" + std::to_string(x) + ", " +
             std::to_string(y) + ", 0> }\n";
  }
  return scene;
}

TEST_F(PovRayNoisePictures, NoisePatternsMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string pigments[6] = {"bozo scale 0.3", "granite", "agate scale 0.7",
                                   "wrinkles scale 0.5", "dents scale 0.4",
                                   "spotted turbulence 0.6 scale 0.5"};
  EXPECT_GE(compare("noise_patterns", patterned_boxes(pigments)), 50.0) << convray_err;
}

TEST_F(PovRayNoisePictures, MarbleAndWoodTurbulenceMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string pigments[6] = {"marble turbulence 0.8 scale 0.6",
                                   "wood turbulence 0.1 scale 0.3",
                                   "marble turbulence <1, 0, 0> octaves 3 omega 0.7 lambda 2.3",
                                   "wood turbulence <0.05, 0.08, 0> rotate 30 * x",
                                   "gradient y turbulence 0.4 scale 0.7",
                                   "bozo noise_generator 1 scale 0.4"};
  EXPECT_GE(compare("marble_wood", patterned_boxes(pigments)), 50.0) << convray_err;
}

TEST_F(PovRayNoisePictures, BumpsDentsAndWrinklesNormalsMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kStage +
      "plane { -z, 0 pigment { rgb 0.8 } normal { bumps 0.7 scale 0.4 } finish { phong 0.5 } }\n"
      "sphere { <1.5, 0, -1.5>, 1 pigment { rgb <1, 0.6, 0.4> } normal { bumps 1 scale 0.2 } }\n"
      "sphere { <-1.5, 0.8, -1.5>, 0.8 pigment { rgb 0.9 } normal { dents 2 scale 0.3 } }\n"
      "sphere { <-1.5, -1.2, -1.5>, 0.8 pigment { rgb 0.9 } normal { wrinkles 0.8 scale 0.5 } }\n";
  EXPECT_GE(compare("noise_normals", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
