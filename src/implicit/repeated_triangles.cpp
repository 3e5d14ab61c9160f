#include "implicit/repeated_triangles.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <utility>

#include "core/keyed_sort.hpp"

namespace convray::implicit {
namespace {

using Corners = std::array<double, 9>;

// The corners sorted lexicographically, so every order and orientation gives one key; + 0.0
// turns -0 into +0, which compare equal but differ in their bits (hashed below).
Corners canonical(const field::Triangle& t) {
  std::array<std::array<double, 3>, 3> v{{{t.a.x + 0.0, t.a.y + 0.0, t.a.z + 0.0},
                                          {t.b.x + 0.0, t.b.y + 0.0, t.b.z + 0.0},
                                          {t.c.x + 0.0, t.c.y + 0.0, t.c.z + 0.0}}};
  std::sort(v.begin(), v.end());
  Corners key;
  for (int i = 0; i < 3; ++i) std::copy(v[i].begin(), v[i].end(), key.begin() + 3 * i);
  return key;
}

uint64_t hash_of(const Corners& key) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the 64-bit patterns, then mixed
  for (double d : key) {
    uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
    h ^= h >> 29;
  }
  return h;
}

}  // namespace

std::optional<DistinctTriangles> merge_repeated(std::span<const field::Triangle> triangles) {
  const size_t n = triangles.size();
  // (hash, index): equal keys adjacent, the indices ascending within a run (all pairs are
  // distinct: one order). The hashes on every core: a big mesh's start-up waits for this.
  std::vector<std::pair<uint64_t, uint32_t>> order(n);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    order[i] = {hash_of(canonical(triangles[i])), uint32_t(i)};
  });
  sort_keyed(order);
  bool repeats = false;
  // Each triangle's first occurrence: within a run of equal hashes, the earliest equal key.
  std::vector<uint32_t> first(n);
  for (size_t begin = 0; begin < n;) {
    size_t end = begin + 1;
    while (end < n && order[end].first == order[begin].first) ++end;
    for (size_t k = begin; k < end; ++k) {  // runs are short: hash collisions are rare
      const uint32_t i = order[k].second;
      first[i] = i;
      for (size_t j = begin; j < k; ++j) {
        const uint32_t earlier = order[j].second;  // the indices ascend within a run
        if (canonical(triangles[earlier]) == canonical(triangles[i])) {
          first[i] = first[earlier];
          repeats = true;
          break;
        }
      }
    }
    begin = end;
  }
  if (!repeats) return std::nullopt;
  DistinctTriangles out;
  out.first.reserve(n);
  out.multiplicity.reserve(n);
  std::vector<uint32_t> slot(n, UINT32_MAX);
  for (size_t i = 0; i < n; ++i) {
    if (first[i] == i) {
      slot[i] = uint32_t(out.first.size());
      out.first.push_back(uint32_t(i));
      out.multiplicity.push_back(1);
    } else {
      ++out.multiplicity[slot[first[i]]];
    }
  }
  return out;
}

size_t repeated_triangle_count(std::span<const field::Triangle> triangles) {
  const std::optional<DistinctTriangles> merged = merge_repeated(triangles);
  return merged ? triangles.size() - merged->size() : 0;
}

}  // namespace convray::implicit
