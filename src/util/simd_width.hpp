#pragma once
// The lanes of the SIMD loops (the field's triangle batch, the exact spans' batch, the
// window march's down-bend sums): doubles in an AVX-512 register where the build has it, else
// in an AVX2 one. Each loop runs over whole widths, its last lanes padded and masked out: GCC
// ends a vectorized loop with a scalar remainder, which on the few lanes those loops usually
// have cost about as much as the rest. With AVX-512, GCC runs these loops 8 lanes wide and
// ended widths of 4 with a 4-lane pass (libmvec's AVX2 atan2 beside its AVX-512 one): whole
// widths of 8 were 0.97 (R = 1) and 0.99 (R = 5) of the time (docs/benchmarks.md, fourteenth
// step); 256-bit vectors throughout (-mprefer-vector-width=256) were 1.10 at R = 5.
#include <cstddef>

namespace convray {

#ifdef __AVX512F__
inline constexpr size_t kSimdWidth = 8;
#else
inline constexpr size_t kSimdWidth = 4;
#endif

// n rounded up to whole SIMD widths.
constexpr size_t whole_simd_widths(size_t n) {
  return (n + kSimdWidth - 1) / kSimdWidth * kSimdWidth;
}

}  // namespace convray
