// Fog and solids against POV-Ray 3.7: no fog is drawn along rays inside a solid that is not
// hollow (the camera's, then those the rays enter through transparent surfaces); `hollow`
// lets it in. Rendered by povray and convray, compared by PSNR.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

std::string scene(const std::string& sky_plane_flags, const std::string& glass_flags) {
  return "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
         "camera { location <0, 1, -6> look_at <0, 0.5, 0> }\n"
         "light_source { <3, 5, -4> color rgb 1 }\n"
         "fog { distance 6 color rgb <0.7, 0.75, 0.8> }\n"
         // The camera is under this plane: inside its solid.
         "plane { y, 50 pigment { rgb <0.2, 0.3, 0.9> } " + sky_plane_flags + " }\n"
         "plane { y, -1 pigment { checker color rgb 1 color rgb 0.2 } }\n"
         "sphere { <1.2, 0.2, 2>, 1.2 pigment { rgbt <1, 1, 1, 0.9> } " + glass_flags + " }\n"
         "box { <-3, -1, 4>, <-1, 2, 6> pigment { rgb <1, 0.3, 0.2> } }\n";
}

class PovRayFogInSolids : public PovRayPictureTest {};

TEST_F(PovRayFogInSolids, NoFogInsideSolidsThatAreNotHollow) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("solid", scene("", "")), 40.0);
}

TEST_F(PovRayFogInSolids, HollowSolidsLetTheFogIn) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("hollow", scene("hollow", "hollow")), 40.0);
}

}  // namespace
}  // namespace convray::testing
