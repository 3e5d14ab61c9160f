// image_map against the povray binary's pictures: POV-Ray's own test.png (in its include
// folder, which both programs search) on the planar, spherical, cylindrical and torus
// projections, repeated and once, without interpolation, bilinear and normalized distance.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayImageMap : public PovRayPictureTest {};

const std::string kSetting =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n";

TEST_F(PovRayImageMap, ProjectionsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { z, 1 pigment { image_map { png \"test.png\" } scale 1.3 translate <0.2, 0.1, 0> } }\n"
      "sphere { <-2, 1, 0>, 0.9 pigment { image_map { png \"test.png\" map_type 1 } "
      "rotate 30 * y translate <-2, 1, 0> } }\n"
      "cylinder { <0, 0, -0.5>, <0, 1.8, -0.5>, 0.7 pigment { image_map { png \"test.png\" "
      "map_type 2 } scale <1, 0.7, 1> translate -0.5 * z } }\n"
      "torus { 1, 0.4 rotate -60 * x translate <2.1, 1, -0.5> pigment { image_map { "
      "png \"test.png\" map_type 5 } rotate -60 * x translate <2.1, 1, -0.5> } }\n";
  EXPECT_GE(compare("image_projections", scene), 40.0) << convray_err;
}

TEST_F(PovRayImageMap, OnceAndInterpolationAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  const std::string scene =
      kSetting +
      "plane { z, 1 pigment { rgb <0.2, 0.3, 0.5> } }\n"
      "box { <-3, 0, -1>, <-1, 2, 0> pigment { image_map { png \"test.png\" once } scale 1.2\n"
      "  translate <-2.6, 0.3, 0> } }\n"
      "box { <-0.9, 0, -1>, <0.9, 2, 0> pigment { image_map { png \"test.png\" interpolate 2 }\n"
      "  scale 8 translate <-4, -3, 0> } }\n"
      "box { <1, 0, -1>, <3, 2, 0> pigment { image_map { png \"test.png\" interpolate 4 }\n"
      "  scale 8 translate <-2, -3, 0> } }\n";
  EXPECT_GE(compare("image_once_interpolate", scene), 40.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
