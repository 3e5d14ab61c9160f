// The table of 8-bit sRGB levels (core/srgb_levels.hpp) against the direct computation,
// quantize_8bit(encode_srgb(v)): every float within 4,096 of each step between two levels (where
// a wrong table would show first), a stride through all the floats in [0, 1] (every 61st),
// and the values outside [0, 1].
#include "core/srgb_levels.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace convray {
namespace {

float float_of(uint32_t bits) { return std::bit_cast<float>(bits); }
uint32_t bits_of(float v) { return std::bit_cast<uint32_t>(v); }

TEST(SrgbLevels, EveryFloatAroundEveryStepAsComputedDirectly) {
  int steps = 0;
  for (int level = 1; level <= 255; ++level) {
    // The step's float, by bisection on the direct computation (its own reference).
    uint32_t below = 0, above = bits_of(1.0f);
    while (above - below > 1) {
      const uint32_t middle = below + (above - below) / 2;
      (srgb_level_direct(float_of(middle)) >= level ? above : below) = middle;
    }
    ++steps;
    for (uint32_t bits = above - 4096; bits <= above + 4096; ++bits) {
      const float v = float_of(bits);
      ASSERT_EQ(srgb_level(v), srgb_level_direct(v)) << "level " << level << " v " << v;
    }
  }
  EXPECT_EQ(steps, 255);
}

TEST(SrgbLevels, AStrideThroughEveryFloatInTheUnitInterval) {
  uint64_t checked = 0;
  for (uint32_t bits = 0; bits <= bits_of(1.0f); bits += 61) {
    const float v = float_of(bits);
    ASSERT_EQ(srgb_level(v), srgb_level_direct(v)) << v;
    ++checked;
  }
  EXPECT_GT(checked, 17000000u);
}

TEST(SrgbLevels, OutsideTheUnitInterval) {
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {-inf, -1.0f, -0.0f, 0.0f, std::numeric_limits<float>::denorm_min(), 1.0f,
                  1.5f, 1e30f, inf, std::numeric_limits<float>::quiet_NaN()}) {
    EXPECT_EQ(srgb_level(v), srgb_level_direct(v)) << v;
  }
  EXPECT_EQ(srgb_level(0.5f), 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354, times 255
}

}  // namespace
}  // namespace convray
