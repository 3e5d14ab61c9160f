// Patterns used as normals without a normal of their own (render/sampled_normal.hpp): POV-Ray
// samples them at a small tetrahedron around the point. Pictures against the povray binary's:
// creases where a ramp wraps, the edges of block patterns, thresholds, the `accuracy`
// keyword and non-uniform pattern transforms.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRaySampledNormals : public PovRayPictureTest {};

const std::string kStage =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 0, -6> look_at <0, 0, 0> angle 60 }\n"
    "light_source { <-4, 6, -8> color rgb 1 }\n";

// Six spheres, one normal each, shiny so that every tilt shows.
std::string bumped_spheres(const std::string (&normals)[6]) {
  std::string scene = kStage;
  for (int k = 0; k < 6; ++k) {
    const double x = -2.4 + 2.4 * (k % 3), y = k < 3 ? 1.2 : -1.2;
    scene += "sphere { 0, 1.1 pigment { rgb <0.9, 0.8, 0.6> } finish { phong 0.9 phong_size 60 }"
             " normal { " + normals[k] + " } translate <" + std::to_string(x) + ", " +
             std::to_string(y) + ", 0> }\n";
  }
  return scene;
}

TEST_F(PovRaySampledNormals, RampsAndTheirCreasesMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string normals[6] = {"gradient x, 5.6 scale 0.24",
                                  "gradient <1, 1, 0> 2 scale 0.3 rotate 20 * z",
                                  "onion 3 scale 0.2",
                                  "marble 1.5 turbulence 0.3 scale 0.5",
                                  "radial 2 frequency 6",
                                  "leopard 4 scale 0.1"};
  EXPECT_GE(compare("ramps", bumped_spheres(normals)), 45.0) << convray_err;
}

TEST_F(PovRaySampledNormals, NoiseAndFunctionPatternsMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string normals[6] = {"granite 2.6",
                                  "agate 1.6 scale 0.5",
                                  "bozo 1 scale 0.3",
                                  "function { x * x + y } 1 scale 0.5",
                                  "function { z > 0.3 } 2 scale 0.6",
                                  "pigment_pattern { spotted color_map { [0 rgb 0] [1 rgb 1] } "
                                  "scale 0.3 } 2"};
  EXPECT_GE(compare("noise_functions", bumped_spheres(normals)), 45.0) << convray_err;
}

TEST_F(PovRaySampledNormals, TurbulenceMovesTheWholeTetrahedron) {
  SKIP_WITHOUT_POVRAY();
  // The plain turbulence moves the sampled point once (a ramp keeps its tilt); marble's and
  // wood's own turbulence is sampled at every corner.
  const std::string normals[6] = {"granite 0.7 turbulence 0.2 scale 1.2",
                                  "bozo 1 turbulence 0.5 scale 0.4",
                                  "gradient x 2 turbulence 0.5 scale 0.3",
                                  "marble 1 turbulence 0.8 scale 0.6",
                                  "wood 1 turbulence 0.1 scale 0.2",
                                  "agate 1 warp { turbulence 0.3 } scale 0.5"};
  EXPECT_GE(compare("turbulence", bumped_spheres(normals)), 45.0) << convray_err;
}

TEST_F(PovRaySampledNormals, BlockPatternsCreaseAtTheirEdges) {
  SKIP_WITHOUT_POVRAY();
  const std::string normals[6] = {"hexagon 1.6 scale 0.124 rotate 90 * x",
                                  "checker 1 scale 0.3",
                                  "brick 1 scale 0.05",
                                  "hexagon 3 scale 0.3",
                                  "checker 2 scale 0.25 rotate 45 * y",
                                  "brick 2 brick_size <1, 0.5, 0.7> mortar 0.1 scale 0.3"};
  const double db = compare("blocks", bumped_spheres(normals));
  EXPECT_GE(db, 45.0) << convray_err;
  EXPECT_EQ(convray_err.find("left out"), std::string::npos) << convray_err;
}

TEST_F(PovRaySampledNormals, AccuracyAndSquashedPatternsMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::string normals[6] = {"gradient x 3 scale 0.2 accuracy 0.06",
                                  "granite 1 accuracy 0.005",
                                  "onion 1 scale <0.3, 0.3, 1>",
                                  "gradient y 2 scale <1, 0.3, 0.5> rotate 30 * x",
                                  "wood 1 scale <0.2, 1, 3> rotate <20, 40, 0>",
                                  "granite 1.5 scale <2, 0.5, 1>"};
  EXPECT_GE(compare("accuracy", bumped_spheres(normals)), 45.0) << convray_err;
}

}  // namespace
}  // namespace convray::testing
