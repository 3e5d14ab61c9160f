#pragma once
// The lanes of the SIMD loops (the field's triangle batch, the exact spans' batch, the
// window march's down-bend sums): four doubles, a 256-bit register's worth. Each loop runs over
// whole widths, its last lanes padded and masked out: GCC ends a vectorized loop with a scalar
// remainder, which on the few lanes those loops usually have cost about as much as the rest.
// GCC 12's -march=native prefers 256-bit vectors on our AVX-512 host (Rocket Lake, as GCC
// tunes for Intel's AVX-512 cores): the loops run four lanes wide there as well, and whole
// widths of eight only padded each call with up to four lanes computed for nothing. Pairs
// against widths of eight on that host (docs/benchmarks.md, twenty-sixth step): the soup 0.95,
// R = 1 0.97, R = 5 0.96; the SIMD files built for 512-bit vectors with widths of eight
// instead: 1.03, 1.06, 1.01 against four. (An earlier step found eights better where GCC ran
// these loops eight wide.)
#include <cstddef>

namespace convray {

inline constexpr size_t kSimdWidth = 4;

// n rounded up to whole SIMD widths.
constexpr size_t whole_simd_widths(size_t n) {
  return (n + kSimdWidth - 1) / kSimdWidth * kSimdWidth;
}

}  // namespace convray
