#pragma once
// A ray's supports in the order the march meets them: by entry. At R = 5 a ray of the dragon
// gathers about 75, in Embree's order, and std::sort moving 24-byte intervals took 11 % of the
// render; this sorts them in O(n) (docs/benchmarks.md, fourteenth step).
#include <span>

#include "accel/support_index.hpp"

namespace convray::implicit {

// Sorts by `enter`, ascending (equal entries in any order).
void sort_by_entry(std::span<accel::SupportInterval> supports);

}  // namespace convray::implicit
