// The short sorts of a ray's lists (util/insertion_sort.hpp, util/bucket_sort.hpp) against
// std::sort: random lists of every length, keys bunched, all equal, and unbounded, with a
// comparison that breaks ties (the one order std::sort gives).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "util/bucket_sort.hpp"
#include "util/insertion_sort.hpp"

namespace convray {
namespace {

TEST(InsertionSort, SortsLikeStdSort) {
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> u(0, 50);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<int> items(size_t(u(rng)));
    for (int& x : items) x = u(rng);
    std::vector<int> expected = items;
    std::sort(expected.begin(), expected.end());
    insertion_sort(std::span(items), std::less<int>());
    EXPECT_EQ(items, expected);
  }
}

using Item = std::pair<double, uint32_t>;

// `count` items keyed by `key(k)`, indexed in order.
template <class Key>
std::vector<Item> items_of(size_t count, Key key) {
  std::vector<Item> items;
  for (uint32_t k = 0; k < count; ++k) items.push_back({key(k), k});
  return items;
}

void expect_sorted_like_std(std::vector<Item> items, const char* what) {
  std::vector<Item> expected = items;
  std::sort(expected.begin(), expected.end());
  bucket_sort(
      std::span(items), [](const Item& i) { return i.first; }, std::less<Item>());
  EXPECT_EQ(items, expected) << what << ", " << items.size() << " items";
}

TEST(BucketSort, SortsLikeStdSort) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> spread(-100.0, 100.0);
  std::normal_distribution<double> bunched(3.0, 1e-6);
  std::uniform_int_distribution<int> few(0, 5);
  for (size_t count : {0, 1, 2, 15, 16, 17, 40, 333, 5000}) {
    expect_sorted_like_std(items_of(count, [&](uint32_t) { return spread(rng); }), "spread");
    // Most keys in one bucket (sorted on its own), a few far away.
    expect_sorted_like_std(
        items_of(count, [&](uint32_t k) { return k % 50 ? bunched(rng) : spread(rng); }),
        "bunched");
    // Ties: equal keys sort by index.
    expect_sorted_like_std(items_of(count, [&](uint32_t) { return double(few(rng)); }), "ties");
    expect_sorted_like_std(items_of(count, [](uint32_t) { return 7.0; }), "all equal");
    expect_sorted_like_std(
        items_of(count,
                 [&](uint32_t k) {
                   return k % 9 == 0 ? -INFINITY : k % 7 ? spread(rng) : INFINITY;
                 }),
        "unbounded");
  }
}

}  // namespace
}  // namespace convray
