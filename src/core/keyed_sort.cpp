#include "core/keyed_sort.hpp"

#include <algorithm>
#include <array>

namespace convray {
namespace {

constexpr int kDigitBits = 11;
constexpr size_t kBuckets = size_t(1) << kDigitBits;
constexpr int kPasses = (64 + kDigitBits - 1) / kDigitBits;
// Below this many, std::sort is as quick as the passes' histograms.
constexpr size_t kFew = 1024;

}  // namespace

void sort_keyed(std::vector<std::pair<uint64_t, uint32_t>>& items) {
  const size_t n = items.size();
  if (n < kFew) {
    std::sort(items.begin(), items.end());
    return;
  }
  // Every pass's histogram in one read of the keys.
  std::vector<std::array<uint32_t, kBuckets>> counts(kPasses);
  for (auto& c : counts) c.fill(0);
  for (const auto& item : items) {
    for (int pass = 0; pass < kPasses; ++pass) {
      ++counts[pass][(item.first >> (pass * kDigitBits)) & (kBuckets - 1)];
    }
  }
  std::vector<std::pair<uint64_t, uint32_t>> other(n);
  for (int pass = 0; pass < kPasses; ++pass) {
    auto& count = counts[pass];
    const int shift = pass * kDigitBits;
    // Every key has this digit: the pass would move nothing.
    if (count[(items[0].first >> shift) & (kBuckets - 1)] == n) continue;
    uint32_t start = 0;
    for (uint32_t& c : count) {
      const uint32_t here = c;
      c = start;
      start += here;
    }
    for (const auto& item : items) other[count[(item.first >> shift) & (kBuckets - 1)]++] = item;
    items.swap(other);
  }
}

}  // namespace convray
