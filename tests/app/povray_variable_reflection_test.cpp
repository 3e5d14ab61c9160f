// Variable reflection (render/variable_reflection.hpp): `reflection { MIN, MAX }` with its
// falloff, and with fresnel the Fresnel reflectance of the interior's ior, against the povray
// binary's pictures.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayVariableReflection : public PovRayPictureTest {};

// Six dark spheres mirroring a checkered floor and a gradient sky, one reflection each.
std::string mirror_spheres(const std::string (&reflections)[6]) {
  std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 1, -7> look_at <0, 0.3, 0> angle 60 }\n"
      "light_source { <-4, 6, -8> color rgb 1 }\n"
      "sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0.9, 0.7>] [1 rgb <0.2, 0.4, 1>] } } }\n"
      "plane { y, -1.2 pigment { checker rgb 1, rgb <0.8, 0.2, 0.1> } }\n";
  for (int k = 0; k < 6; ++k) {
    const double x = -2.4 + 2.4 * (k % 3), y = k < 3 ? 1.3 : -0.2;
    scene += "sphere { 0, 1.1 pigment { rgb 0.05 } finish { ambient 0 diffuse 0.1 reflection { " +
             reflections[k] + " } } interior { ior 1.5 } translate <" + std::to_string(x) +
             ", " + std::to_string(y) + ", 0> }\n";
  }
  return scene;
}

TEST_F(PovRayVariableReflection, FalloffAndFresnelMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string reflections[6] = {"0, 1",
                                      "0.1, 0.9 falloff 3",
                                      "0.9, 0.1",
                                      "0, 1 fresnel on",
                                      "0.6 fresnel",
                                      "rgb <0.1, 0.2, 0>, rgb <1, 0.6, 0.2> fresnel on"};
  const double db = compare("variable_reflection", mirror_spheres(reflections));
  EXPECT_GE(db, 45.0) << convray_err;
  EXPECT_EQ(convray_err.find("reflection"), std::string::npos) << convray_err;
}

}  // namespace
}  // namespace convray::testing
