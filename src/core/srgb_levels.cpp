#include "core/srgb_levels.hpp"

#include <bit>
#include <limits>
#include <vector>

#include "core/image_file.hpp"
#include "core/png_writer.hpp"

namespace convray {
namespace {

constexpr int kBucketShift = 17;
constexpr uint32_t kOneBits = 0x3F800000u;  // 1.0f
constexpr uint32_t kBuckets = kOneBits >> kBucketShift;

struct Bucket {
  float step;         // the first float of the bucket at level + 1 (+inf: none)
  uint8_t level;      // the level of the bucket's first float
  bool direct;        // the level rises by more than one within the bucket (or falls)
};

float float_of(uint32_t bits) { return std::bit_cast<float>(bits); }

std::vector<Bucket> make_table() {
  std::vector<Bucket> table(kBuckets);
  for (uint32_t b = 0; b < kBuckets; ++b) {
    const uint32_t first = b << kBucketShift, last = first + (1u << kBucketShift) - 1;
    const uint8_t low = srgb_level_direct(float_of(first)), high = srgb_level_direct(float_of(last));
    Bucket& bucket = table[b];
    bucket = {std::numeric_limits<float>::infinity(), low, high != low && high != low + 1};
    if (high != low + 1) continue;
    // The first float at level + 1: bisection over the bucket's floats (ordered as integers).
    uint32_t below = first, above = last;
    while (above - below > 1) {
      const uint32_t middle = below + (above - below) / 2;
      (srgb_level_direct(float_of(middle)) > low ? above : below) = middle;
    }
    bucket.step = float_of(above);
  }
  return table;
}

}  // namespace

uint8_t srgb_level_direct(float linear) { return quantize_8bit(encode_srgb(linear)); }

uint8_t srgb_level(float linear) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  static const std::vector<Bucket> table = make_table();
  const Bucket& bucket = table[std::bit_cast<uint32_t>(linear) >> kBucketShift];
  if (bucket.direct) return srgb_level_direct(linear);
  return uint8_t(bucket.level + (linear >= bucket.step ? 1 : 0));
}

}  // namespace convray
