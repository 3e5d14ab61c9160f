// Prisms of quadratic, cubic and Bezier splines, linear and conic sweeps, against the povray
// binary's pictures: which points close an outline and which only set slopes, and where a
// conic prism's apex lies, are POV-Ray's only if the pictures agree.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayCurvedPrism : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <1, 6, -7> look_at <0, 0.3, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "light_source { <5, 3, -2> color rgb 0.4 }\n"
    "plane { y, -1 pigment { rgb 0.6 } }\n";

// A star-like outline and a hole in it, repeated for each spline's closing rule.
const std::string kQuadratic =
    "12, <0.2, -1>, <0.2, 0.2>, <1, -0.2>, <1, 0.2>, <0.2, 1>, <-0.2, 1>, <-1, 0.2>,\n"
    "  <-1, -0.2>, <-0.2, 0.2>, <-0.2, -1>, <0.2, -1>, <0.2, 0.2>\n";
const std::string kCubic =
    "13, <-0.2, -1>, <0.2, -1>, <0.2, 0.2>, <1, -0.2>, <1, 0.2>, <0.2, 1>, <-0.2, 1>,\n"
    "  <-1, 0.2>, <-1, -0.2>, <-0.2, 0.2>, <-0.2, -1>, <0.2, -1>, <0.2, 0.2>\n";
const std::string kBezier =
    "8, <-1, 0>, <-1, 1.5>, <1, 1.5>, <1, 0>, <1, 0>, <0.5, -0.5>, <-0.5, -0.5>, <-1, 0>\n";

TEST_F(PovRayCurvedPrism, LinearSweeps) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene = kSetting + "prism { quadratic_spline 0, 0.5, " + kQuadratic +
                            "  pigment { rgb <0.9, 0.3, 0.2> } translate <-2.2, 0, 0> }\n" +
                            "prism { cubic_spline -0.3, 0.6, " + kCubic +
                            "  pigment { rgb <0.2, 0.8, 0.3> } rotate 30 * y }\n" +
                            "prism { bezier_spline linear_sweep 0.8, 0, " + kBezier +
                            "  pigment { rgb <0.3, 0.4, 0.9> } translate <2.2, 0, 0.5> }\n";
  EXPECT_GE(compare("curved_prisms", scene), 35.0) << convray_err;
}

TEST_F(PovRayCurvedPrism, ConicSweeps) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "prism { conic_sweep linear_spline 0.3, 1, 5, <-1, -1>, <1, -1>, <1, 1>,\n"
      "  <-1, 1>, <-1, -1> pigment { rgb <0.9, 0.3, 0.2> } scale 1.2 translate <-2.2, -1, 0> }\n" +
      "prism { conic_sweep cubic_spline 0.2, 1, " + kCubic +
      "  pigment { rgb <0.2, 0.8, 0.3> } rotate 180 * x translate y }\n" +
      "difference { prism { conic_sweep bezier_spline 0.5, 1.2, " + kBezier +
      "  } sphere { <0, 1.2, 0>, 0.4 } pigment { rgb <0.3, 0.4, 0.9> } translate <2.2, -1, 0.5> "
      "}\n";
  EXPECT_GE(compare("conic_prisms", scene), 35.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
