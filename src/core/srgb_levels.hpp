#pragma once
// The 8-bit level a PNG stores for a linear value: quantize_8bit(encode_srgb(v)), read from a
// table instead of a pow and a round per value (levels_of spent 9 of the soup's 17 ms of
// writing there, 800x600). Both steps only ever keep or raise the level as v grows (pow in
// float is monotone: glibc computes it in double, far finer than a float's spacing), so the
// level is a step function of v with 255 steps. The floats in [0, 1) are cut into buckets by
// their top bits (a bucket is 2^17 consecutive floats); each bucket holds its first float's
// level and the first float of the bucket, if any, where the level goes up by one. A bucket
// where it goes up by more (none: a bucket spans at most 0.9 of a level) or down is computed
// directly. tests/core/srgb_levels_test.cpp compares every float around every
// step, and a stride through all the others, with the direct computation.
#include <cstdint>

namespace convray {

// quantize_8bit(encode_srgb(linear)), the same for every float (NaN and below 0 give 0,
// from 1 up 255).
uint8_t srgb_level(float linear);

// The same, computed directly (the table's reference).
uint8_t srgb_level_direct(float linear);

}  // namespace convray
