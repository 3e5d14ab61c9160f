#pragma once
// Sorts a short list by a key of type double in O(n) where the keys spread along their range
// (a ray's supports by entry, a cone's balls by distance from its apex): a counting sort into
// as many buckets as items, by where each key falls between the least and the greatest, then
// insertion sort within the buckets, which hold one or two each. No mispredicted branches of
// a comparison sort (std::sort on a ray's supports: 11 % of the render at R = 5, fourteenth
// step of docs/benchmarks.md). A crowded bucket (keys bunched around one value) is sorted on
// its own with std::sort, so the whole stays O(n log n) at worst. The result is the order
// `less` gives (which must agree with the keys: a key below another's sorts first), so a
// `less` that breaks ties makes it the one order std::sort would give.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "util/insertion_sort.hpp"

namespace convray {

// Below this many, insertion sort on the items themselves is as quick.
inline constexpr size_t kBucketSortFew = 16;

template <class T, class Key, class Less>
void bucket_sort(std::span<T> items, Key key, Less less) {
  const size_t n = items.size();
  if (n <= kBucketSortFew) {
    insertion_sort(items, less);
    return;
  }
  double lo = key(items[0]), hi = lo;
  for (const T& item : items) {
    lo = std::min(lo, key(item));
    hi = std::max(hi, key(item));
  }
  const double scale = double(n) / (hi - lo);
  if (!(hi > lo) || !std::isfinite(scale) || !std::isfinite(lo) || !std::isfinite(hi)) {
    std::sort(items.begin(), items.end(), less);  // all equal, or unbounded
    return;
  }
  thread_local std::vector<uint32_t> bucket, start;
  thread_local std::vector<T> sorted;
  bucket.resize(n);
  start.assign(n + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    bucket[i] = uint32_t(std::min(double(n - 1), (key(items[i]) - lo) * scale));
    ++start[bucket[i] + 1];
  }
  for (size_t b = 0; b < n; ++b) start[b + 1] += start[b];
  sorted.resize(n);
  for (size_t i = 0; i < n; ++i) sorted[start[bucket[i]]++] = items[i];
  std::copy(sorted.begin(), sorted.end(), items.begin());
  // start[b] is now where bucket b ends.
  for (size_t b = 0, begin = 0; b < n; begin = start[b++]) {
    if (start[b] - begin > kBucketSortFew) {
      std::sort(items.begin() + begin, items.begin() + start[b], less);
    }
  }
  insertion_sort(items, less);  // within the other buckets
}

}  // namespace convray
