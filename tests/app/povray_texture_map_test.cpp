// Texture patterns: `PATTERN texture_map { [v T] ... }` (whole textures, finishes and normals
// included, picked and mixed by a pattern), `average texture_map`, `tiles { ... tile2 ... }`,
// against the povray binary's pictures.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayTextureMap : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "#declare Shiny = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.9 } }\n"
    "#declare Stripes = texture { pigment { gradient z color_map { [0.5 rgb <1, 1, 0>]\n"
    "  [0.5 rgb <0.2, 0, 0.6>] } scale 0.3 } normal { bumps 0 } }\n";

TEST_F(PovRayTextureMap, EntriesArePickedAndMixedInThePatternsSpace) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 texture { gradient x scale 2 texture_map { [0.2 pigment { rgb 0.8 }]\n"
      "  [0.4 Stripes rotate 30 * y] [0.6 Shiny] [0.6 pigment { checker rgb 1 rgb 0 }\n"
      "  scale 0.2] [0.9 pigment { rgb <0.1, 0.5, 0.2> } finish { ambient 0.4 }] }\n"
      "  translate 0.3 * x } }\n"
      "sphere { <0, 1, 0>, 1 texture { spherical translate <0, 1, -0.8>\n"
      "  texture_map { [0.1 Shiny] [0.7 pigment { rgb <0.2, 0.4, 1> }\n"
      "  normal { gradient y 0.5 scale 0.2 }] } } }\n"
      "box { <1.3, 0, -0.5>, <2.3, 1, 0.5> texture { planar frequency 2 texture_map {\n"
      "  [0 Shiny] [1 pigment { onion color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 }\n"
      "  ] } translate 0.5 * y } }\n";
  EXPECT_GE(compare("texture_map", scene), 40.0) << convray_err;
}

TEST_F(PovRayTextureMap, AverageTilesAndNestedMaps) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { y, 0 texture { tiles { texture { Stripes } texture { pigment { rgbt <0, 0, 1,\n"
      "  0.6> } } tile2 texture { pigment { rgb 0.9 } } } scale 0.8 } }\n"
      "sphere { <-1.2, 1, 0>, 1 texture { average texture_map { [Shiny]\n"
      "  [2 pigment { radial frequency 8 } finish { ambient 0.3 }] [Stripes] } } }\n"
      "sphere { <1.2, 1, 0>, 1 texture { gradient y texture_map { [0.3 Shiny] [0.7 boxed\n"
      "  texture_map { [0.2 Stripes] [0.8 pigment { rgb <0.3, 0.9, 0.4> }] } scale 0.5 ] }\n"
      "  translate 0.2 * y } }\n";
  EXPECT_GE(compare("texture_average_tiles", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
