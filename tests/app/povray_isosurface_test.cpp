// Isosurfaces, function patterns and pigment functions against the povray binary's pictures:
// the inside (f < threshold), the container's faces where the solid reaches them (and none
// with `open`), functions.inc's f_rounded_box, and the wrap of a function pattern's value;
// and trace()'s points and normals on isosurfaces against the numbers the binary prints
// (where POV-Ray reports a crossing for a given accuracy, and its minimum depth).
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayIsosurface : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "#include \"functions.inc\"\n"
    "camera { location <0, 3, -8> look_at <0, 0, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "light_source { <5, 3, -2> color rgb 0.4 }\n"
    "plane { y, -1.5 pigment { checker rgb 0.3 rgb 0.7 } }\n";

TEST_F(PovRayIsosurface, ContainersThresholdAndOpen) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } }\n"
      "  max_gradient 7 pigment { rgb <0.9, 0.3, 0.2> } translate <-2.5, 0, 0> }\n"
      // A wavy plane cut by a sphere: the sphere's surface closes the solid below it.
      "isosurface { function { y + 0.3 * sin(3 * x) } threshold 0.1\n"
      "  contained_by { sphere { 0, 1.2 } } max_gradient 1.5\n"
      "  pigment { rgb <0.2, 0.8, 0.3> } }\n"
      "isosurface { function { y + 0.3 * sin(3 * x) } contained_by { box { -1, 1 } } open\n"
      "  max_gradient 1.5 pigment { rgb <0.3, 0.4, 0.9> } rotate -30 * y translate <2.5, 0, 0> }\n";
  EXPECT_GE(compare("iso_containers", scene), 30.0) << convray_err;
}

TEST_F(PovRayIsosurface, RoundedBoxAndFunctionPatterns) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "isosurface { function { f_rounded_box(x, y, z, 0.2, 1, 0.7, 0.8) }\n"
      "  contained_by { box { -1.1, 1.1 } }\n"
      "  pigment { function { x * 2 + y } color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] } }\n"
      "  rotate <-10, 30, 0> translate <-1.6, 0, 0> }\n"
      "#declare Stripes = function { pattern { gradient x } }\n"
      "#declare Tint = function { pigment { gradient y color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } } }\n"
      "sphere { 0, 1.2 translate <1.6, 0, 0>\n"
      "  pigment { function { Stripes(x * 3, 0, 0) * 0.5 + Tint(0, y, 0).green * 0.5 } } }\n";
  EXPECT_GE(compare("iso_functions", scene), 30.0) << convray_err;
}

// trace() on isosurfaces: POV-Ray reports the far end of the piece of the ray's stretch in
// the container, halved to `accuracy` or less, that holds the root, with the forward
// difference of f (step `accuracy`) as the normal, and skips crossings within 5 accuracies of
// the ray's start. Rays from outside the container, from inside it, from inside the solid
// next to its surface, slanted and unnormalized, at three accuracies, box and sphere
// containers, and a transformed isosurface.
TEST_F(PovRayIsosurface, TracePointsAndNormalsWhereThePovrayBinaryReportsThem) {
  SKIP_WITHOUT_POVRAY();
  std::string scene =
      "#version 3.7;\n"
      "#declare N = y;\n"
      "#macro T(O, A, B) #local H = trace(O, A, B, N);\n"
      "  #debug concat(vstr(3, H, \", \", 0, 12), \" n \", vstr(3, N, \", \", 0, 12), \"\\n\")\n"
      "#end\n";
  for (const char* accuracy : {"0.01", "0.001", "0.0001"}) {
    const std::string a = accuracy;
    scene +=
        "#declare B = isosurface { function { x*x*x + y*y + z*z*z*z - 1 } max_gradient 10\n"
        "  contained_by { box { <-2, -3, -2>, <2, 1.5, 2> } } accuracy " + a + " }\n"
        "#declare S = isosurface { function { x*x + y*y + z*z - 1 } max_gradient 4\n"
        "  contained_by { sphere { <0.1, 0.2, 0>, 1.7 } } accuracy " + a + " }\n"
        "#declare M = object { B scale <1, 2, 0.5> rotate 20 * z translate <0.3, -0.2, 0.1> }\n"
        "T(B, <0.3, 10, 0.2>, -y) T(B, <0.7, 10, -0.6>, -y) T(B, <0.3, 1.2, 0.2>, <0.1, -1, 0.05>)\n"
        "T(S, <0.3, 10, 0.2>, -y) T(S, <0, 0.99, 0>, y) T(S, <0, 0.9, 0>, y) T(S, <0, 0.5, 0>, y)\n"
        "T(S, <0, 1.002, 0>, -y) T(S, <0, 1.1, 0>, -y) T(S, <0.2, -0.3, 0.1>, <1, 2, -0.5>)\n"
        "T(M, <0.5, 10, 0.3>, -y) T(M, <-3, 0.4, 0.2>, <1, 0.2, 0.1>)\n";
  }
  std::vector<double> expected, found;
  std::string output;
  debug_numbers(scene, expected, found, &output);
  ASSERT_EQ(found.size(), expected.size()) << output;
  ASSERT_EQ(found.size(), 3u * 12u * 6u);
  for (size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-9) << i;
}

}  // namespace
}  // namespace convray::testing
