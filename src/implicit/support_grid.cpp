#include "implicit/support_grid.hpp"

#include <algorithm>
#include <cmath>

namespace convray::implicit {

namespace {
// Enough cells that a cell holds a handful of primitives, few enough to stay small in memory.
constexpr double kCellsPerPrimitive = 2.0;
constexpr double kMaxCells = double(1 << 22);
}  // namespace

SupportGrid::SupportGrid(std::span<const Box3> boxes, double min_cell) {
  for (const Box3& b : boxes) {
    bounds_.extend(b.lo);
    bounds_.extend(b.hi);
  }
  if (boxes.empty() || bounds_.empty()) return;
  const Vec3 extent = glm::max(bounds_.extent(), Vec3(1e-300));
  const double volume = extent.x * extent.y * extent.z;
  const double target = std::clamp(kCellsPerPrimitive * double(boxes.size()), 1.0, kMaxCells);
  cell_size_ = std::max(min_cell, std::cbrt(volume / target));
  // Thin or flat sets: never more than kMaxCells in all, whatever the aspect ratio.
  for (;;) {
    dims_ = glm::max(glm::ivec3(glm::ceil(extent / cell_size_)), glm::ivec3(1));
    if (double(dims_.x) * dims_.y * dims_.z <= kMaxCells) break;
    cell_size_ *= 1.25;
  }

  const auto for_each_cell = [&](const Box3& b, auto&& visit) {
    const glm::ivec3 lo = cell_of(b.lo), hi = cell_of(b.hi);
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) visit(linear({x, y, z}));
  };
  // Count, prefix-sum, fill: compressed rows without per-cell vectors.
  cell_start_.assign(size_t(dims_.x) * dims_.y * dims_.z + 1, 0);
  for (const Box3& b : boxes) for_each_cell(b, [&](size_t c) { ++cell_start_[c + 1]; });
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  entries_.resize(cell_start_.back());
  std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (uint32_t i = 0; i < boxes.size(); ++i) {
    for_each_cell(boxes[i], [&](size_t c) { entries_[fill[c]++] = i; });
  }
}

glm::ivec3 SupportGrid::cell_of(const Vec3& p) const {
  const Vec3 rel = (p - bounds_.lo) / cell_size_;
  return glm::clamp(glm::ivec3(glm::floor(rel)), glm::ivec3(0), dims_ - 1);
}

size_t SupportGrid::linear(const glm::ivec3& c) const {
  return (size_t(c.z) * dims_.y + c.y) * dims_.x + c.x;
}

std::span<const uint32_t> SupportGrid::candidates(const Vec3& p) const {
  if (cell_start_.empty()) return {};
  // Outside the union of the boxes nothing can be non-zero (and NaN fails every test).
  if (!(p.x >= bounds_.lo.x && p.y >= bounds_.lo.y && p.z >= bounds_.lo.z &&
        p.x <= bounds_.hi.x && p.y <= bounds_.hi.y && p.z <= bounds_.hi.z)) {
    return {};
  }
  const size_t c = linear(cell_of(p));
  return {entries_.data() + cell_start_[c], cell_start_[c + 1] - cell_start_[c]};
}

}  // namespace convray::implicit
