// Layered textures (`texture { A } texture { B }`: B over A, A seen where B's pigment lets
// light through) and block texture patterns (`texture { checker texture { A } texture { B }
// }`), rendered by povray and by convray: the pictures must match.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayTextureLayers : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "background { rgb <0.2, 0.3, 0.5> }\n";

TEST_F(PovRayTextureLayers, TransparentLayersShowTheLayersBelow) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "#declare Lines = texture { pigment { gradient x color_map { [0 rgbt <0.1, 0.2, 0.9, 0>]\n"
      "  [0.2 rgbt <0.1, 0.2, 0.9, 0>] [0.2 rgbt 1] [1 rgbt 1] } scale 0.5 } }\n"
      "plane { y, 0\n"
      "  texture { pigment { rgb 0.9 } finish { ambient 0.3 diffuse 0.7 } }\n"
      "  texture { Lines }\n"
      "  texture { Lines rotate 90 * y }\n"
      "}\n"
      "sphere { <-1.2, 1, 0>, 1\n"
      "  texture { pigment { rgb <1, 0.3, 0.2> } finish { phong 0.8 } }\n"
      "  texture { pigment { gradient y color_map { [0.5 rgbf <1, 1, 0, 0.7>]\n"
      "    [0.5 rgbt <0, 0, 0, 1>] } scale 0.4 } finish { reflection 0.2 } }\n"
      "}\n"
      "sphere { <1.2, 1, 0>, 1\n"
      "  texture { pigment { rgb <0.2, 0.8, 0.3> } }\n"
      "  texture { pigment { rgbt <1, 1, 1, 0.6> } finish { diffuse 0.4 phong 1 } }\n"
      "}\n";
  EXPECT_GE(compare("layers", scene), 40.0) << convray_err;
}

TEST_F(PovRayTextureLayers, CheckerOfTexturesPicksAWholeTexturePerBlock) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "#declare Dark = texture { pigment { rgb <0.2, 0.1, 0> } finish { phong 1 } }\n"
      "#declare Light = texture { pigment { rgb <1, 0.9, 0.6> } finish { ambient 0.4 } }\n"
      "plane { y, 0 texture { checker texture { Light } texture { Dark } translate 0.3 * x }\n"
      "  scale 1.5 }\n"
      "cylinder { <-2, 0, 1>, <2, 1.5, 1>, 0.4\n"
      "  texture { checker texture { Dark } texture { pigment { rgb <0.3, 0.6, 1> } }\n"
      "    scale 0.5 rotate 30 * z } }\n";
  EXPECT_GE(compare("checker_textures", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
