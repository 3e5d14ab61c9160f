// no_image and no_reflection against POV-Ray 3.7: a no_image object is hidden from camera rays
// and from what they see through transparent surfaces, yet shows in mirrors and casts shadows;
// a no_reflection object is seen directly but not in mirrors. Each scene is rendered by
// povray and by convray and must match (PSNR).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

const char* kSetting =
    "camera { location <0, 0.5, -5> look_at <0, 0, 0> angle 45 }\n"
    "light_source { <2, 10, -10> color rgb 1 }\n"
    "background { color rgb <0, 0, 0.3> }\n"
    "plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.4 } }\n"
    "plane { z, 3 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.8 } }\n";

class PovRayObjectVisibility : public PovRayPictureTest {};

TEST_F(PovRayObjectVisibility, NoImageIsHiddenFromTheCameraAndWhatItSeesThrough) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = std::string(kSetting) +
                            "sphere { <-1, 0, 0>, 0.7 pigment { rgb <1, 0.2, 0.1> } no_image }\n"
                            "box { <-2, -0.9, -1.5>, <0, 1.2, -1.4> pigment { rgbt <1, 1, 1, 0.8> } }\n"
                            "union { sphere { <1, 0, 0>, 0.5 } cylinder { <1, 0, 0>, <1, 1, 0>, 0.2 }\n"
                            "  pigment { rgb <0.2, 1, 0.3> } no_image }\n";
  EXPECT_GE(compare("no_image", scene), 40.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

TEST_F(PovRayObjectVisibility, NoReflectionIsSeenDirectlyButNotInMirrors) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = std::string(kSetting) +
                            "sphere { <-1, 0, 0>, 0.7 pigment { rgb <1, 1, 0.1> } no_reflection }\n"
                            "sphere { <1, 0, 0>, 0.7 pigment { rgb <0.2, 1, 0.3> } }\n"
                            "union { sphere { <0, 0.8, 1>, 0.3 } sphere { <0, -0.5, 1>, 0.3 }\n"
                            "  pigment { rgb <1, 0.3, 1> } no_reflection }\n";
  EXPECT_GE(compare("no_reflection", scene), 40.0);
  EXPECT_EQ(convray_err.find("ignored"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
