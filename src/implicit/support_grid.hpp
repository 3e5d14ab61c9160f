#pragma once
// A uniform grid over a set of boxes (each primitive's support: its bounding box grown by R),
// answering "which primitives can be non-zero at point P" with one cell lookup; the cell lists
// are conservative. MeshField's point query, for the millions of points of `field`, `slice`
// and `polygonize` on a triangle file: one cell and its compressed row, where a hierarchy
// (core/bvh.hpp, or Embree in accel/) walks a path of nodes per point.
#include <cstdint>
#include <span>
#include <vector>

#include "util/math.hpp"

namespace convray::implicit {

class SupportGrid {
 public:
  SupportGrid() = default;
  // boxes[i] is the support box of primitive i; cell size at least min_cell.
  SupportGrid(std::span<const Box3> boxes, double min_cell);

  // Indices of every primitive whose support box contains p (and possibly a few more).
  std::span<const uint32_t> candidates(const Vec3& p) const;

  size_t cell_count() const { return cell_start_.empty() ? 0 : cell_start_.size() - 1; }
  size_t entry_count() const { return entries_.size(); }

 private:
  glm::ivec3 cell_of(const Vec3& p) const;
  size_t linear(const glm::ivec3& c) const;

  Box3 bounds_;
  double cell_size_ = 1.0;
  glm::ivec3 dims_{0};
  std::vector<uint32_t> cell_start_;  // CSR: cell c holds entries_[cell_start_[c] .. [c+1])
  std::vector<uint32_t> entries_;
};

}  // namespace convray::implicit
