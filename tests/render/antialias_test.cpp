// The anti-aliasing decisions and sample positions on their own (the rendered average at an
// edge is in render_scene_test.cpp).
#include "render/antialias.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace convray::render {
namespace {

TEST(Antialias, ColourDistanceSumsChannelDifferencesOfClampedColours) {
  EXPECT_NEAR(color_distance(Vec3(0.1, 0.2, 0.3), Vec3(0.2, 0.0, 0.3), 1.0), 0.3, 1e-12);
  EXPECT_NEAR(color_distance(Vec3(5.0, 0, 0), Vec3(1.0, 0, 0)), 0.0, 1e-12);  // both white
}

TEST(Antialias, ColoursAreComparedThroughPovRaysAntialiasGamma) {
  // POV-Ray 3.7 starts supersampling greys 0.5 / 0.6 below a threshold of 0.1714 and
  // 0.05 / 0.15 below 0.4995 (bisected on its renders): c^(1/2.5) differences, summed.
  EXPECT_NEAR(color_distance(Vec3(0.5), Vec3(0.6)), 0.1714, 0.003);
  EXPECT_NEAR(color_distance(Vec3(0.05), Vec3(0.15)), 0.4995, 0.003);
  const double one = std::pow(0.6, 0.4) - std::pow(0.5, 0.4);
  EXPECT_NEAR(color_distance(Vec3(0.5), Vec3(0.6)), 3.0 * one, 1e-12);
}

TEST(Antialias, BothPixelsOfADifferingPairAreSupersampled) {
  Film film(4, 3);
  film.set(1, 1, Vec3(0.2, 0.1, 0.05));  // distance 0.35 from its black neighbours (gamma 1)
  const std::vector<uint8_t> flags = pixels_to_supersample(film, 0.3, 1.0);
  const std::vector<uint8_t> expected = {0, 1, 0, 0,   // above
                                         1, 1, 1, 0,   // left, itself, right
                                         0, 1, 0, 0};  // below
  EXPECT_EQ(flags, expected);
  EXPECT_EQ(pixels_to_supersample(film, 0.36, 1.0), std::vector<uint8_t>(12, 0));  // not above
}

TEST(Antialias, GridOfSubPixelCentres) {
  AntialiasSettings settings;
  settings.depth = 2;
  const std::vector<Vec2> positions = supersample_positions(3, 5, settings);
  const std::vector<Vec2> expected = {{3.25, 5.25}, {3.75, 5.25}, {3.25, 5.75}, {3.75, 5.75}};
  EXPECT_EQ(positions, expected);
}

TEST(Antialias, JitterStaysInTheCellAndDependsOnlyOnSeedAndPixel) {
  AntialiasSettings settings;
  settings.depth = 3;
  settings.jitter = true;
  settings.seed = 7;
  const std::vector<Vec2> a = supersample_positions(10, 20, settings);
  EXPECT_EQ(a, supersample_positions(10, 20, settings));
  EXPECT_NE(a, supersample_positions(11, 20, settings));
  settings.seed = 8;
  EXPECT_NE(a, supersample_positions(10, 20, settings));
  for (size_t k = 0; k < a.size(); ++k) {
    const double cx = 10 + (double(k % 3) + 0.5) / 3.0, cy = 20 + (double(k / 3) + 0.5) / 3.0;
    EXPECT_LE(std::abs(a[k].x - cx), 0.5 / 3.0);
    EXPECT_LE(std::abs(a[k].y - cy), 0.5 / 3.0);
  }
}

}  // namespace
}  // namespace convray::render
