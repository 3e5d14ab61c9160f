#pragma once
// Exactly repeated triangles of one mesh: the same three corners, in any order and
// orientation. Their fields are equal, so a mesh's sum needs each distinct triangle once,
// with its multiplicity as a factor (issue 17: scans and exported soups carry repeated faces,
// and a soup of one triangle copied 10^5 times crossed 7,015 supports per ray).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "field/triangle.hpp"

namespace convray::implicit {

// Indices rather than copies: the caller's triangles stay where they are (a copy of the
// dragon's 200,000 cost 14.6 MB of fresh pages at start-up).
struct DistinctTriangles {
  std::vector<uint32_t> first;         // each one's first occurrence in the input, ascending
  std::vector<uint32_t> multiplicity;  // how often each occurs (>= 1)
  size_t size() const { return first.size(); }
};

// The distinct triangles and their multiplicities, or nothing when no triangle repeats (the
// usual case, which costs a hash and a sort). Corners compare by exact value (-0 = +0).
std::optional<DistinctTriangles> merge_repeated(std::span<const field::Triangle> triangles);

// How many triangles are copies of an earlier one (0 for a mesh without repeats).
size_t repeated_triangle_count(std::span<const field::Triangle> triangles);

}  // namespace convray::implicit
