// POV-Ray 3.7's gamma rule for older scenes: without assumed_gamma, a scene whose #version is
// below 3.7 when the parse ends (or that never says #version) is written without gamma
// correction, with a warning; otherwise colours are sRGB-encoded. Each scene is rendered by
// povray and by convray and must match (PSNR), and both must warn alike.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

const char* kBody =
    "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
    "light_source { <-3, 5, -4> color rgb 1 }\n"
    "background { color rgb <0.3, 0.5, 0.8> }\n"
    "plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.1> } }\n"
    "sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }\n";
const char* kTurnedOff = "gamma_correction is turned off";

class PovRayGamma : public PovRayPictureTest {};

TEST_F(PovRayGamma, NoVersionAndNoAssumedGammaIsWrittenWithoutGammaCorrection) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("no_version", kBody), 40.0);
  EXPECT_NE(povray_messages.find(kTurnedOff), std::string::npos) << povray_messages;
  EXPECT_NE(convray_err.find(kTurnedOff), std::string::npos) << convray_err;
}

TEST_F(PovRayGamma, Version36WithoutAssumedGammaIsWrittenWithoutGammaCorrection) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("v36", std::string("#version 3.6;\n") + kBody), 40.0);
  EXPECT_NE(convray_err.find(kTurnedOff), std::string::npos) << convray_err;
}

TEST_F(PovRayGamma, TheVersionWhenTheSceneEndsDecides) {
  SKIP_WITHOUT_POVRAY();
  // Raised to 3.7 at the end: gamma corrected; an include that sets and restores #version
  // (colors.inc) counts as a #version of 3.7.
  EXPECT_GE(compare("raised", std::string("#version 3.6;\n") + kBody + "#version 3.7;\n"), 40.0);
  EXPECT_EQ(convray_err.find(kTurnedOff), std::string::npos) << convray_err;
  EXPECT_GE(compare("colors_inc", std::string("#include \"colors.inc\"\n") + kBody), 40.0);
  EXPECT_EQ(convray_err.find(kTurnedOff), std::string::npos) << convray_err;
}

TEST_F(PovRayGamma, AnAssumedGammaKeepsGammaCorrection) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("given", std::string("#version 3.6;\nglobal_settings { assumed_gamma 1.0 }\n") +
                                 kBody),
            40.0);
  EXPECT_EQ(convray_err.find(kTurnedOff), std::string::npos) << convray_err;
  EXPECT_EQ(povray_messages.find(kTurnedOff), std::string::npos) << povray_messages;
}

TEST_F(PovRayGamma, AnAssumedGammaOtherThanOneIsRenderedWithoutAWarning) {
  SKIP_WITHOUT_POVRAY();
  EXPECT_GE(compare("gamma22", std::string("#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n") +
                                   kBody),
            40.0);
  EXPECT_EQ(convray_err.find("assumed_gamma"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
