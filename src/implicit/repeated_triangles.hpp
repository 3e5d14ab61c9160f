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

struct DistinctTriangles {
  std::vector<field::Triangle> triangles;  // each first occurrence, in the order of the input
  std::vector<uint32_t> multiplicity;      // how often each occurs (>= 1)
};

// The distinct triangles and their multiplicities, or nothing when no triangle repeats (the
// usual case, which costs a hash and a sort). Corners compare by exact value (-0 = +0).
std::optional<DistinctTriangles> merge_repeated(std::span<const field::Triangle> triangles);

// How many triangles are copies of an earlier one (0 for a mesh without repeats).
size_t repeated_triangle_count(std::span<const field::Triangle> triangles);

}  // namespace convray::implicit
