// pigment_pattern against POV-Ray 3.7: the pattern's value is the grey of the pigment's colour
// (0.297 R + 0.589 G + 0.114 B, filter and transmit aside); both programs print it with #debug
// at the same points for plain, mapped, layered-pattern and transformed pigments.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayPigmentPattern : public PovRayPictureTest {};

TEST_F(PovRayPigmentPattern, TheValueIsThePigmentsGrey) {
  SKIP_WITHOUT_POVRAY();
  std::string scene =
      "#version 3.7;\n"
      "#declare F0 = function { pattern { pigment_pattern {\n"
      "  color rgbft <0.2, 0.7, 0.4, 0.5, 0.3> } } }\n"
      "#declare F1 = function { pattern { pigment_pattern { gradient x color_map { [0 rgb 0]\n"
      "  [1 rgb <1, 0.5, 0.2>] } } } }\n"
      "#declare F2 = function { pattern { pigment_pattern { checker color rgb <1, 0, 0>\n"
      "  color rgb <0, 0, 1> scale 0.7 } } }\n"
      "#declare F3 = function { pattern { pigment_pattern { bozo scale 0.3 } rotate 30 * y } }\n"
      "#declare F4 = function { pattern { pigment_pattern { agate color_map {\n"
      "  [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.8>] } } } }\n"
      "#declare S = seed(5);\n"
      "#declare I = 0;\n"
      "#while (I < 12)\n"
      "  #declare P = <rand(S), rand(S), rand(S)> * 6 - 3;\n"
      "  #debug concat(str(F0(P.x, P.y, P.z), 0, 9), \" \", str(F1(P.x, P.y, P.z), 0, 9), \" \",\n"
      "    str(F2(P.x, P.y, P.z), 0, 9), \" \", str(F3(P.x, P.y, P.z), 0, 9), \" \",\n"
      "    str(F4(P.x, P.y, P.z), 0, 9), \"\\n\")\n"
      "  #declare I = I + 1;\n"
      "#end\n";
  std::vector<double> pov, ours;
  debug_numbers(scene, pov, ours);
  ASSERT_EQ(pov.size(), 60u);
  ASSERT_EQ(ours.size(), pov.size());
  for (size_t i = 0; i < pov.size(); ++i) EXPECT_NEAR(ours[i], pov[i], 1e-4) << i;  // gradient drifts by 1e-5
}

TEST_F(PovRayPigmentPattern, PicksColoursInAPigment) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
      "camera { location <0, 1, -4> look_at <0, 0.3, 0> }\n"
      "light_source { <3, 5, -4> color rgb 1 }\n"
      "plane { y, -1 pigment { pigment_pattern { checker color rgb 0.2 color rgb 0.9 }\n"
      "  color_map { [0 rgb <0.1, 0.2, 0.6>] [1 rgb <1, 0.8, 0.2>] } } }\n"
      "sphere { <0, 0.3, 0>, 1 pigment { pigment_pattern { gradient y color_map {\n"
      "  [0 rgb 0] [1 rgb 1] } scale 0.5 } color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } } }\n";
  EXPECT_GE(compare("pigment_pattern", scene), 40.0);
}

}  // namespace
}  // namespace convray::testing
