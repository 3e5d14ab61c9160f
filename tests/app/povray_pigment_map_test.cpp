// pigment_map (whole pigments picked and mixed by a pattern's value, in the pattern's space),
// average pigment_map (mixed by weight)
// and checker blocks of pigments, against the povray binary's pictures; also the colours
// POV-Ray reads one after another without a comma (`checker rgb 1 rgb 0`).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayPigmentMap : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "#declare Stripes = pigment { gradient z color_map { [0.5 rgb <1, 1, 0>]\n"
    "  [0.5 rgb <0.2, 0, 0.6>] } scale 0.3 }\n";

TEST_F(PovRayPigmentMap, EntriesArePickedAndMixedInThePatternsSpace) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 pigment { gradient x scale 2 pigment_map { [0.2 rgb <0.1, 0.6, 0.2>]\n"
      "  [0.4 Stripes rotate 30 * y] [0.7 Stripes scale 0.5]\n"
      "  [0.9 checker rgb 1 rgb 0 scale 0.2] } translate 0.3 * x } }\n"
      "sphere { <0, 1, 0>, 1 pigment { gradient y translate 0.2 * y\n"
      "  pigment_map { [0 rgb <1, 0, 0>] [1 Stripes] } scale 0.5 } translate 0.5 * x }\n";
  EXPECT_GE(compare("pigment_map", scene), 40.0) << convray_err;
}

TEST_F(PovRayPigmentMap, CheckerOfPigmentsAndSkySpheres) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "sky_sphere { pigment { gradient y pigment_map { [0 rgb <0.9, 0.7, 0.5>]\n"
      "  [0.3 Stripes scale 0.2] [0.6 rgb <0.1, 0.2, 0.7>] } } }\n"
      "plane { y, 0 pigment { checker pigment { Stripes rotate 90 * y } pigment { rgb 0.9 }\n"
      "  scale 0.7 } }\n"
      "box { <-1, 0, -1>, <1, 1.5, 1> pigment { checker rgb <1, 0, 0> rgbt <0, 0, 1, 0.5>\n"
      "  scale 0.5 } rotate 30 * y }\n";
  EXPECT_GE(compare("checker_pigments", scene), 40.0) << convray_err;
}

TEST_F(PovRayPigmentMap, AverageMixesThePigmentsByWeight) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 pigment { average pigment_map { [gradient x color_map { [0 rgb 0]\n"
      "  [1 rgb <1, 0.5, 0>] }] [3 checker rgb <0, 0, 1> rgb 1 scale 0.5]\n"
      "  [0.5 rgbt <0, 1, 0, 0.8>] } scale 2 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { average translate y pigment_map { [2 Stripes]\n"
      "  [1 rgb <0.2, 0.3, 0.9>] } } finish { phong 0.5 } }\n";
  EXPECT_GE(compare("average_pigment", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
