#pragma once
// Insertion sort, for the short and nearly sorted lists of a ray (Embree visits supports
// roughly front to back), and within bucket_sort's buckets: O(n + inversions), less than
// std::sort on the few dozen supports of a typical ray.
#include <span>
#include <utility>

namespace convray {

template <typename T, typename Less>
void insertion_sort(std::span<T> items, Less less) {
  for (size_t i = 1; i < items.size(); ++i) {
    if (!less(items[i], items[i - 1])) continue;
    T item = std::move(items[i]);
    size_t j = i;
    do {
      items[j] = std::move(items[j - 1]);
      --j;
    } while (j > 0 && less(item, items[j - 1]));
    items[j] = std::move(item);
  }
}

}  // namespace convray
