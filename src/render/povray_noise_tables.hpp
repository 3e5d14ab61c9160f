#pragma once
// POV-Ray 3.7's noise tables, measured from the povray binary's behaviour by
// scripts/derive-povray-noise.py (docs/noise.md tells how): the data lives in
// povray_noise_tables.cpp, which that script writes.
#include <array>
#include <cstdint>

namespace convray::render::povray_noise {

// The lattice hash repeats every kHashSize cells along each axis.
constexpr int kHashSize = 4096;
// Entries -1..265 of the corner table: a corner with hash h (0..255) reads its value from
// entry h - 1 (halved) and its gradient from entries h..h+2; the vector noise's y and z
// components read the windows 4 and 8 entries further on.
constexpr int kCornerTableSize = 267;

// The integer added to each lattice coordinate before the hash (modulo kHashSize).
extern const int kLatticeOffset;
// The default generator's range correction: value = (raw + kRangeBias) * kRangeScale.
extern const double kRangeScale;
extern const double kRangeBias;
// A permutation of 0..kHashSize-1, applied once per axis.
extern const std::array<uint16_t, kHashSize> kPermutation;
extern const std::array<double, kCornerTableSize> kCornerTable;

}  // namespace convray::render::povray_noise
