// min_extent, max_extent and trace() against the povray binary: the numbers both print with
// #debug for the same scene (boxes of primitives, CSG, transformed objects, text and lathes;
// hits, misses and the normal written into trace's fourth argument).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayObjectFunctions : public PovRayPictureTest {
 protected:
  void expect_same_numbers(const std::string& scene) {
    std::vector<double> expected, found;
    std::string output;
    debug_numbers(scene, expected, found, &output);
    ASSERT_EQ(found.size(), expected.size()) << output;
    ASSERT_GT(found.size(), 20u);
    // POV-Ray pads its boxes by about 1e-5.
    for (size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-4) << i;
  }
};

const std::string kPrint =
    "#macro P(O) #debug concat(vstr(3, min_extent(O), \", \", 0, 6), \" / \",\n"
    "  vstr(3, max_extent(O), \", \", 0, 6), \"\\n\") #end\n";

TEST_F(PovRayObjectFunctions, BoundingBoxes) {
  SKIP_WITHOUT_POVRAY();
  expect_same_numbers(
      "#version 3.7;\n" + kPrint +
      "P(sphere { <1, 2, 3>, 0.5 })\n"
      "P(box { <-1, 0, 0>, <1, 1, 2> rotate 30 * y translate x })\n"
      "P(union { sphere { <1, 2, 3>, 0.5 } box { 0, 1 } })\n"
      "P(difference { box { -1, 1 } sphere { 0, 1.2 } })\n"
      "P(intersection { box { -1, 1 } sphere { <1, 0, 0>, 1 } })\n"
      "P(lathe { cubic_spline 6, <0, -1>, <0, -1>, <1.5, -0.5>, <1, 1>, <0, 1.5>, <0, 1.5> })\n"
      "P(torus { 2, 0.5 rotate 90 * x scale <1, 2, 1> })\n"
      "P(text { ttf \"timrom.ttf\" \"|a|\" 1 0.1 * x scale <2, 2, 1> })\n");
}

TEST_F(PovRayObjectFunctions, Trace) {
  SKIP_WITHOUT_POVRAY();
  expect_same_numbers(
      "#version 3.7;\n"
      "#declare U = union { sphere { <1, 2, 3>, 0.5 } box { -1, 1 rotate 30 * z } }\n"
      "#declare N = <7, 7, 7>;\n"
      "#macro T(A, B) #local H = trace(U, A, B, N);\n"
      "  #debug concat(vstr(3, H, \", \", 0, 6), \" n \", vstr(3, N, \", \", 0, 6), \"\\n\")\n"
      "#end\n"
      "T(<0.2, 10, 0.5>, -y) T(<0, 10, 0.5>, y) T(<1, 2, -3>, <0, 0, 2>)\n"
      "T(<-5, 0.3, 0.1>, <1, 0.1, 0>) T(<1.1, 2, 3>, z)\n"
      "#declare H = trace(U, <1, 2.1, -3>, z);\n"
      "#debug concat(vstr(3, H, \", \", 0, 6), \"\\n\")\n");
}

}  // namespace
}  // namespace convray::testing
