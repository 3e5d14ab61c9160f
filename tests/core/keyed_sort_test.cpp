// The radix sort of (key, index) pairs against std::sort of the same pairs: the same order,
// for counts below and above the radix threshold, keys spread over all 64 bits, keys that
// differ in one digit only (passes skipped), many equal keys (ties in index order), and the
// largest key (spatial_order's non-finite points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "core/keyed_sort.hpp"

namespace convray {
namespace {

using Keyed = std::vector<std::pair<uint64_t, uint32_t>>;

template <class KeyOf>
Keyed keyed_by(size_t n, KeyOf key_of) {
  Keyed items(n);
  for (size_t i = 0; i < n; ++i) items[i] = {key_of(i), uint32_t(i)};
  return items;
}

void expect_as_std_sort(Keyed items) {
  Keyed expected = items;
  std::sort(expected.begin(), expected.end());
  sort_keyed(items);
  ASSERT_EQ(items.size(), expected.size());
  for (size_t k = 0; k < items.size(); ++k) {
    ASSERT_EQ(items[k], expected[k]) << "position " << k << " of " << items.size();
  }
}

TEST(KeyedSort, RandomKeysOfEveryWidthAndCount) {
  std::mt19937_64 rng(5);
  for (const size_t n : {0u, 1u, 2u, 100u, 1023u, 1024u, 5000u, 70000u}) {
    for (const int bits : {3, 11, 12, 40, 63, 64}) {
      const uint64_t mask = bits == 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
      expect_as_std_sort(keyed_by(n, [&](size_t) { return rng() & mask; }));
    }
  }
}

TEST(KeyedSort, KeysDifferingInOneDigitOnly) {
  std::mt19937_64 rng(6);
  const uint64_t high = 0xabcdef0123456789ull & ~(uint64_t(0x7ff) << 22);
  expect_as_std_sort(keyed_by(20000, [&](size_t) { return high | (rng() & 0x7ff) << 22; }));
}

TEST(KeyedSort, EqualKeysStayInIndexOrder) {
  std::mt19937_64 rng(7);
  expect_as_std_sort(keyed_by(30000, [&](size_t) { return rng() % 5; }));
  expect_as_std_sort(keyed_by(30000, [](size_t) { return uint64_t(42); }));
  expect_as_std_sort(keyed_by(30000, [](size_t i) { return i % 3 ? UINT64_MAX : uint64_t(i); }));
}

TEST(KeyedSort, DescendingKeys) {
  expect_as_std_sort(keyed_by(50000, [](size_t i) { return uint64_t(1e12) - uint64_t(i) * 977; }));
}

}  // namespace
}  // namespace convray
