#pragma once
// The lanes of the SIMD loops (the field's triangle batch, the exact spans' batch, the
// window march's down-bend sums): doubles in an AVX2 register. Each loop runs over whole
// widths, its last lanes padded and masked out: GCC ends a vectorized loop with a scalar
// remainder, which on the few lanes those loops usually have cost about as much as the rest.
#include <cstddef>

namespace convray {

inline constexpr size_t kSimdWidth = 4;

// n rounded up to whole SIMD widths.
constexpr size_t whole_simd_widths(size_t n) {
  return (n + kSimdWidth - 1) / kSimdWidth * kSimdWidth;
}

}  // namespace convray
