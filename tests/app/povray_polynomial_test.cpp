// POV-Ray's polynomial surfaces (quadric, cubic, quartic, poly) against POV-Ray's pictures:
// shapes of its own include files (shapesq.inc, shapes_old.inc) and written ones, clipped
// and in CSG as the include files expect, rendered by povray and by convray.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayPolynomial : public PovRayPictureTest {};

const char* kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 3, -9> look_at <0, 0, 0> angle 50 }\n"
    "light_source { <-5, 10, -10> color rgb 1 }\n"
    "background { color rgb <0.2, 0.3, 0.4> }\n";

TEST_F(PovRayPolynomial, QuarticsOfShapesqIncAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      std::string(kSetting) + "#include \"shapes.inc\"\n#include \"shapesq.inc\"\n" +
      "object { Torus_40_12 scale 0.05 pigment { color rgb <0.9, 0.4, 0.2> } "
      "finish { phong 0.6 } translate <-2.5, 0, 0> }\n"
      "intersection { object { Piriform } sphere { 0, 2 } pigment { color rgb <0.3, 0.8, 0.3> }"
      " translate <2.5, 0, 0> }\n"
      "intersection { object { Steiner_Surface } sphere { 0, 1.2 } pigment { color rgb 0.8 } "
      "translate <0, 1.5, 0> }\n";
  EXPECT_GE(compare("quartics", scene), 35.0);
}

TEST_F(PovRayPolynomial, QuadricCubicAndPolyAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      std::string(kSetting) + "#include \"shapes_old.inc\"\n" +
      // An ellipsoid written as a quadric, and shapes_old.inc's cone clipped by a box.
      "quadric { <1, 4, 1>, <0.5, 0, 0>, <0, 0, 0.3>, -1 pigment { color rgb <0.2, 0.4, 1> } "
      "translate <-2.5, 0.5, 0> }\n"
      "intersection { object { QCone_Y } box { <-1, -1.5, -1>, <1, 0, 1> } "
      "pigment { color rgb <1, 0.8, 0.2> } translate <2.5, 1, 0> }\n"
      // x^3 - y = 0 as a cubic, and a poly of order 4 (the torus R = 1, r = 0.6), in boxes;
      // no comma after the order, as objects/primitiv.pov writes it.
      "intersection { cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0> } "
      "box { -1, 1 } pigment { color rgb <0.8, 0.2, 0.8> } translate <0, 1.2, 0> }\n"
      "intersection { poly { 4 <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.72, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,"
      " 1, 0, 0, 2, 0, 1.28, 0, 0, 0, 0, 1, 0, -2.72, 0, 0.4096> sturm } box { -2, 2 } "
      "pigment { color rgb <0.3, 0.9, 0.9> } translate <0, -1, -1> }\n";
  EXPECT_GE(compare("polynomials", scene), 35.0);
}

}  // namespace
}  // namespace convray::testing
