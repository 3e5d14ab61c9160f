// A ray's supports sorted by entry (implicit/entry_order.hpp) against std::stable_sort of the
// same intervals: the same entries in the same order, and the same set of intervals (each
// primitive once, with its own exit). Inputs of every shape the bucket sort treats apart:
// few, spread, bunched around one place with an outlier, ties, negative and infinite entries.
#include "implicit/entry_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace convray::implicit {
namespace {

using accel::SupportInterval;

std::vector<SupportInterval> intervals_from(const std::vector<double>& entries) {
  std::vector<SupportInterval> out;
  for (size_t i = 0; i < entries.size(); ++i) {
    out.push_back({uint32_t(i), entries[i], entries[i] + 1.0 + double(i)});
  }
  return out;
}

void expect_sorted_like_stable_sort(const std::vector<double>& entries) {
  std::vector<SupportInterval> ours = intervals_from(entries), reference = ours;
  sort_by_entry(ours);
  std::stable_sort(reference.begin(), reference.end(),
                   [](const auto& a, const auto& b) { return a.enter < b.enter; });
  ASSERT_EQ(ours.size(), reference.size());
  std::vector<bool> seen(entries.size(), false);
  for (size_t k = 0; k < ours.size(); ++k) {
    // Equal entries may come in either order; their values may not.
    EXPECT_EQ(ours[k].enter, reference[k].enter) << "position " << k << " of " << ours.size();
    ASSERT_LT(ours[k].primitive, entries.size());
    EXPECT_FALSE(seen[ours[k].primitive]) << "primitive " << ours[k].primitive << " twice";
    seen[ours[k].primitive] = true;
    EXPECT_EQ(ours[k].exit, entries[ours[k].primitive] + 1.0 + double(ours[k].primitive));
  }
}

TEST(EntryOrder, EmptyAndSingle) {
  expect_sorted_like_stable_sort({});
  expect_sorted_like_stable_sort({3.0});
}

TEST(EntryOrder, RandomSpreadEntriesOfEveryCount) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> along(-50.0, 400.0);
  for (size_t n = 2; n <= 300; n += (n < 40 ? 1 : 17)) {
    std::vector<double> entries(n);
    for (double& e : entries) e = along(rng);
    expect_sorted_like_stable_sort(entries);
  }
}

TEST(EntryOrder, NearlySortedAsEmbreeHandsThemOver) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> jitter(0.0, 3.0);
  std::vector<double> entries(200);
  for (size_t i = 0; i < entries.size(); ++i) entries[i] = double(i) + jitter(rng);
  expect_sorted_like_stable_sort(entries);
}

TEST(EntryOrder, BunchedEntriesWithAnOutlierAndTies) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> tiny(0.0, 1e-9);
  std::vector<double> entries;
  for (int i = 0; i < 500; ++i) entries.push_back(1.0 + tiny(rng));  // one bucket
  entries.push_back(1e6);                                           // far away
  for (int i = 0; i < 40; ++i) entries.push_back(2.5);              // equal entries
  std::shuffle(entries.begin(), entries.end(), rng);
  expect_sorted_like_stable_sort(entries);
}

TEST(EntryOrder, AllEqualNegativeAndInfiniteEntries) {
  expect_sorted_like_stable_sort(std::vector<double>(50, -2.0));
  std::vector<double> entries;
  for (int i = 0; i < 30; ++i) entries.push_back(-double(i) * 0.37);
  entries.push_back(-INFINITY);
  entries.push_back(INFINITY);
  expect_sorted_like_stable_sort(entries);
  expect_sorted_like_stable_sort({1e308, -1e308, 0.0, 5.0, -0.0, 1e-300, 3.0, 2.0, 1.0, 9.0,
                                  8.0, 7.0, 6.0, 4.0, 11.0, 10.0, 12.0, 13.0, 14.0, 15.0});
}

}  // namespace
}  // namespace convray::implicit
