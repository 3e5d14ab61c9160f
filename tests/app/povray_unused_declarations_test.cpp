// POV-Ray's include files declare textures and sky spheres that need features convray cannot
// render yet (stones2.inc's crackle, skies.inc's pigment_map); a scene that includes them and
// never uses those must render as POV-Ray renders it.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayUnusedDeclarations : public PovRayPictureTest {};

TEST_F(PovRayUnusedDeclarations, IncludesWithUnsupportedDeclarationsRenderAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "#include \"colors.inc\"\n#include \"stones.inc\"\n#include \"skies.inc\"\n"
      "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
      "light_source { <3, 5, -3> color White }\n"
      "sphere { <0, 0.5, 0>, 1 pigment { color Orange } finish { phong 0.5 } }\n"
      "plane { y, -0.5 pigment { checker color White color Gray40 } }\n";
  EXPECT_GE(compare("unused_declarations", scene), 40.0);
}

}  // namespace
}  // namespace convray::testing
