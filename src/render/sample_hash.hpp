#pragma once
// Reproducible pseudo-random numbers without any generator state: each number is a hash of
// what identifies the sample (the seed, a pixel, a sample index, ...). So a jittered sample
// is the same whichever thread draws it and in whatever order: renders stay byte-identical
// for any thread count.
#include <cstdint>

namespace convray::render {

// SplitMix64's finaliser: a bijective mix where every input bit affects every output bit.
constexpr uint64_t mix_bits(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

// A hash of several integers, order-sensitive.
constexpr uint64_t hash_values(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  uint64_t h = mix_bits(a + 0x9e3779b97f4a7c15ull);
  h = mix_bits(h ^ (b + 0x9e3779b97f4a7c15ull));
  h = mix_bits(h ^ (c + 0x632be59bd9b4e019ull));
  return mix_bits(h ^ (d + 0x85157af5ull));
}

// A number in [0, 1) from a hash: its top 53 bits.
constexpr double unit_from_hash(uint64_t h) { return double(h >> 11) * 0x1.0p-53; }

}  // namespace convray::render
