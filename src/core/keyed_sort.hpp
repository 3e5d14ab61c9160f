#pragma once
// Sorts (key, index) pairs, the start-up's big sorts (a mesh's triangles in Morton order,
// repeated triangles by hash): all pairs distinct, so the result is the one order that
// std::sort gives. A least-significant-digit radix sort: six passes of 11 bits over the key
// (a pass is skipped where every key has the same digit), the indices riding along; stable,
// so equal keys stay in index order as they came. In place of tbb::parallel_sort, the
// dragon's start-up (200,000 triangles, both sorts) took 0.89 of the CPU time and 0.93 of the
// wall time (docs/benchmarks.md, eighteenth step).
#include <cstdint>
#include <utility>
#include <vector>

namespace convray {

// `items` must hold each (key, index) pair once and come in ascending index order (as built
// by a loop over the indices): then ties in key stay in index order, which is what the pair
// order asks.
void sort_keyed(std::vector<std::pair<uint64_t, uint32_t>>& items);

}  // namespace convray
