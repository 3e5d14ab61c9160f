// A negative transmit against POV-Ray 3.7: `transmit -1` subtracts what is behind the surface
// (and (1 - t) doubles its own light); the ray behind is traced all the same.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayNegativeTransmit : public PovRayPictureTest {};

TEST_F(PovRayNegativeTransmit, SubtractsWhatIsBehind) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
      "camera { orthographic location <0, 0, -10> look_at 0 right 4 * x up 3 * y }\n"
      "plane { z, 2 pigment { checker color rgb <0.2, 0.4, 0.6> color rgb <0.1, 0.3, 0.2>\n"
      "  scale 0.5 } finish { ambient 1 diffuse 0 } }\n"
      "disc { <-1, 0, 0>, z, 0.9 pigment { rgb 0.5 transmit -1 } finish { ambient 1 diffuse 0 } }\n"
      "disc { <1, 0, 0>, z, 0.9 pigment { rgb <0.6, 0.5, 0.4> filter -0.5 }\n"
      "  finish { ambient 1 diffuse 0 } }\n";
  EXPECT_GE(compare("negative_transmit", scene), 40.0);
}

}  // namespace
}  // namespace convray::testing
