// POV-Ray's adaptive averaging of an area light's shadow rays, on made-up visibilities.
#include "render/area_light.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <utility>

namespace convray::render {
namespace {

// Counts the shadow rays asked for, and answers from `lit(i, j)`.
struct Probe {
  explicit Probe(std::function<bool(int, int)> lit_lights) : lit(std::move(lit_lights)) {}

  std::function<bool(int, int)> lit;
  int calls = 0;

  std::function<Vec3(int, int)> visibility() {
    return [this](int i, int j) {
      ++calls;
      return Vec3(lit(i, j) ? 1.0 : 0.0);
    };
  }
};

TEST(AreaLight, FullySubdividedItIsTheTrapezoidRule) {
  // 3 x 3 grid subdivided to the end (adaptive 5), only the centre light visible: its
  // trapezoid weight is 4 of 16.
  Probe probe([](int i, int j) { return i == 1 && j == 1; });
  EXPECT_NEAR(area_light_visibility(3, 3, 5, probe.visibility()).r, 0.25, 1e-15);
  EXPECT_EQ(probe.calls, 9);  // every light once, shared corners included
  // Only a corner visible: weight 1 of 16.
  Probe corner([](int i, int j) { return i == 0 && j == 0; });
  EXPECT_NEAR(area_light_visibility(3, 3, 5, corner.visibility()).r, 1.0 / 16.0, 1e-15);
}

TEST(AreaLight, AgreeingCornersEndTheSearchOnceDeepEnough) {
  // Corners all lit, a hidden light inside: adaptive 0 trusts the corners.
  Probe shallow([](int i, int j) { return !(i == 2 && j == 2); });
  EXPECT_EQ(area_light_visibility(5, 5, 0, shallow.visibility()).r, 1.0);
  EXPECT_EQ(shallow.calls, 4);
  // adaptive 1 looks one level down (the middle light is a corner there).
  Probe deeper([](int i, int j) { return !(i == 2 && j == 2); });
  EXPECT_LT(area_light_visibility(5, 5, 1, deeper.visibility()).r, 1.0);
}

TEST(AreaLight, LinearAndSingleLights) {
  Probe line([](int i, int) { return i < 2; });  // 4 x 1: lights 0, 1 lit, 2, 3 hidden
  // Split at light 1: [0, 1] averages 1, [1, 3] splits into [1, 2] (1/2) and [2, 3] (0).
  EXPECT_NEAR(area_light_visibility(4, 1, 0, line.visibility()).r, 0.5 * (1.0 + 0.25), 1e-15);
  Probe single([](int, int) { return true; });
  EXPECT_EQ(area_light_visibility(1, 1, 0, single.visibility()).r, 1.0);
  EXPECT_EQ(single.calls, 1);
}

}  // namespace
}  // namespace convray::render
