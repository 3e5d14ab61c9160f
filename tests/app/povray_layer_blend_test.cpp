// Transparent layers against the povray binary's pictures, for each language version whose
// rule differs (render/layer_blend.hpp): POV-Ray 3.7 blends every layer one way; the 3.7
// binary draws older scenes as the older versions did (3.5 and 3.6 weigh a filtered layer's
// own colour by 1 - filter * its brightest channel; before 3.5, layers of one texture and,
// before 3.7, a sky_sphere's layers let filter through like transmit). Patterned layers, so
// each picture holds many colour and filter values.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayLayerBlend : public PovRayPictureTest {};

std::string scene_for(const std::string& version) {
  return "#version " + version + ";\n"
         "global_settings { assumed_gamma 1.0 }\n"
         "camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 60 }\n"
         "light_source { <-3, 5, -4> color rgb 1 }\n"
         "background { color rgb <0.2, 0.5, 0.1> }\n"
         "sky_sphere {\n"
         "  pigment { gradient y color_map { [0 rgb <0.4, 0.6, 0.9>] [1 rgb <0.1, 0.1, 0.4>] } }\n"
         "  pigment { gradient x color_map { [0 rgbf <0.9, 0.9, 0.9, 0.9>] [0.5 rgbf <0.8, 0.4,\n"
         "    0.2, 0.3>] [1 rgbft <0.3, 0.6, 0.1, 0.4, 0.2>] } scale 0.3 }\n"
         "}\n"
         // A layered texture: an opaque checker under two filtered, patterned layers.
         "box { <-2.2, 0, 0>, <-0.2, 2, 0.5>\n"
         "  texture { pigment { checker rgb <0.39, 0.58, 0.93> rgb <0.9, 0.7, 0.2> scale 0.4 } }\n"
         "  texture { pigment { gradient y color_map { [0 rgbf <0.9, 0.9, 0.9, 0.9>]\n"
         "    [1 rgbf <0.8, 0.4, 0.2, 0.5>] } } finish { phong 0.5 } }\n"
         "  texture { pigment { gradient x color_map { [0 rgbf <0.45, 0.45, 0.45, 0.9>]\n"
         "    [1 rgbt <0.2, 0.4, 0.8, 0.5>] } scale 0.5 } } }\n"
         // A single filtered layer over what lies behind it.
         "box { <0.2, 0, 0>, <2.2, 2, 0.5>\n"
         "  pigment { gradient y color_map { [0 rgbf <0.8, 0.4, 0.2, 0.5>]\n"
         "    [1 rgbft <0.3, 0.6, 0.1, 0.3, 0.4>] } } }\n"
         "plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }\n";
}

TEST_F(PovRayLayerBlend, EachLanguageVersionBlendsAsThePovrayBinaryDoes) {
  SKIP_WITHOUT_POVRAY();
  for (const std::string version : {"3.7", "3.6", "3.5", "3.1"}) {
    EXPECT_GE(compare("layers_" + version, scene_for(version)), 45.0)
        << "#version " << version << "\n" << convray_err;
  }
}

}  // namespace
}  // namespace convray::testing
