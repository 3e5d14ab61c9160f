// Variable reflection, conserve_energy and the weight adc_bailout gives reflected rays,
// against POV-Ray 3.7 (render/variable_reflection.hpp).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayReflection : public PovRayPictureTest {};

const std::string kHeader =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
    "background { rgb <0.9, 0.8, 0.7> }\n"
    "camera { orthographic location <0, 0, -10> look_at 0 right 4.4 * x up 3.3 * y }\n"
    "plane { z, -12 pigment { checker rgb 1 rgb <0.2, 0.3, 0.6> scale 2 }\n"
    "  finish { ambient 1 diffuse 0 } }\n";

std::string sphere(const std::string& at, const std::string& finish, double ior) {
  return "sphere { " + at + ", 1 pigment { rgb 0 } finish { ambient 0 diffuse 0 " + finish +
         " } interior { ior " + std::to_string(ior) + " } }\n";
}

TEST_F(PovRayReflection, VariesWithTheAngle) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = kHeader + sphere("<-1.1, 0.8, 0>", "reflection { 0, 1 }", 1.5) +
                            sphere("<1.1, 0.8, 0>", "reflection { 0.1, 0.7 falloff 2 }", 1.5) +
                            sphere("<-1.1, -0.8, 0>", "reflection { 0.2, 0.6 fresnel on }", 1.5) +
                            sphere("<1.1, -0.8, 0>", "reflection { 0.8 fresnel on }", 2.4);
  EXPECT_GE(compare("variable_reflection", scene), 40.0);
}

TEST_F(PovRayReflection, MetallicReflectionTakesThePigmentsColour) {
  SKIP_WITHOUT_POVRAY();
  // `reflection { R metallic M }` tints the reflection, the finish's `metallic` does not.
  const std::string scene =
      kHeader +
      "sphere { <-1.1, 0.8, 0>, 1 pigment { rgb <0.9, 0.5, 0.2> }\n"
      "  finish { ambient 0 diffuse 0 reflection { 0.8 metallic } } }\n"
      "sphere { <1.1, 0.8, 0>, 1 pigment { rgb <0.2, 0.9, 0.5> }\n"
      "  finish { ambient 0 diffuse 0 reflection { 0.1, 0.9 metallic 0.5 } } }\n"
      "sphere { <0, -0.8, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> }\n"
      "  finish { ambient 0 diffuse 0 reflection 0.8 metallic } }\n";
  EXPECT_GE(compare("metallic_reflection", scene), 40.0);
}

TEST_F(PovRayReflection, ConserveEnergyDimsTransmittedLightByTheReflection) {
  SKIP_WITHOUT_POVRAY();
  // A perspective camera sees the transparent plane at every angle; behind it a lit checker.
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { rgb 0 }\n"
      "camera { location 0 direction z right 4 * x up 3 * y }\n"
      "plane { -z, -2 pigment { checker rgb 1 rgb <0.3, 0.6, 0.2> } finish { ambient 1 diffuse 0 } }\n"
      "plane { -z, -1 hollow pigment { rgbt <1, 1, 1, 0.8> }\n"
      "  finish { ambient 0.2 diffuse 0 reflection { rgb <0.1, 0.3, 0.2>, 1 } conserve_energy } }\n";
  EXPECT_GE(compare("conserve_energy", scene), 40.0);
}

TEST_F(PovRayReflection, AdcBailoutWeighsFresnelByTheAngleOthersByTheMaximum) {
  SKIP_WITHOUT_POVRAY();
  // Under adc_bailout 0.1 POV-Ray traces `reflection { 0, 0.2 }` at every angle (and the
  // mirror it sees), `reflection { 0, 1 fresnel on }` only where it reaches 0.1.
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 adc_bailout 0.1 }\n"
      "background { rgb 1 }\n"
      "camera { orthographic location <0, 0, -10> look_at 0 right 4.4 * x up 3.3 * y }\n"
      "plane { z, -15 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }\n" +
      sphere("<-1.1, 0, 0>", "reflection { 0, 0.2 }", 1.5) +
      sphere("<1.1, 0, 0>", "reflection { 0, 1 fresnel on }", 1.5);
  EXPECT_GE(compare("adc_weights", scene), 40.0);
}

TEST_F(PovRayReflection, GlassWithDeepTraceLevelStaysCheap) {
  SKIP_WITHOUT_POVRAY();
  // glass.inc's F_Glass5 (fresnel, conserve_energy) in stacked boxes under max_trace_level
  // 50: fresnel's weak reflections die by adc_bailout, as in POV-Ray (stackertransp.pov).
  std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 max_trace_level 50 }\n"
      "background { rgb <0.6, 0.7, 0.9> }\n"
      "camera { location <2, 3, -6> look_at <0, 1, 0> }\n"
      "light_source { <-5, 10, -10> rgb 1 }\n"
      "plane { y, 0 pigment { checker rgb 1 rgb 0.2 } }\n";
  for (int i = 0; i < 6; ++i) {
    scene += "box { -0.45, 0.45 translate <" + std::to_string(0.3 * i - 0.8) + ", " +
             std::to_string(0.45 + 0.9 * (i % 3)) + ", " + std::to_string(0.2 * (i / 3)) +
             "> pigment { rgbf <0.9, 0.98, 1, 0.95> }\n"
             "  finish { ambient 0 diffuse 0 specular 0.7 roughness 0.001\n"
             "    reflection { 0.2, 1.0 fresnel on } conserve_energy } interior { ior 1.5 } }\n";
  }
  EXPECT_GE(compare("glass_stack", scene), 35.0);
}

}  // namespace
}  // namespace convray::testing
